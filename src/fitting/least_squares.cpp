#include "fitting/least_squares.hpp"

#include <fmt/core.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <nlopt.hpp>

namespace iwb::fitting {

namespace {

struct Counted {
  const LeastSquaresProblem& problem;
  int evaluations = 0;
  Eigen::VectorXd operator()(const Eigen::VectorXd& x) {
    ++evaluations;
    return problem.residuals(x);
  }
};

double objective(const std::vector<double>& x, std::vector<double>& /*grad*/, void* data) {
  auto& f = *static_cast<Counted*>(data);
  return f(Eigen::Map<const Eigen::VectorXd>(x.data(), Eigen::Index(x.size()))).squaredNorm();
}

std::string describe(nlopt::result r) {
  switch (r) {
    case nlopt::XTOL_REACHED:
      return "parameters converged";
    case nlopt::FTOL_REACHED:
      return "objective converged";
    case nlopt::MAXEVAL_REACHED:
      return "evaluation limit";
    case nlopt::STOPVAL_REACHED:
      return "objective reached zero";
    default:
      return "converged";
  }
}

Eigen::MatrixXd central_jacobian(const LeastSquaresProblem& problem, const Eigen::VectorXd& x,
                                 Eigen::Index m, int& evaluations) {
  const Eigen::Index p = x.size();
  Eigen::MatrixXd J(m, p);
  for (Eigen::Index k = 0; k < p; ++k) {
    // Central differences, kept inside the box: a one-sided step at a bound would halve the order.
    Eigen::VectorXd xp = x, xm = x;
    xp(k) = std::min(x(k) + problem.difference_step(k), problem.upper(k));
    xm(k) = std::max(x(k) - problem.difference_step(k), problem.lower(k));
    J.col(k) = (problem.residuals(xp) - problem.residuals(xm)) / (xp(k) - xm(k));
  }
  evaluations += int(2 * p);
  return J;
}

// Levenberg-Marquardt with Marquardt's diagonal scaling, steps clamped into the box. Converged
// when a Jacobian no longer buys a relative decrease of kPolishDecrease in ||r||^2 (or ||r||
// reached zero); a stop at the iteration limit is reported as not converged, because a noise-free
// calibration stopped there sits many of its own sigmas from the truth (issue 20 item 3).
struct PolishOutcome {
  int iterations = 0;
  bool converged = false;
  std::string reason;
};

PolishOutcome polish(const LeastSquaresProblem& problem, int iterations, Eigen::VectorXd& x,
                     int& evaluations) {
  constexpr double kPolishDecrease = 1e-10;
  Eigen::VectorXd r = problem.residuals(x);
  ++evaluations;
  double lambda = 1e-3;
  PolishOutcome out;
  for (; out.iterations < iterations; ++out.iterations) {
    if (r.squaredNorm() == 0.0) return {out.iterations, true, "residuals zero"};
    const Eigen::MatrixXd J = central_jacobian(problem, x, r.size(), evaluations);
    const Eigen::MatrixXd jtj = J.transpose() * J;
    const Eigen::VectorXd g = J.transpose() * r;
    bool improved = false;
    for (int tries = 0; tries < kPolishTrials && !improved; ++tries, lambda *= 10.0) {
      Eigen::MatrixXd a = jtj;
      a.diagonal() += lambda * jtj.diagonal().cwiseMax(1e-300);
      const Eigen::VectorXd trial =
          (x - a.ldlt().solve(g)).cwiseMax(problem.lower).cwiseMin(problem.upper);
      const Eigen::VectorXd rt = problem.residuals(trial);
      ++evaluations;
      if (rt.squaredNorm() < r.squaredNorm()) {
        const double decrease = 1.0 - rt.squaredNorm() / r.squaredNorm();
        x = trial;
        r = rt;
        improved = true;
        lambda = std::max(lambda / 100.0, 1e-9);
        if (decrease < kPolishDecrease)
          return {out.iterations + 1, true, "relative decrease below 1e-10"};
      }
    }
    if (!improved) return {out.iterations + 1, true, "no step decreases the residual"};
  }
  out.reason = "iteration limit";
  return out;
}

}  // namespace

void gauss_newton_covariance(const LeastSquaresProblem& problem, LeastSquaresResult& at) {
  const Eigen::Index p = at.x.size();
  at.residuals = problem.residuals(at.x);
  const Eigen::Index m = at.residuals.size();
  at.jacobian = central_jacobian(problem, at.x, m, at.evaluations);
  at.evaluations += 1;
  const double s2 = at.residuals.squaredNorm() / double(std::max<Eigen::Index>(m - p, 1));
  const Eigen::MatrixXd jtj = at.jacobian.transpose() * at.jacobian;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(jtj);
  const double largest = eig.eigenvalues().cwiseAbs().maxCoeff();
  Eigen::MatrixXd pinv = Eigen::MatrixXd::Zero(p, p);
  Eigen::VectorXd null_weight = Eigen::VectorXd::Zero(p);
  for (Eigen::Index i = 0; i < p; ++i) {
    const double lambda = eig.eigenvalues()(i);
    const Eigen::VectorXd v = eig.eigenvectors().col(i);
    if (largest > 0.0 && lambda > kSingularRelative * largest)
      pinv += v * v.transpose() / lambda;
    else
      null_weight += v.cwiseAbs2();
  }
  at.unit_covariance = pinv;
  at.covariance = s2 * pinv;
  at.sigma.resize(p);
  // A parameter with a share of a null direction above this is not determined by the data.
  constexpr double kNullShare = 1e-3;
  for (Eigen::Index k = 0; k < p; ++k) {
    at.sigma(k) = null_weight(k) > kNullShare ? std::numeric_limits<double>::infinity()
                                              : std::sqrt(std::max(at.covariance(k, k), 0.0));
    if (std::isinf(at.sigma(k))) {
      at.covariance.row(k).setConstant(std::numeric_limits<double>::infinity());
      at.covariance.col(k).setConstant(std::numeric_limits<double>::infinity());
      at.unit_covariance.row(k).setConstant(std::numeric_limits<double>::infinity());
      at.unit_covariance.col(k).setConstant(std::numeric_limits<double>::infinity());
    }
  }
  at.rmse = std::sqrt(at.residuals.squaredNorm() / double(std::max<Eigen::Index>(m, 1)));
}

int most_evaluations(const LeastSquaresSettings& settings, int unknowns) {
  const int polish = settings.polish_iterations > 0
                         ? 1 + settings.polish_iterations * (2 * unknowns + kPolishTrials)
                         : 0;
  return settings.max_evaluations + polish + 2 * unknowns + 1;
}

LeastSquaresResult fit_least_squares(const LeastSquaresProblem& problem,
                                     const LeastSquaresSettings& settings) {
  const auto n = unsigned(problem.start.size());
  Counted counted{problem};
  nlopt::opt opt(nlopt::LN_BOBYQA, n);
  const std::vector<double> lo(problem.lower.data(), problem.lower.data() + n);
  const std::vector<double> hi(problem.upper.data(), problem.upper.data() + n);
  opt.set_lower_bounds(lo);
  opt.set_upper_bounds(hi);
  opt.set_min_objective(objective, &counted);
  opt.set_xtol_rel(settings.xtol_rel);
  opt.set_maxeval(settings.max_evaluations);
  opt.set_stopval(0.0);
  if (settings.initial_step_share > 0.0) {
    std::vector<double> step(n);
    for (unsigned k = 0; k < n; ++k) step[k] = settings.initial_step_share * (hi[k] - lo[k]);
    opt.set_initial_step(step);
  }
  std::vector<double> x(n);
  for (unsigned k = 0; k < n; ++k) x[k] = std::clamp(problem.start(Eigen::Index(k)), lo[k], hi[k]);
  LeastSquaresResult out;
  double f = 0.0;
  try {
    out.stop_reason = describe(opt.optimize(x, f));
  } catch (const std::exception& e) {  // NLopt's roundoff-limited stop still leaves the best x
    out.stop_reason = fmt::format("stopped: {}", e.what());
  }
  out.x = Eigen::Map<const Eigen::VectorXd>(x.data(), Eigen::Index(n));
  out.evaluations = counted.evaluations;
  out.converged = out.stop_reason != "evaluation limit";
  if (settings.polish_iterations > 0) {
    const auto lm = polish(problem, settings.polish_iterations, out.x, out.evaluations);
    out.converged = lm.converged;
    out.stop_reason += fmt::format(
        ", then Levenberg-Marquardt: {} after {} iteration(s)",
        lm.converged ? "converged, " + lm.reason : "NOT CONVERGED, " + lm.reason, lm.iterations);
  }
  gauss_newton_covariance(problem, out);
  return out;
}

}  // namespace iwb::fitting
