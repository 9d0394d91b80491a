#pragma once
// Bounded nonlinear least squares for the workbench's fits (comparison/fit: kappa_r and d_s to a
// DEM run; src/calibration: hypoplastic parameters to soil tests). One procedure, so both report
// the same kind of uncertainty:
//   - minimise ||r(x)||^2 with NLopt's derivative-free LN_BOBYQA inside box bounds (the residuals
//     come from element-test runs whose derivatives we do not have, and runs that leave the
//     model's domain make r jump: a model-based trust region copes, Levenberg-Marquardt does not);
//   - optionally, bounded Levenberg-Marquardt steps from there (polish_iterations > 0): near the
//     optimum the residuals are smooth and Gauss-Newton converges in a few Jacobians where
//     BOBYQA, in 8 dimensions, can spend its whole budget crawling along a curved valley;
//   - at the optimum, J by central differences and the Gauss-Newton covariance
//     C = s^2 (J^T J)^-1 with s^2 = ||r||^2 / (m - p).
// Directions of J^T J whose eigenvalue is below kSingularRelative of the largest are treated as
// unidentifiable: C is the pseudo-inverse on the rest and the parameters with weight on the null
// directions get an infinite sigma, instead of a number the data do not support.
#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

namespace iwb::fitting {

using ResidualFunction = std::function<Eigen::VectorXd(const Eigen::VectorXd&)>;

struct LeastSquaresProblem {
  ResidualFunction residuals;
  Eigen::VectorXd start, lower, upper;
  Eigen::VectorXd difference_step;  // central-difference step per coordinate for J
};

struct LeastSquaresSettings {
  double xtol_rel = 1e-7;
  int max_evaluations = 400;
  // BOBYQA's first trust-region radius as a share of each box width; 0 = NLopt's default (a
  // large share, right for a start far from the optimum, wasteful near it).
  double initial_step_share = 0.0;
  // Most Levenberg-Marquardt iterations after BOBYQA (each 2p+1 to 2p+kPolishTrials evaluations);
  // they stop earlier when converged.
  int polish_iterations = 0;
};

// Relative eigenvalue of J^T J below which a direction counts as unidentifiable (the data do not
// change when the parameters move along it, to the precision of double and the integrator).
inline constexpr double kSingularRelative = 1e-12;

struct LeastSquaresResult {
  Eigen::VectorXd x;
  Eigen::VectorXd residuals;   // at x
  Eigen::MatrixXd jacobian;    // at x
  Eigen::MatrixXd covariance;  // s^2 (J^T J)^+ ; rows/columns of unidentifiable parameters inf
  // (J^T J)^+ alone: the covariance at unit residual variance. With residuals scaled by their
  // expected scatter, it says how well the data *could* determine x even when a noise-free
  // (synthetic) target makes s^2 vanish.
  Eigen::MatrixXd unit_covariance;
  Eigen::VectorXd sigma;  // sqrt of the diagonal; inf where unidentifiable
  double rmse = 0.0;      // sqrt(||r||^2 / m)
  int evaluations = 0;
  std::string stop_reason;
  // False when the last stage stopped at its limit (BOBYQA's evaluations, or Levenberg-Marquardt's
  // iterations) rather than on its convergence test: the estimate and its sigma are then not
  // to be trusted.
  bool converged = false;
};

// The most residual evaluations fit_least_squares can take for `unknowns` parameters: BOBYQA's
// budget; the polish's first evaluation and, per Levenberg-Marquardt iteration, a
// central-difference Jacobian (2 unknowns) and up to kPolishTrials trial steps; the covariance's
// Jacobian and residual. A progress line's "at most" (it usually stops well before). For
// max_evaluations > 0 only: NLopt reads 0 or less as no limit.
inline constexpr int kPolishTrials = 8;
int most_evaluations(const LeastSquaresSettings& settings, int unknowns);

// Minimises from `start` (clamped into the bounds) and returns the optimum with its covariance.
LeastSquaresResult fit_least_squares(const LeastSquaresProblem& problem,
                                     const LeastSquaresSettings& settings = {});

// The covariance part alone, at a given x: used after a fit, and for a profile of fixed x.
void gauss_newton_covariance(const LeastSquaresProblem& problem, LeastSquaresResult& at);

}  // namespace iwb::fitting
