#include "comparison/fit.hpp"

#include <cmath>

#include "fitting/least_squares.hpp"

namespace iwb::comparison {

namespace {

// tau residuals (kPa) at every DEM row; rows a replay did not reach count as tau_model = 0,
// so that a parameter set leaving the model's domain is penalised, not rewarded
Eigen::VectorXd tau_residuals(const DemRun& dem, Variant variant, double kappa, double log_ds) {
  variant.inputs.roughness.kappa_r = kappa;
  variant.d_s_mm = std::exp(log_ds);
  const Replay r = replay(dem, variant);
  Eigen::VectorXd res(Eigen::Index(dem.tau_kPa.size()));
  for (std::size_t i = 0; i < dem.tau_kPa.size(); ++i)
    res(Eigen::Index(i)) = (i < r.tau_kPa.size() ? r.tau_kPa[i] : 0.0) - dem.tau_kPa[i];
  return res;
}

}  // namespace

FitResult fit_kappa_and_ds(const DemRun& dem, const Variant& start, const FitBounds& b) {
  fitting::LeastSquaresProblem p;
  p.residuals = [&](const Eigen::VectorXd& x) { return tau_residuals(dem, start, x(0), x(1)); };
  p.lower = Eigen::Vector2d(b.kappa_min, std::log(b.d_s_min_d50 * dem.d50_mm));
  p.upper = Eigen::Vector2d(b.kappa_max, std::log(b.d_s_max_d50 * dem.d50_mm));
  p.start = Eigen::Vector2d(start.inputs.roughness.kappa_r, std::log(start.d_s_mm));
  p.difference_step = Eigen::Vector2d(1e-4 * std::max(start.inputs.roughness.kappa_r, 0.1), 1e-4);
  const auto r = fitting::fit_least_squares(p);
  FitResult out;
  out.kappa_r = r.x(0);
  out.d_s_mm = std::exp(r.x(1));
  out.sigma_kappa_r = r.sigma(0);
  out.sigma_d_s_mm = out.d_s_mm * r.sigma(1);
  out.rmse_tau_kPa = r.rmse;
  out.evaluations = r.evaluations;
  out.stop_reason = r.stop_reason;
  return out;
}

}  // namespace iwb::comparison
