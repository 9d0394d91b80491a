#include "fitting/constrained.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <nlopt.hpp>
#include <vector>

namespace iwb::fitting {

namespace {

// NLopt asks for the objective and the constraints at the same point one after the other: the
// last point is kept, and the best feasible point seen, which COBYLA does not always return (it
// may stop on a point a tolerance outside the constraints).
struct Evaluator {
  const ConstrainedProblem& problem;
  Eigen::VectorXd last_x;
  ConstrainedEvaluation last;
  int evaluations = 0;
  Eigen::VectorXd best_x;
  ConstrainedEvaluation best;
  double best_objective = INFINITY;

  const ConstrainedEvaluation& at(const double* x) {
    const Eigen::Map<const Eigen::VectorXd> v(x, problem.start.size());
    if (evaluations > 0 && last_x == v) return last;
    last_x = v;
    last = problem.evaluate(last_x);
    ++evaluations;
    const double f = last.residuals.squaredNorm();
    if ((last.constraints.array() <= 0.0).all() && f < best_objective)
      best_objective = f, best_x = last_x, best = last;
    return last;
  }
};

double squared_norm(unsigned n, const double* x, double* /*grad*/, void* data) {
  (void)n;
  return static_cast<Evaluator*>(data)->at(x).residuals.squaredNorm();
}

void constraint_values(unsigned m, double* c, unsigned /*n*/, const double* x, double* /*grad*/,
                       void* data) {
  const auto& e = static_cast<Evaluator*>(data)->at(x);
  for (unsigned k = 0; k < m; ++k) c[k] = e.constraints(Eigen::Index(k));
}

}  // namespace

ConstrainedResult fit_constrained(const ConstrainedProblem& problem,
                                  const ConstrainedSettings& settings) {
  const auto n = unsigned(problem.start.size());
  Evaluator eval{problem, {}, {}, 0, {}, {}, INFINITY};
  nlopt::opt opt(nlopt::LN_COBYLA, n);
  const std::vector<double> lo(problem.lower.data(), problem.lower.data() + n);
  const std::vector<double> hi(problem.upper.data(), problem.upper.data() + n);
  opt.set_lower_bounds(lo);
  opt.set_upper_bounds(hi);
  opt.set_min_objective(squared_norm, &eval);
  opt.add_inequality_mconstraint(constraint_values, &eval,
                                 std::vector<double>(std::size_t(problem.constraints), 0.0));
  opt.set_xtol_rel(settings.xtol_rel);
  opt.set_maxeval(settings.max_evaluations);
  std::vector<double> step(n), x(n);
  for (unsigned k = 0; k < n; ++k) {
    step[k] = settings.initial_step_share * (hi[k] - lo[k]);
    x[k] = std::clamp(problem.start(Eigen::Index(k)), lo[k], hi[k]);
  }
  opt.set_initial_step(step);
  // the start first: what is returned when no point meets the constraints
  const Eigen::VectorXd start = Eigen::Map<const Eigen::VectorXd>(x.data(), Eigen::Index(n));
  const ConstrainedEvaluation at_start = eval.at(x.data());
  ConstrainedResult out;
  double f = 0.0;
  try {
    const auto r = opt.optimize(x, f);
    out.stop_reason = r == nlopt::MAXEVAL_REACHED ? "evaluation limit" : "converged";
  } catch (const std::exception& e) {  // a roundoff-limited stop still leaves the best point
    out.stop_reason = fmt::format("stopped: {}", e.what());
  }
  out.evaluations = eval.evaluations;
  out.feasible = std::isfinite(eval.best_objective);
  out.x = out.feasible ? eval.best_x : start;
  out.at = out.feasible ? eval.best : at_start;
  out.rmse = out.at.residuals.size() > 0
                 ? std::sqrt(out.at.residuals.squaredNorm() / double(out.at.residuals.size()))
                 : 0.0;
  return out;
}

}  // namespace iwb::fitting
