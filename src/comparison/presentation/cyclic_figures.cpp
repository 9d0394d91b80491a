#include "comparison/presentation/cyclic_figures.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "comparison/verdicts/cyclic_verdicts.hpp"

namespace iwb::comparison {

namespace {

// One series of compare.csv: the DEM's (variant 0's DEM columns) or a variant's model columns,
// row k being the DEM's row k (a replay that stopped has fewer rows).
struct Series {
  std::vector<double> u_x, tau, sigma_n;
};

struct Curves {
  Series dem;
  std::vector<Series> model;  // by variant index
};

Curves split(const io::CsvTable& curves, std::size_t variants) {
  Curves out;
  out.model.resize(variants);
  const int vc = curves.column("variant"), xc = curves.column("u_x_mm");
  const int td = curves.column("tau_dem_kPa"), tm = curves.column("tau_model_kPa");
  const int sd = curves.column("sigma_n_dem_kPa"), sm = curves.column("sigma_n_model_kPa");
  for (const auto& r : curves.rows) {
    const auto v = std::size_t(r[vc]);
    if (v == 0) {
      out.dem.u_x.push_back(r[xc]), out.dem.tau.push_back(r[td]);
      out.dem.sigma_n.push_back(r[sd]);
    }
    if (v < variants) {
      auto& m = out.model[v];
      m.u_x.push_back(r[xc]), m.tau.push_back(r[tm]), m.sigma_n.push_back(r[sm]);
    }
  }
  return out;
}

// Rows [first, last] from the last row at or before travel `from` to the first at or after `to`.
struct RowRange {
  std::size_t first = 0, last = 0;
};

RowRange rows_between(const std::vector<double>& travel, double from, double to) {
  RowRange r;
  const auto start = std::upper_bound(travel.begin(), travel.end(), from);
  r.first = start == travel.begin() ? 0 : std::size_t(start - travel.begin()) - 1;
  const auto end = std::lower_bound(travel.begin(), travel.end(), to);
  r.last = end == travel.end() ? travel.size() - 1 : std::size_t(end - travel.begin());
  return r;
}

std::vector<double> slice(const std::vector<double>& v, RowRange r) {
  if (r.first >= v.size()) return {};
  const std::size_t last = std::min(r.last, v.size() - 1);
  return {v.begin() + std::ptrdiff_t(r.first), v.begin() + std::ptrdiff_t(last) + 1};
}

std::string label(const nlohmann::json& variant) {
  return variant["label"].get<std::string>();
}

// A figure of y against x over `rows`, the variants shown first and the DEM last.
Figure over_rows(const std::string& name, const std::string& title, const std::string& xlabel,
                 const std::string& ylabel, const Curves& c, const nlohmann::json& variants,
                 const std::vector<std::size_t>& shown, RowRange rows,
                 std::vector<double> Series::*x, std::vector<double> Series::*y) {
  std::vector<PlotCurve> plotted;
  for (std::size_t v : shown)
    plotted.push_back({label(variants[v]), slice(c.model[v].*x, rows), slice(c.model[v].*y, rows)});
  plotted.push_back(
      {"DEM (this run)", slice(c.dem.*x, rows), slice(c.dem.*y, rows), kReferenceStyle});
  return curves_figure(name, title, xlabel, ylabel, plotted);
}

// A per-cycle quantity of cycle_quantities' JSON (a cycle's `key`) against N.
PlotCurve per_cycle(const std::string& title, const nlohmann::json& cycles, const char* key,
                    const std::string& style) {
  PlotCurve p{title, {}, {}, style};
  for (const auto& c : cycles)
    if (c[key].is_number())
      p.x.push_back(c["cycle"].get<double>()), p.y.push_back(c[key].get<double>());
  return p;
}

// The DEM's seed mean at the judged cycles with its 95 % t-interval (as the verdicts have them),
// where the comparison had seeds: the means as points, each interval as a vertical bar.
void seed_means(const nlohmann::json& cmp, const char* key, std::vector<PlotCurve>& plotted) {
  const auto& predicted = cmp["variants"][cmp["verdicts"]["predicted_variant"].get<std::size_t>()];
  if (!predicted.contains("cyclic")) return;
  PlotCurve means{"", {}, {}, "with points pt 6 ps 2 lw 2 lc rgb '#555555'"};
  std::vector<PlotCurve> bars;
  std::size_t seeds = 0;
  for (const auto& v : predicted["cyclic"]["verdicts"]) {
    if (v["quantity"] != key || !v["dem_t_interval_95"].is_number()) continue;
    const std::string where = v["where"];
    if (where.rfind("cycle ", 0) != 0) continue;
    const double n = std::stod(where.substr(6)), mean = v["dem"], ci = v["dem_t_interval_95"];
    means.x.push_back(n), means.y.push_back(mean);
    bars.push_back({"", {n, n}, {mean - ci, mean + ci}, "with lines lw 2 lc rgb '#555555'"});
    seeds = v["seeds"].get<std::size_t>();
  }
  if (means.x.empty()) return;
  means.title = fmt::format("DEM, mean of {} seeds +- 95 % t-interval", seeds);
  plotted.push_back(means);
  plotted.insert(plotted.end(), bars.begin(), bars.end());
}

Figure against_n(const std::string& name, const std::string& title, const std::string& ylabel,
                 const char* key, const nlohmann::json& cmp,
                 const std::vector<std::size_t>& shown) {
  std::vector<PlotCurve> plotted;
  for (std::size_t v : shown) {
    const auto& variant = cmp["variants"][v];
    if (variant.contains("cyclic"))
      plotted.push_back(per_cycle(label(variant), variant["cyclic"]["model"]["cycles"], key,
                                  "with linespoints lw 2 pt 7"));
  }
  seed_means(cmp, key, plotted);
  plotted.push_back(per_cycle("DEM (this run)", cmp["cyclic"]["cycles"], key,
                              "with linespoints lw 3 pt 7 ps 1.2 lc rgb '#000000'"));
  Figure f = curves_figure(name, title, "cycle N", ylabel, plotted);
  f.extra += "set xtics 1\n";
  return f;
}

}  // namespace

std::vector<Figure> cyclic_figures(const nlohmann::json& cmp, const io::CsvTable& curves,
                                   const std::vector<double>& travel_mm,
                                   const cycles::Program& program,
                                   const std::vector<std::size_t>& shown) {
  const auto& variants = cmp["variants"];
  const Curves c = split(curves, variants.size());
  const double cycle_travel = 4.0 * program.amplitude_mm;
  const int reached = int(cmp["cyclic"]["cycles"].size());
  std::vector<Figure> figs;
  for (int n : judged_cycles(reached))
    figs.push_back(over_rows(fmt::format("loop_{}", n), fmt::format("tau against u_x, cycle {}", n),
                             "u_x (mm)", "tau (kPa)", c, variants, shown,
                             rows_between(travel_mm, cycle_travel * (n - 1), cycle_travel * n),
                             &Series::u_x, &Series::tau));
  const std::string boundary = cmp["dem"]["boundary"].get<std::string>();
  if (boundary != "CNL")  // under CNL sigma_n is held
    figs.push_back(against_n("sigma_n_ratio_n",
                             "sigma_n at the end of each cycle over sigma_n0 (degradation)",
                             "sigma_n / sigma_n0", "sigma_n_ratio", cmp, shown));
  if (boundary != "CV")  // under CV u_n is held
    figs.push_back(against_n("u_n_n", "accumulated u_n at the end of each cycle (ratcheting)",
                             "u_n (mm), dilation positive", "u_n_end_mm", cmp, shown));
  if (boundary == "CV")
    figs.push_back(over_rows("stress_path", "Stress path over the cycles (CV)", "sigma_n (kPa)",
                             "tau (kPa)", c, variants, shown,
                             rows_between(travel_mm, 0.0, program.cycles_travel_mm()),
                             &Series::sigma_n, &Series::tau));
  if (cmp["cyclic"].value("post_cyclic", nlohmann::json()).is_object())  // the DEM reached it
    figs.push_back(over_rows("post_cyclic", "Post-cyclic monotonic shear: tau against u_x",
                             "u_x (mm)", "tau (kPa)", c, variants, shown,
                             rows_between(travel_mm, program.cycles_travel_mm(), travel_mm.back()),
                             &Series::u_x, &Series::tau));
  return figs;
}

}  // namespace iwb::comparison
