// Least squares under inequality constraints, on problems solved by hand: the nearest point of a
// half-plane is the orthogonal projection onto its edge; a constraint that does not bind leaves
// the unconstrained optimum; a start no point improves on is returned as it is.
#include <catch2/catch.hpp>
#include <cmath>

#include "fitting/constrained.hpp"

using namespace iwb;

namespace {
// r(x) = x - (2, 2), constrained by x0 + x1 <= s: for s < 4 the optimum is the projection of
// (2, 2) onto x0 + x1 = s, (s/2, s/2), with ||r||^2 = 2 (2 - s/2)^2.
fitting::ConstrainedProblem half_plane(double s) {
  fitting::ConstrainedProblem p;
  p.evaluate = [s](const Eigen::VectorXd& x) {
    return fitting::ConstrainedEvaluation{x - Eigen::Vector2d(2.0, 2.0),
                                          Eigen::VectorXd::Constant(1, x(0) + x(1) - s)};
  };
  p.start = Eigen::Vector2d(0.0, 0.0);
  p.lower = Eigen::Vector2d(-5.0, -5.0);
  p.upper = Eigen::Vector2d(5.0, 5.0);
  p.constraints = 1;
  return p;
}
}  // namespace

TEST_CASE("constrained least squares: a binding half-plane gives the projection onto its edge",
          "[fitting]") {
  const auto r = fitting::fit_constrained(half_plane(2.0));
  REQUIRE(r.feasible);
  CHECK(r.x(0) == Approx(1.0).margin(1e-3));
  CHECK(r.x(1) == Approx(1.0).margin(1e-3));
  CHECK(r.at.constraints(0) <= 0.0);
  CHECK(r.rmse == Approx(std::sqrt(2.0 * 1.0 * 1.0 / 2.0)).margin(1e-3));
}

TEST_CASE("constrained least squares: a constraint that does not bind leaves the plain optimum",
          "[fitting]") {
  const auto r = fitting::fit_constrained(half_plane(10.0));
  REQUIRE(r.feasible);
  CHECK(r.x(0) == Approx(2.0).margin(1e-3));
  CHECK(r.x(1) == Approx(2.0).margin(1e-3));
}

TEST_CASE("constrained least squares: when no point meets the constraints the start is returned",
          "[fitting]") {
  auto p = half_plane(-100.0);  // x0 + x1 >= -10 inside the box: never met
  p.start = Eigen::Vector2d(0.5, -0.5);
  const auto r = fitting::fit_constrained(p);
  CHECK_FALSE(r.feasible);
  CHECK(r.x(0) == 0.5);
  CHECK(r.x(1) == -0.5);
}
