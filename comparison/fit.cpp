#include "comparison/fit.hpp"

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
double usable(double scale, double magnitude) { return std::max(scale, 1e-9 * std::max(magnitude, 1.0)); }

void append(std::vector<double>& res, const std::vector<double>& dem, const std::vector<double>& model,
            double scale) {
  for (std::size_t i = 0; i < dem.size(); ++i) res.push_back(((i < model.size() ? model[i] : 0.0) - dem[i]) / scale);
}

}  // namespace

FitTargets tau_only_targets() { return {1.0, 0.0, 0.0, "tau alone, in kPa"}; }

FitTargets joint_targets(const DemRun& dem, const SeedScatter& s) {
  const bool seeds = s.from_seeds();
  const double tau = seeds ? s.tau.rms_sd : range(dem.tau_kPa);
  FitTargets t{usable(tau, range(dem.tau_kPa)), 0.0, 0.0, ""};
  const char* what = seeds ? "seed scatter (RMS over rows of the SD across seeds)" : "range over the run (no seeds given)";
  if (dem.boundary == driver::BoundaryKind::kCNL) {
    t.u_n_scale_mm = usable(seeds ? s.u_n.rms_sd : range(dem.u_n_mm), range(dem.u_n_mm));
    t.weighting = fmt::format("tau / {:.3g} kPa and u_n / {:.3g} mm: each by its {}", t.tau_scale_kPa,
                              t.u_n_scale_mm, what);
  } else {
    t.sigma_n_scale_kPa = usable(seeds ? s.sigma_n.rms_sd : range(dem.sigma_n_kPa), range(dem.sigma_n_kPa));
    t.weighting = fmt::format("tau / {:.3g} kPa and sigma_n / {:.3g} kPa: each by its {}", t.tau_scale_kPa,
                              t.sigma_n_scale_kPa, what);
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

FitResult fit_kappa_and_ds(const DemRun& dem, const Variant& start, const FitTargets& targets,
                           const FitBounds& b) {
  // A degenerate kappa_r box (a model that reads no wall roughness) fixes kappa_r at its bound and
  // fits d_s alone: its uncertainty is not invented.
  const bool kappa_fitted = b.kappa_max > b.kappa_min;
  const int n = kappa_fitted ? 2 : 1, ds = n - 1;  // the unknowns: (kappa_r,) ln d_s
  fitting::LeastSquaresProblem p;
  p.residuals = [&](const Eigen::VectorXd& x) {
    Variant v = start;
    v.inputs.roughness.kappa_r = kappa_fitted ? x(0) : b.kappa_min;
    v.d_s_mm = std::exp(x(ds));
    return fit_residuals(dem, replay(dem, v), targets);
  };
  p.lower.resize(n), p.upper.resize(n), p.start.resize(n), p.difference_step.resize(n);
  if (kappa_fitted) {
    p.lower(0) = b.kappa_min, p.upper(0) = b.kappa_max, p.start(0) = start.inputs.roughness.kappa_r;
    p.difference_step(0) = 1e-4 * std::max(start.inputs.roughness.kappa_r, 0.1);
  }
  p.lower(ds) = std::log(b.d_s_min_d50 * dem.d50_mm), p.upper(ds) = std::log(b.d_s_max_d50 * dem.d50_mm);
  p.start(ds) = std::log(start.d_s_mm), p.difference_step(ds) = 1e-4;
  const auto r = fitting::fit_least_squares(p);
  FitResult out;
  out.kappa_r = kappa_fitted ? r.x(0) : b.kappa_min;
  out.kappa_fitted = kappa_fitted;
  out.sigma_kappa_r = kappa_fitted ? r.sigma(0) : 0.0;
  out.d_s_mm = std::exp(r.x(ds));
  out.sigma_d_s_mm = out.d_s_mm * r.sigma(ds);
  out.rms_scaled = r.rmse;
  out.evaluations = r.evaluations;
  for (int k = 0; k < n; ++k)
    if (std::abs(r.x(k) - p.lower(k)) < kAtBound * (p.upper(k) - p.lower(k)) ||
        std::abs(r.x(k) - p.upper(k)) < kAtBound * (p.upper(k) - p.lower(k)))
      out.at_bound.push_back(k == ds ? "d_s" : "kappa_r");
  out.algorithm = fmt::format("NLopt LN_BOBYQA on {}; residuals: {}",
                              kappa_fitted ? "(kappa_r, ln d_s)" : fmt::format("ln d_s (kappa_r fixed at {:g})", b.kappa_min),
                              targets.weighting);
  out.stop_reason = r.stop_reason;
  return out;
}

}  // namespace iwb::comparison
