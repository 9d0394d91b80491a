#include "comparison/verdicts/feasibility.hpp"

#include <fmt/core.h>

#include <cmath>
#include <limits>

namespace iwb::comparison {

namespace {

// max |error| / tolerance over the verdicts, and which quantity it is; a quantity the model did
// not reach counts as infinitely far.
std::pair<double, std::string> worst(const std::vector<Verdict>& verdicts) {
  std::pair<double, std::string> w{0.0, ""};
  for (const auto& v : verdicts) {
    const double r =
        v.error ? std::abs(*v.error) / v.tolerance : std::numeric_limits<double>::infinity();
    if (r > w.first || w.second.empty()) w = {r, v.key};
  }
  return w;
}

std::string finding(const Feasibility& f, const DemRun& dem, const FitBounds& b) {
  const std::string box = fmt::format("kappa_r in [{:g}, {:g}] x d_s in [{:g}, {:g}] d50",
                                      b.kappa_min, b.kappa_max, b.d_s_min_d50, b.d_s_max_d50);
  if (f.feasible > 0)
    return fmt::format("{} of {} points of {} make every quantity hold", f.feasible, f.points, box);
  return fmt::format(
      "no (kappa_r, d_s) of {} makes every quantity hold ({} points); the best compromise, "
      "kappa_r = {:.3f}, d_s = {:.1f} d50, still misses {} by {:.1f} times its tolerance",
      box, f.points, f.best_kappa_r, f.best_d_s_mm / dem.d50_mm, f.best_worst_quantity,
      f.best_worst_ratio);
}

}  // namespace

Feasibility scan_feasibility(const DemRun& dem, const SeedScatter& scatter, const Variant& base,
                             const Tolerances& tolerances, int n, const FitBounds& b) {
  Feasibility f;
  f.best_worst_ratio = std::numeric_limits<double>::infinity();
  const double lo = std::log(b.d_s_min_d50 * dem.d50_mm), hi = std::log(b.d_s_max_d50 * dem.d50_mm);
  const int n_kappa =
      b.kappa_max > b.kappa_min ? n : 1;  // a degenerate box: kappa_r fixed (no roughness)
  for (int i = 0; i < n_kappa; ++i)
    for (int j = 0; j < n; ++j) {
      Variant v = base;
      v.inputs.roughness.kappa_r =
          n_kappa == 1 ? b.kappa_min
                       : b.kappa_min + (b.kappa_max - b.kappa_min) * i / double(n - 1);
      v.d_s_mm = std::exp(lo + (hi - lo) * j / double(n - 1));
      const auto verdicts = judge(dem, scatter, replay(dem, v), tolerances);
      ++f.points;
      if (all_hold(verdicts)) ++f.feasible;
      const auto [ratio, key] = worst(verdicts);
      if (ratio < f.best_worst_ratio)
        f.best_worst_ratio = ratio, f.best_worst_quantity = key,
        f.best_kappa_r = v.inputs.roughness.kappa_r, f.best_d_s_mm = v.d_s_mm;
    }
  f.finding = finding(f, dem, b);
  return f;
}

nlohmann::json to_json(const Feasibility& f) {
  return {{"points", f.points},
          {"feasible", f.feasible},
          {"best_compromise",
           {{"kappa_r", f.best_kappa_r},
            {"d_s_mm", f.best_d_s_mm},
            {"worst_error_over_tolerance", std::isfinite(f.best_worst_ratio)
                                               ? nlohmann::json(f.best_worst_ratio)
                                               : nlohmann::json(nullptr)},
            {"worst_quantity", f.best_worst_quantity}}},
          {"finding", f.finding}};
}

}  // namespace iwb::comparison
