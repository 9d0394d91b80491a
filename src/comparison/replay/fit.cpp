#include "comparison/replay/fit.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "fitting/least_squares.hpp"

namespace iwb::comparison {

namespace {

// An optimum within this share of the box width from a bound sits on it.
constexpr double kAtBound = 1e-3;

double range(const std::vector<double>& x) {
  const auto [lo, hi] = std::minmax_element(x.begin(), x.end());
  return *hi - *lo;
}

// A scale that is never 0: a DEM series without scatter or range (a CV run's u_n) gets a tiny
// one relative to its magnitude, so a residual stays finite.
double usable(double scale, double magnitude) {
  return std::max(scale, 1e-9 * std::max(magnitude, 1.0));
}

void append(std::vector<double>& res, const std::vector<double>& dem,
            const std::vector<double>& model, double scale) {
  for (std::size_t i = 0; i < dem.size(); ++i)
    res.push_back(((i < model.size() ? model[i] : 0.0) - dem[i]) / scale);
}

}  // namespace

FitTargets tau_only_targets() {
  return {1.0, 0.0, 0.0, "tau alone, in kPa"};
}

FitTargets joint_targets(const DemRun& dem, const SeedScatter& s) {
  const bool seeds = s.from_seeds();
  const double tau = seeds ? s.tau.rms_sd : range(dem.tau_kPa);
  FitTargets t{usable(tau, range(dem.tau_kPa)), 0.0, 0.0, ""};
  const char* what = seeds ? "seed scatter (RMS over rows of the SD across seeds)"
                           : "range over the run (no seeds given)";
  if (dem.boundary == driver::BoundaryKind::kCNL) {
    t.u_n_scale_mm = usable(seeds ? s.u_n.rms_sd : range(dem.u_n_mm), range(dem.u_n_mm));
    t.weighting = fmt::format("tau / {:.3g} kPa and u_n / {:.3g} mm: each by its {}",
                              t.tau_scale_kPa, t.u_n_scale_mm, what);
  } else {
    t.sigma_n_scale_kPa =
        usable(seeds ? s.sigma_n.rms_sd : range(dem.sigma_n_kPa), range(dem.sigma_n_kPa));
    t.weighting = fmt::format("tau / {:.3g} kPa and sigma_n / {:.3g} kPa: each by its {}",
                              t.tau_scale_kPa, t.sigma_n_scale_kPa, what);
  }
  return t;
}

Eigen::VectorXd fit_residuals(const DemRun& dem, const Replay& r, const FitTargets& t) {
  std::vector<double> res;
  append(res, dem.tau_kPa, r.tau_kPa, t.tau_scale_kPa);
  if (t.u_n_scale_mm > 0.0) append(res, dem.u_n_mm, r.u_n_mm, t.u_n_scale_mm);
  if (t.sigma_n_scale_kPa > 0.0) append(res, dem.sigma_n_kPa, r.sigma_n_kPa, t.sigma_n_scale_kPa);
  return Eigen::Map<Eigen::VectorXd>(res.data(), Eigen::Index(res.size()));
}

double value_of(const Variant& v, const models::FitParameter& what) {
  switch (what.target) {
    case models::FitParameter::Target::kRoughness:
      return v.inputs.roughness.kappa_r;
    case models::FitParameter::Target::kShearZone:
      return v.d_s_mm;
    case models::FitParameter::Target::kParameter:
      return v.inputs.tables.at(what.table).at(what.key);
  }
  return NAN;
}

void set_value(Variant& v, const models::FitParameter& what, double x) {
  switch (what.target) {
    case models::FitParameter::Target::kRoughness:
      v.inputs.roughness.kappa_r = x;
      return;
    case models::FitParameter::Target::kShearZone:
      v.d_s_mm = x;
      return;
    case models::FitParameter::Target::kParameter:
      v.inputs.tables[what.table][what.key] = x;
      return;
  }
}

namespace {

// The optimiser's coordinate of unknown u and back: ln x for a logarithmic one.
double to_x(const Unknown& u, double v) {
  return u.what.logarithmic ? std::log(v) : v;
}
double from_x(const Unknown& u, double x) {
  return u.what.logarithmic ? std::exp(x) : x;
}

Variant variant_at(const Variant& start, const std::vector<Unknown>& unknowns,
                   const Eigen::VectorXd& x) {
  Variant v = start;
  for (std::size_t k = 0; k < unknowns.size(); ++k)
    set_value(v, unknowns[k].what, from_x(unknowns[k], x(Eigen::Index(k))));
  return v;
}

bool on_bound(const fitting::LeastSquaresProblem& p, const Eigen::VectorXd& x, int k) {
  const double width = p.upper(k) - p.lower(k);
  return std::abs(x(k) - p.lower(k)) < kAtBound * width ||
         std::abs(x(k) - p.upper(k)) < kAtBound * width;
}

bool any_on_bound(const fitting::LeastSquaresProblem& p, const Eigen::VectorXd& x) {
  for (int k = 0; k < int(x.size()); ++k)
    if (on_bound(p, x, k)) return true;
  return false;
}

// A start on the edge of the box (eq. 5.35's kappa_r floor on a flat wall) can lead BOBYQA into a
// local optimum on that edge where the model has no friction at all, although the box holds a
// far better fit (issue 34's flat cyclic cells). An optimum on a bound is therefore tried once
// more from the box's centre, and the better of the two kept.
fitting::LeastSquaresResult fit_with_second_start(fitting::LeastSquaresProblem p,
                                                  std::string& note) {
  auto first = fitting::fit_least_squares(p);
  if (!any_on_bound(p, first.x)) return first;
  p.start = (p.lower + p.upper) / 2.0;
  auto second = fitting::fit_least_squares(p);
  const bool keep_second = second.rmse < first.rmse;
  note = fmt::format(
      "the first start ended on a bound (scaled RMS {:.3g}); a second from the box's centre "
      "ended at {:.3g}: kept the {}",
      first.rmse, second.rmse, keep_second ? "second" : "first");
  auto& kept = keep_second ? second : first;
  kept.evaluations = first.evaluations + second.evaluations;
  return kept;
}

}  // namespace

VariantFit fit_variant(const DemRun& dem, const Variant& start, const FitTargets& targets,
                       const std::vector<Unknown>& unknowns) {
  const int n = int(unknowns.size());
  fitting::LeastSquaresProblem p;
  p.residuals = [&](const Eigen::VectorXd& x) {
    return fit_residuals(dem, replay(dem, variant_at(start, unknowns, x)), targets);
  };
  p.lower.resize(n), p.upper.resize(n), p.start.resize(n), p.difference_step.resize(n);
  for (int k = 0; k < n; ++k) {
    const auto& u = unknowns[std::size_t(k)];
    p.lower(k) = to_x(u, u.lower), p.upper(k) = to_x(u, u.upper);
    p.start(k) = std::clamp(to_x(u, value_of(start, u.what)), p.lower(k), p.upper(k));
    p.difference_step(k) = u.what.logarithmic ? 1e-4 : 1e-4 * std::max(std::abs(p.start(k)), 0.1);
  }
  VariantFit out;
  const auto r = fit_with_second_start(p, out.starts);
  out.best = variant_at(start, unknowns, r.x);
  out.rms_scaled = r.rmse, out.evaluations = r.evaluations, out.stop_reason = r.stop_reason;
  for (int k = 0; k < n; ++k) {
    const auto& u = unknowns[std::size_t(k)];
    const double v = from_x(u, r.x(k));
    const double sigma = u.what.logarithmic ? v * r.sigma(k) : r.sigma(k);
    out.values.push_back({u.what.name, v, sigma, on_bound(p, r.x, k)});
  }
  return out;
}

FitResult fit_kappa_and_ds(const DemRun& dem, const Variant& start, const FitTargets& targets,
                           const FitBounds& b) {
  // A degenerate kappa_r box (a model that reads no wall roughness) fixes kappa_r at its bound and
  // fits d_s alone: its uncertainty is not invented.
  const bool kappa_fitted = b.kappa_max > b.kappa_min;
  using Target = models::FitParameter::Target;
  std::vector<Unknown> unknowns;
  if (kappa_fitted) unknowns.push_back({{"kappa_r", Target::kRoughness}, b.kappa_min, b.kappa_max});
  unknowns.push_back({{"d_s", Target::kShearZone, {}, {}, 0.0, 0.0, false, true},
                      b.d_s_min_d50 * dem.d50_mm,
                      b.d_s_max_d50 * dem.d50_mm});
  Variant from = start;
  if (!kappa_fitted) from.inputs.roughness.kappa_r = b.kappa_min;
  const auto r = fit_variant(dem, from, targets, unknowns);
  FitResult out;
  out.kappa_fitted = kappa_fitted;
  out.kappa_r = r.best.inputs.roughness.kappa_r;
  out.sigma_kappa_r = kappa_fitted ? r.values.front().sigma : 0.0;
  out.d_s_mm = r.values.back().value;
  out.sigma_d_s_mm = r.values.back().sigma;
  out.rms_scaled = r.rms_scaled;
  out.evaluations = r.evaluations;
  for (const auto& v : r.values)
    if (v.at_bound) out.at_bound.push_back(v.name);
  out.algorithm =
      fmt::format("NLopt LN_BOBYQA on {}; residuals: {}",
                  kappa_fitted ? "(kappa_r, ln d_s)"
                               : fmt::format("ln d_s (kappa_r fixed at {:g})", b.kappa_min),
                  targets.weighting);
  out.stop_reason = r.stop_reason;
  if (!r.starts.empty()) out.algorithm += "; " + r.starts;
  return out;
}

}  // namespace iwb::comparison
