#include "comparison/replay/seed_scatter.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "common/errors.hpp"
#include "comparison/replay/quantities.hpp"

namespace iwb::comparison {

namespace {

// Equal on every key both record. A key one side lacks was added to the scene schema after that
// run was made (the resolved scene records every key with its value, defaults included), so the
// older run had it at its default: runs of one scene made before and after such an addition are
// seeds of each other (issue 36: seeds 4 and 5 of the truth cells were made after the schema
// gained particles.suction_kPa, surface_tension_N_m and shear.post_cyclic_mm).
bool equal_where_both_record(const nlohmann::json& a, const nlohmann::json& b) {
  if (!a.is_object() || !b.is_object()) return a == b;
  for (const auto& [key, value] : a.items())
    if (b.contains(key) && !equal_where_both_record(value, b.at(key))) return false;
  return true;
}

void check_same_scene(const DemRun& run, const DemRun& seed) {
  if (!same_scene_but_seed(run, seed))
    throw InputError(
        fmt::format("{}: not a seed of {}: its scene differs in more than the seed "
                    "(manifest.json /scene/resolved)",
                    seed.dir.string(), run.dir.string()));
}

// The displacement travelled since the start of shear (u_x = 0) at each row: cyclic paths
// return through the same u_x, the travel keeps increasing. A cyclic run's wall moves at v, and
// its travel is v t: summing |du_x| over rows would cut every reversal's corner (src/cycles/).
std::vector<double> travel(const DemRun& r) {
  if (cyclic_program(r)) return cyclic_travel(r);
  const auto& u_x = r.u_x_mm;
  std::vector<double> s(u_x.size(), std::abs(u_x.front()));
  for (std::size_t i = 1; i < u_x.size(); ++i) s[i] = s[i - 1] + std::abs(u_x[i] - u_x[i - 1]);
  return s;
}

// y at travel x by linear interpolation in (xs, ys); held at the first value before it.
double at(const std::vector<double>& xs, const std::vector<double>& ys, double x) {
  const auto hi = std::upper_bound(xs.begin(), xs.end(), x);
  if (hi == xs.begin()) return ys.front();
  if (hi == xs.end()) return ys.back();
  const std::size_t j = std::size_t(hi - xs.begin());
  const double w = (x - xs[j - 1]) / (xs[j] - xs[j - 1]);
  return ys[j - 1] + w * (ys[j] - ys[j - 1]);
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

// Per row of the compared run (`where`, its travel), mean and SD over the seeds of one series.
SeriesScatter series_scatter(const std::vector<const DemRun*>& all,
                             const std::vector<double>& where, std::size_t rows,
                             std::vector<double> DemRun::*member) {
  SeriesScatter out;
  std::vector<std::vector<double>> travels;  // once per run, not per row
  for (const auto* r : all) travels.push_back(travel(*r));
  double sum = 0.0;
  for (std::size_t i = 0; i < rows; ++i) {
    std::vector<double> values;
    for (std::size_t k = 0; k < all.size(); ++k)
      values.push_back(at(travels[k], all[k]->*member, where[i]));
    const auto ms = mean_sd(values);
    out.mean.push_back(ms.mean), out.sd.push_back(ms.sd), sum += ms.sd * ms.sd;
  }
  out.rms_sd = rows > 0 ? std::sqrt(sum / double(rows)) : 0.0;
  return out;
}

void quantity_scatter(const std::vector<const DemRun*>& all, SeedScatter& out) {
  const auto keys = judged_quantities(all.front()->boundary, all.front()->cyclic());
  std::map<std::string, std::vector<double>> values;
  for (const auto* r : all)
    for (const auto& [k, v] : evaluate_quantities(
             {r->u_x_mm, r->tau_kPa, r->sigma_n_kPa, r->u_n_mm, &r->e_band, r->wall_zone_mm}, keys))
      if (v) values[k].push_back(*v);
  for (const auto& [k, v] : values) {
    const auto ms = mean_sd(v);
    out.quantity_mean[k] = ms.mean;
    out.quantity_sd[k] = ms.sd;
  }
  out.quantity_values = values;
}

std::string summary_text(const DemRun& r, const char* key) {
  const auto it = r.summary.find(key);
  return it != r.summary.end() && it->is_string() ? it->get<std::string>() : std::string();
}

// The runs a cell's statistics rest on: those that sheared at the wall under test, while any did
// (summary.json shear_mode); the others are recorded in out.left_out, the residuals that have not
// settled (friction_steady_state) in out.not_steady and the runs whose shear split between wall
// and plate in out.split.
std::vector<const DemRun*> admitted(const std::vector<const DemRun*>& all, SeedScatter& out) {
  constexpr const char* kAtThePlate = "localised at the plate";
  std::vector<const DemRun*> kept;
  for (const auto* r : all)
    if (summary_text(*r, "shear_mode") != kAtThePlate) kept.push_back(r);
  if (kept.empty()) kept = all, out.only_plate_runs = true;  // nothing else to rest on
  for (const auto* r : all)
    if (std::find(kept.begin(), kept.end(), r) == kept.end())
      out.left_out.emplace_back(r->dir.string(), kAtThePlate);
  for (const auto* r : kept) {
    const auto settled = friction_steady_state(
        {r->u_x_mm, r->tau_kPa, r->sigma_n_kPa, r->u_n_mm, &r->e_band, r->wall_zone_mm}, r->d50_mm);
    if (!settled || !settled->steady) out.not_steady.push_back(r->dir.string());
    if (summary_text(*r, "shear_mode") == "split between wall and plate")
      out.split.push_back(r->dir.string());
  }
  return kept;
}

}  // namespace

bool same_scene_but_seed(const DemRun& a, const DemRun& b) {
  return equal_where_both_record(a.scene_but_seed, b.scene_but_seed);
}

SeedScatter seed_scatter(const DemRun& run, const std::vector<DemRun>& other_seeds) {
  SeedScatter out;
  std::vector<const DemRun*> all = {&run};
  for (const auto& s : other_seeds) check_same_scene(run, s), all.push_back(&s);
  all = admitted(all, out);
  const auto where = travel(run);
  double covered = where.back();
  for (const auto* r : all)
    out.runs.push_back(r->dir.string()), covered = std::min(covered, travel(*r).back());
  // the run's rows up to the shortest seed's end (to half an output interval: the same end
  // displacement, written a fraction of an interval apart)
  const double half_row = 0.5 * where.back() / double(where.size());
  out.rows =
      std::size_t(std::upper_bound(where.begin(), where.end(), covered + half_row) - where.begin());
  out.tau = series_scatter(all, where, out.rows, &DemRun::tau_kPa);
  out.u_n = series_scatter(all, where, out.rows, &DemRun::u_n_mm);
  out.sigma_n = series_scatter(all, where, out.rows, &DemRun::sigma_n_kPa);
  quantity_scatter(all, out);
  return out;
}

std::vector<DemRun> seeds_of(const DemRun& run, const std::vector<DemRun>& candidates) {
  std::vector<DemRun> out;
  for (const auto& c : candidates)
    if (same_scene_but_seed(c, run) && !std::filesystem::equivalent(c.dir, run.dir))
      out.push_back(c);
  return out;
}

}  // namespace iwb::comparison
