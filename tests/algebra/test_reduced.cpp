// The reduced operators (seed 5.22-5.34) against the same operations on the embedded 3x3 tensor,
// over random and degenerate states; ERRATA items 1 and 2.
#include <catch2/catch.hpp>
#include <random>
#include <vector>

#include "algebra/reduced.hpp"
#include "algebra/tensor3.hpp"

using namespace iwb::algebra;
using Vec4 = reduced::Vec4<double>;
using Mat3 = tensor3::Mat3<double>;

namespace {

// Random states plus the degenerate sweep of STYLE.md on every component.
std::vector<Vec4> samples() {
  std::mt19937 rng(20261121);
  std::uniform_real_distribution<double> u(-500.0, 500.0);
  std::vector<Vec4> out;
  for (int i = 0; i < 500; ++i) out.emplace_back(u(rng), u(rng), u(rng), u(rng));
  const double sweep[] = {-10, -1, -1e-12, 0, 1e-12, 1, 10};
  for (double a : sweep)
    for (double b : sweep) out.emplace_back(a, b, b - a, a * b);
  return out;
}

double scale(const Vec4& x) {
  return 1.0 + x.cwiseAbs().maxCoeff();
}

}  // namespace

TEST_CASE("embedding is the symmetric tensor of CONVENTIONS.md", "[algebra]") {
  const Mat3 m = reduced::embed(Vec4(1, 2, 3, 4));
  Mat3 expected;
  expected << 1, 3, 4, 3, 2, 0, 4, 0, 2;
  CHECK(m == expected);
}

TEST_CASE("trace, ':', norm and det agree with the embedded 3x3 operations", "[algebra]") {
  const auto xs = samples();
  for (std::size_t i = 0; i + 1 < xs.size(); ++i) {
    const Vec4& x = xs[i];
    const Vec4& y = xs[i + 1];
    const Mat3 X = reduced::embed(x), Y = reduced::embed(y);
    const double s = scale(x) * scale(y);
    CHECK(reduced::trace(x) == Approx(X.trace()).margin(1e-12 * s));
    CHECK(reduced::double_contraction(x, y) ==
          Approx(tensor3::double_contraction(X, Y)).margin(1e-12 * s));
    CHECK(reduced::norm(x) == Approx(tensor3::norm(X)).margin(1e-12 * scale(x)));
    CHECK(reduced::determinant(x) == Approx(X.determinant()).margin(1e-12 * std::pow(scale(x), 3)));
  }
}

TEST_CASE("unit tensors: 1 embeds to the identity, I : X = X, 1 : X = tr X", "[algebra]") {
  CHECK(reduced::embed(reduced::unit<double>()) == Mat3::Identity());
  for (const auto& x : samples()) {
    const Vec4 ix = reduced::double_contraction(reduced::unit4<double>(), x);
    CHECK((ix - x).cwiseAbs().maxCoeff() <= 1e-13 * scale(x));
    CHECK(reduced::double_contraction(reduced::unit<double>(), x) ==
          Approx(reduced::trace(x)).margin(1e-12 * scale(x)));
  }
}

TEST_CASE("outer product: (X (x) Y) : Z = X (Y : Z), as for 3x3 tensors", "[algebra]") {
  const auto xs = samples();
  for (std::size_t i = 0; i + 2 < xs.size(); i += 3) {
    const Vec4 &x = xs[i], &y = xs[i + 1], &z = xs[i + 2];
    const Vec4 lhs = reduced::double_contraction(reduced::outer_product(x, y), z);
    const Mat3 expected =
        reduced::embed(x) * tensor3::double_contraction(reduced::embed(y), reduced::embed(z));
    const double s = scale(x) * scale(y) * scale(z);
    CHECK((reduced::embed(lhs) - expected).cwiseAbs().maxCoeff() <= 1e-12 * s);
  }
}

TEST_CASE("deviators embed to the 3x3 deviators (eqs. 5.28-5.30, ERRATA item 1)", "[algebra]") {
  for (const auto& x : samples()) {
    const Mat3 X = reduced::embed(x);
    CHECK((reduced::embed(reduced::deviator(x)) - tensor3::deviator(X)).cwiseAbs().maxCoeff() <=
          1e-12 * scale(x));
    const double tr = X.trace();
    if (std::abs(tr) < 1e-3 * scale(x)) continue;  // X^ is undefined at tr X = 0
    const Mat3 hat_dev = X / tr - Mat3::Identity() / 3.0;
    const Mat3 got = reduced::embed(reduced::normalized_deviator(x));
    CHECK((got - hat_dev).cwiseAbs().maxCoeff() <= 1e-12 * scale(x) / std::abs(tr) + 1e-14);
    CHECK(reduced::normalized_deviator(x)(3) == Approx(x(3) / tr));  // the fourth component
  }
}

TEST_CASE("inner product keeps four entries of the 3x3 product and loses the rest (ERRATA 2)",
          "[algebra]") {
  const auto xs = samples();
  for (std::size_t i = 0; i + 1 < xs.size(); ++i) {
    const Vec4 &x = xs[i], &y = xs[i + 1];
    const Vec4 p = reduced::inner_product(x, y);
    const Mat3 P = reduced::embed(x) * reduced::embed(y);
    const double s = scale(x) * scale(y) * 1e-12;
    CHECK(p(0) == Approx(P(0, 0)).margin(s));
    CHECK(p(1) == Approx(P(1, 1)).margin(s));
    CHECK(p(2) == Approx(P(0, 1)).margin(s));
    CHECK(p(3) == Approx(P(2, 0)).margin(s));
    // What the embedding cannot hold: (3,3) differs from (2,2), and a (2,3) entry appears.
    CHECK(P(2, 2) - P(1, 1) == Approx(x(3) * y(3) - x(2) * y(2)).margin(s));
    CHECK(P(1, 2) == Approx(x(2) * y(3)).margin(s));
  }
}

TEST_CASE("tr(X.X.X): reduced minus exact is tr X (X3^2 - X4^2), equal for deviators (ERRATA 2)",
          "[algebra]") {
  for (const auto& x : samples()) {
    const double reduced_value = reduced::trace_of_cube(x);
    const double exact = tensor3::trace_of_cube(reduced::embed(x));
    const double s = 1e-12 * std::pow(scale(x), 3);
    CHECK(reduced_value - exact ==
          Approx(reduced::trace(x) * (x(2) * x(2) - x(3) * x(3))).margin(s));
    const Vec4 d = reduced::deviator(x);
    CHECK(reduced::trace_of_cube(d) == Approx(tensor3::trace_of_cube(reduced::embed(d))).margin(s));
  }
  // Not an identity that holds trivially: a non-deviatoric state with tau_x != tau_y differs.
  const Vec4 x(-100, -50, 30, 0);
  CHECK(std::abs(reduced::trace_of_cube(x) - tensor3::trace_of_cube(reduced::embed(x))) > 1e4);
}
