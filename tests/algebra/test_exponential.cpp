// exp over the algebra policies (src/algebra/exponential.hpp): the 3x3 series against the
// exponential from the eigen-decomposition, exp(a 1) = e^a 1, exp(X) exp(-X) = 1, and the reduced
// series against the 2x2 block of the embedding when one shear component is zero.
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "algebra/exponential.hpp"
#include "algebra/ops.hpp"

using namespace iwb::algebra;
using Mat3 = tensor3::Mat3<double>;
using Vec4 = reduced::Vec4<double>;

namespace {

Mat3 spectral_exponential(const Mat3& x) {
  Eigen::SelfAdjointEigenSolver<Mat3> es(x);
  return es.eigenvectors() * es.eigenvalues().array().exp().matrix().asDiagonal() *
         es.eigenvectors().transpose();
}

Mat3 random_symmetric(std::mt19937& rng, double size) {
  std::uniform_real_distribution<double> u(-size, size);
  Mat3 a;
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j) a(i, j) = a(j, i) = u(rng);
  return a;
}

}  // namespace

TEST_CASE(
    "exponential: 3x3 series equals the spectral exponential, exp(a 1) = e^a 1, exp(X) exp(-X) = 1",
    "[algebra]") {
  std::mt19937 rng(8152);
  for (double size : {1e-3, 0.5, 3.0, 12.0}) {
    for (int i = 0; i < 50; ++i) {
      const Mat3 x = random_symmetric(rng, size);
      const Mat3 e = exponential<Tensor3Ops, double>(x);
      // the series' round-off: eps times its largest term, e^||dev x|| e^(tr x / 3)
      const Mat3 dev = x - x.trace() / 3.0 * Mat3::Identity();
      const double roundoff = 1e-14 * std::exp(dev.norm() + x.trace() / 3.0);
      CHECK((e - spectral_exponential(x)).norm() <= std::max(1e-14 * e.norm(), roundoff));
      CHECK((e * exponential<Tensor3Ops, double>(Mat3(-x)) - Mat3::Identity()).norm() <=
            1e-14 * std::exp(2.0 * dev.norm()));
    }
  }
  CHECK((exponential<Tensor3Ops, double>(Mat3(-0.7 * Mat3::Identity())) -
         std::exp(-0.7) * Mat3::Identity())
            .norm() < 1e-15);
}

TEST_CASE(
    "exponential: the reduced series with one shear component is the embedding's 2x2 block "
    "exponential",
    "[algebra]") {
  std::mt19937 rng(8153);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  for (int i = 0; i < 100; ++i) {
    const Vec4 x(u(rng), u(rng), u(rng), 0.0);
    const Vec4 r = exponential<ReducedOps, double>(x);
    Mat3 block = reduced::embed(x);
    block(2, 2) = 0.0;  // the 2x2 block alone
    const Mat3 e = spectral_exponential(block);
    CHECK(r(0) == Approx(e(0, 0)).epsilon(1e-13));
    CHECK(r(1) == Approx(e(1, 1)).epsilon(1e-13));
    CHECK(r(2) == Approx(e(0, 1)).epsilon(1e-13).margin(1e-15));
    CHECK(r(3) == 0.0);
  }
}
