// The shared least-squares core: on a linear model the Gauss-Newton covariance is exact, and a
// direction the residuals do not depend on is reported as unidentifiable (infinite sigma), not as
// a number.
#include <Eigen/Dense>
#include <catch2/catch.hpp>
#include <cmath>

#include "fitting/least_squares.hpp"

using namespace iwb;

namespace {
// y = 2 + 0.5 t at t = 0..9 with a fixed, zero-mean, non-trivial perturbation
Eigen::VectorXd times() {
  return Eigen::VectorXd::LinSpaced(10, 0.0, 9.0);
}
Eigen::VectorXd data() {
  Eigen::VectorXd y = 2.0 + 0.5 * times().array();
  const double noise[10] = {0.03, -0.02, 0.01, -0.04, 0.02, 0.00, -0.01, 0.03, -0.03, 0.01};
  for (int i = 0; i < 10; ++i) y(i) += noise[i];
  return y;
}
}  // namespace

TEST_CASE("linear least squares: optimum and covariance equal the normal equations", "[fitting]") {
  fitting::LeastSquaresProblem p;
  p.residuals = [](const Eigen::VectorXd& x) -> Eigen::VectorXd {
    return (x(0) + x(1) * times().array()).matrix() - data();
  };
  p.start = Eigen::Vector2d(0.0, 0.0);
  p.lower = Eigen::Vector2d(-10.0, -10.0);
  p.upper = Eigen::Vector2d(10.0, 10.0);
  p.difference_step = Eigen::Vector2d(1e-4, 1e-4);
  fitting::LeastSquaresSettings s;
  s.polish_iterations = 5;
  const auto r = fitting::fit_least_squares(p, s);

  Eigen::MatrixXd A(10, 2);
  A.col(0).setOnes();
  A.col(1) = times();
  const Eigen::Vector2d x = (A.transpose() * A).ldlt().solve(A.transpose() * data());
  const double s2 = (A * x - data()).squaredNorm() / 8.0;
  const Eigen::Matrix2d cov = s2 * (A.transpose() * A).inverse();
  CHECK(r.x(0) == Approx(x(0)).epsilon(1e-8));
  CHECK(r.x(1) == Approx(x(1)).epsilon(1e-8));
  CHECK(r.sigma(0) == Approx(std::sqrt(cov(0, 0))).epsilon(1e-6));
  CHECK(r.sigma(1) == Approx(std::sqrt(cov(1, 1))).epsilon(1e-6));
  CHECK(r.unit_covariance(1, 1) == Approx(cov(1, 1) / s2).epsilon(1e-6));
}

TEST_CASE("a parameter the residuals ignore gets an infinite sigma, the others keep theirs",
          "[fitting]") {
  fitting::LeastSquaresProblem p;
  // x(2) does not enter: the data cannot identify it
  p.residuals = [](const Eigen::VectorXd& x) -> Eigen::VectorXd {
    return (x(0) + x(1) * times().array()).matrix() - data();
  };
  p.start = Eigen::Vector3d(0.0, 0.0, 1.0);
  p.lower = Eigen::Vector3d(-10.0, -10.0, -10.0);
  p.upper = Eigen::Vector3d(10.0, 10.0, 10.0);
  p.difference_step = Eigen::Vector3d(1e-4, 1e-4, 1e-4);
  const auto r = fitting::fit_least_squares(p);
  CHECK(std::isinf(r.sigma(2)));
  CHECK(std::isfinite(r.sigma(0)));
  CHECK(std::isfinite(r.sigma(1)));
  CHECK(r.x(1) == Approx(0.5).margin(0.02));
}

TEST_CASE("a fit never takes more residual evaluations than most_evaluations says", "[fitting]") {
  // Rosenbrock's valley as residuals, BOBYQA stopped after its first interpolation set (2n+1) and
  // three Levenberg-Marquardt iterations from there: steps get rejected and retried with a larger
  // damping, which a bound of one trial a Jacobian would not cover.
  int counted = 0;
  fitting::LeastSquaresProblem p;
  p.residuals = [&counted](const Eigen::VectorXd& x) -> Eigen::VectorXd {
    ++counted;
    return Eigen::Vector2d(10.0 * (x(1) - x(0) * x(0)), 1.0 - x(0));
  };
  p.start = Eigen::Vector2d(-1.2, 1.0);
  p.lower = Eigen::Vector2d(-5.0, -5.0);
  p.upper = Eigen::Vector2d(5.0, 5.0);
  p.difference_step = Eigen::Vector2d(1e-6, 1e-6);
  fitting::LeastSquaresSettings s;
  s.max_evaluations = 5;
  s.polish_iterations = 3;
  const auto r = fitting::fit_least_squares(p, s);
  CHECK(r.evaluations == counted);
  CHECK(counted <= fitting::most_evaluations(s, 2));
  // the case exercises retries: more than one trial step per Jacobian somewhere
  CHECK(counted > s.max_evaluations + 1 + s.polish_iterations * (2 * 2 + 1) + 2 * 2 + 1);
}
