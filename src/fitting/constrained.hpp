#pragma once
// Bounded least squares under inequality constraints (issue 59): minimise ||r(x)||^2 subject to
// c_k(x) <= 0, inside box bounds. For a material set that must fit DEM runs while the soil tests
// still accept it (comparison/causes/form_limit.hpp): the constraints are not smooth (a model that
// leaves its domain makes them jump) and have no derivatives we know, so NLopt's derivative-free
// LN_COBYLA, which takes inequality constraints directly, from a start that meets them (then every
// point it returns as feasible is one the constraints accept; a penalty would trade a violation
// against the fit by a weight nobody can state).
#include <Eigen/Core>
#include <functional>
#include <string>

namespace iwb::fitting {

struct ConstrainedEvaluation {
  Eigen::VectorXd residuals;    // r(x)
  Eigen::VectorXd constraints;  // c(x): met where every entry is <= 0
};

struct ConstrainedProblem {
  // Both at once: r and c come from the same runs, so each point is evaluated once.
  std::function<ConstrainedEvaluation(const Eigen::VectorXd&)> evaluate;
  Eigen::VectorXd start, lower, upper;
  Eigen::Index constraints = 0;
};

struct ConstrainedSettings {
  double xtol_rel = 1e-5;
  int max_evaluations = 600;
  double initial_step_share = 0.05;  // COBYLA's first simplex, as a share of each box width
};

struct ConstrainedResult {
  Eigen::VectorXd x;  // the best point that meets every constraint (the start if none better)
  ConstrainedEvaluation at;
  double rmse = 0.0;  // sqrt(||r||^2 / m) at x
  int evaluations = 0;
  bool feasible = false;  // every c_k(x) <= 0
  std::string stop_reason;
};

// The best point met that meets every constraint. When none does (the start does not either),
// `feasible` is false and the start is returned: the caller says what that means.
ConstrainedResult fit_constrained(const ConstrainedProblem& problem,
                                  const ConstrainedSettings& settings = {});

}  // namespace iwb::fitting
