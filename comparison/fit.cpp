#include "comparison/fit.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <fmt/core.h>
#include <nlopt.hpp>

namespace iwb::comparison {

namespace {

struct Problem {
  const DemRun& dem;
  Variant variant;
  int evaluations = 0;

  // tau residuals (kPa) at every DEM row; rows a replay did not reach count as tau_model = 0,
  // so that a parameter set leaving the model's domain is penalised, not rewarded
  Eigen::VectorXd residuals(double kappa, double log_ds) {
    ++evaluations;
    variant.inputs.roughness.kappa_r = kappa;
    variant.d_s_mm = std::exp(log_ds);
    const Replay r = replay(dem, variant);
    Eigen::VectorXd res(Eigen::Index(dem.tau_kPa.size()));
    for (std::size_t i = 0; i < dem.tau_kPa.size(); ++i)
      res(Eigen::Index(i)) = (i < r.tau_kPa.size() ? r.tau_kPa[i] : 0.0) - dem.tau_kPa[i];
    return res;
  }
};

double objective(const std::vector<double>& x, std::vector<double>& /*grad*/, void* data) {
  return static_cast<Problem*>(data)->residuals(x[0], x[1]).squaredNorm();
}

}  // namespace

FitResult fit_kappa_and_ds(const DemRun& dem, const Variant& start, const FitBounds& b) {
  Problem p{dem, start};
  nlopt::opt opt(nlopt::LN_BOBYQA, 2);
  const std::vector<double> lo = {b.kappa_min, std::log(b.d_s_min_d50 * dem.d50_mm)};
  const std::vector<double> hi = {b.kappa_max, std::log(b.d_s_max_d50 * dem.d50_mm)};
  opt.set_lower_bounds(lo);
  opt.set_upper_bounds(hi);
  opt.set_min_objective(objective, &p);
  opt.set_xtol_rel(1e-7);
  opt.set_maxeval(400);
  std::vector<double> x = {std::clamp(start.inputs.roughness.kappa_r, lo[0], hi[0]),
                           std::clamp(std::log(start.d_s_mm), lo[1], hi[1])};
  double f = 0.0;
  FitResult out;
  try {
    const nlopt::result r = opt.optimize(x, f);
    out.stop_reason = r == nlopt::XTOL_REACHED ? "parameters converged" : r == nlopt::MAXEVAL_REACHED ? "evaluation limit" : "converged";
  } catch (const std::exception& e) {
    out.stop_reason = fmt::format("stopped: {}", e.what());
  }
  out.kappa_r = x[0];
  out.d_s_mm = std::exp(x[1]);
  // Gauss-Newton covariance from the residuals' Jacobian at the optimum
  const Eigen::VectorXd r0 = p.residuals(x[0], x[1]);
  const Eigen::Index n = r0.size();
  Eigen::MatrixXd J(n, 2);
  const double h[2] = {1e-4 * std::max(x[0], 0.1), 1e-4};
  for (int k = 0; k < 2; ++k) {
    std::vector<double> xp = x, xm = x;
    xp[k] += h[k];
    xm[k] -= h[k];
    J.col(k) = (p.residuals(xp[0], xp[1]) - p.residuals(xm[0], xm[1])) / (2.0 * h[k]);
  }
  const double s2 = r0.squaredNorm() / double(std::max<Eigen::Index>(n - 2, 1));
  const Eigen::Matrix2d cov = s2 * (J.transpose() * J).inverse();
  out.sigma_kappa_r = std::sqrt(std::max(cov(0, 0), 0.0));
  out.sigma_d_s_mm = out.d_s_mm * std::sqrt(std::max(cov(1, 1), 0.0));
  out.rmse_tau_kPa = std::sqrt(r0.squaredNorm() / double(n));
  out.evaluations = p.evaluations;
  return out;
}

}  // namespace iwb::comparison
