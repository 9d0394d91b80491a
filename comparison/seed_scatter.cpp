#include "comparison/seed_scatter.hpp"

#include <fmt/core.h>

#include <cmath>
#include <filesystem>

#include "common/errors.hpp"
#include "comparison/quantities.hpp"

namespace iwb::comparison {

namespace {

// Rows of two seeds are the same instant of shear when their u_x agree to a fraction of the
// output spacing (the same scene writes at the same u_x; the engine's step quantises it).
constexpr double kRowMatchShare = 0.25;

void check_same_scene(const DemRun& run, const DemRun& seed) {
  if (seed.scene_but_seed != run.scene_but_seed)
    throw InputError(fmt::format("{}: not a seed of {}: its scene differs in more than the seed "
                                 "(manifest.json /scene/resolved)",
                                 seed.dir.string(), run.dir.string()));
}

void check_rows(const DemRun& run, const DemRun& seed, std::size_t rows) {
  const double spacing = (run.u_x_mm[rows - 1] - run.u_x_mm[0]) / double(rows - 1);
  for (std::size_t i = 0; i < rows; ++i)
    if (std::abs(seed.u_x_mm[i] - run.u_x_mm[i]) > kRowMatchShare * std::abs(spacing))
      throw InputError(fmt::format("{}/timeseries.csv:{}: u_x_mm = {:g} where {} has {:g}: seeds must "
                                   "write their rows at the same u_x",
                                   seed.dir.string(), i + 2, seed.u_x_mm[i], run.dir.string(), run.u_x_mm[i]));
}

struct MeanSd {
  double mean, sd;
};

MeanSd mean_sd(const std::vector<double>& x) {
  double m = 0.0, v = 0.0;
  for (double a : x) m += a;
  m /= double(x.size());
  for (double a : x) v += (a - m) * (a - m);
  return {m, x.size() > 1 ? std::sqrt(v / double(x.size() - 1)) : 0.0};
}

// RMS over rows of the standard deviation across seeds of one series.
double row_scatter(const std::vector<const std::vector<double>*>& series, std::size_t rows) {
  double sum = 0.0;
  for (std::size_t i = 0; i < rows; ++i) {
    std::vector<double> at;
    for (const auto* s : series) at.push_back((*s)[i]);
    sum += std::pow(mean_sd(at).sd, 2);
  }
  return std::sqrt(sum / double(rows));
}

void quantity_scatter(const std::vector<const DemRun*>& all, SeedScatter& out) {
  const auto keys = judged_quantities(all.front()->boundary);
  std::map<std::string, std::vector<double>> values;
  for (const auto* r : all)
    for (const auto& [k, v] : evaluate_quantities({r->u_x_mm, r->tau_kPa, r->sigma_n_kPa, r->u_n_mm}, keys))
      if (v) values[k].push_back(*v);
  for (const auto& [k, v] : values) {
    const auto ms = mean_sd(v);
    out.quantity_mean[k] = ms.mean;
    out.quantity_sd[k] = ms.sd;
  }
}

}  // namespace

SeedScatter seed_scatter(const DemRun& run, const std::vector<DemRun>& other_seeds) {
  SeedScatter out;
  std::vector<const DemRun*> all = {&run};
  out.rows = run.u_x_mm.size();
  for (const auto& s : other_seeds) {
    check_same_scene(run, s);
    all.push_back(&s);
    out.rows = std::min(out.rows, s.u_x_mm.size());
  }
  for (const auto* r : all) {
    out.runs.push_back(r->dir.string());
    check_rows(run, *r, out.rows);
  }
  auto series = [&](auto member) {
    std::vector<const std::vector<double>*> s;
    for (const auto* r : all) s.push_back(&(r->*member));
    return row_scatter(s, out.rows);
  };
  out.tau_kPa = series(&DemRun::tau_kPa);
  out.u_n_mm = series(&DemRun::u_n_mm);
  out.sigma_n_kPa = series(&DemRun::sigma_n_kPa);
  quantity_scatter(all, out);
  return out;
}

std::vector<DemRun> seeds_of(const DemRun& run, const std::vector<DemRun>& candidates) {
  std::vector<DemRun> out;
  for (const auto& c : candidates)
    if (c.scene_but_seed == run.scene_but_seed &&
        !std::filesystem::equivalent(c.dir, run.dir))
      out.push_back(c);
  return out;
}

}  // namespace iwb::comparison
