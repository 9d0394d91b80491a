#pragma once
// Whether any (kappa_r, d_s) makes a model hold on every judged quantity at once (issue 14): a
// scan of the fit's box, kScanPoints x kScanPoints (kappa_r linear, d_s logarithmic), each point
// a replay judged as the variants are. A fit minimises a sum of squares and can miss a corner
// where every tolerance is met; the scan says whether that corner exists, and if not, which
// quantity stands in the way of the best compromise (the point whose worst |error|/tolerance is
// smallest).
#include <nlohmann/json.hpp>
#include <string>

#include "comparison/replay/fit.hpp"
#include "comparison/verdicts/verdicts.hpp"

namespace iwb::comparison {

struct Feasibility {
  int points = 0, feasible = 0;
  double best_kappa_r = 0.0, best_d_s_mm = 0.0;
  double best_worst_ratio = 0.0;  // max over quantities of |error| / tolerance at the best point
  std::string best_worst_quantity;
  std::string finding;  // one sentence for people
};

Feasibility scan_feasibility(const DemRun& dem, const SeedScatter& scatter, const Variant& base,
                             const Tolerances& tolerances, int points_per_axis,
                             const FitBounds& bounds = {});

nlohmann::json to_json(const Feasibility& f);

}  // namespace iwb::comparison
