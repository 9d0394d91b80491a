// Total Sobol indices (src/assessment/sobol.hpp) on functions whose indices are known in closed
// form: the Ishigami function (Ishigami & Homma 1990; its total indices 0.5576, 0.4424, 0.2437 for
// a = 7, b = 0.1 are the standard check, Saltelli et al. 2010) and an additive linear function,
// whose total index of x_i is a_i^2 Var x_i / sum_j a_j^2 Var x_j.
#include <catch2/catch.hpp>
#include <cmath>

#include "assessment/sobol.hpp"

using namespace iwb::assessment;

TEST_CASE("Jansen's total indices of the Ishigami function converge to their closed form",
          "[assessment]") {
  // x_i uniform on [-pi, pi]: mean 0 is not a COV's base, so shift by 10 pi and subtract it back
  const double shift = 10.0 * M_PI, cov = M_PI / std::sqrt(3.0) / shift;
  std::vector<Distribution> p;
  for (const char* name : {"x1", "x2", "x3"})
    p.push_back({name, Distribution::Kind::kUniform, shift, cov});
  const auto ishigami = [&](const std::vector<double>& x) {
    const double a = x[0] - shift, b = x[1] - shift, c = x[2] - shift;
    return std::vector<double>{std::sin(a) + 7.0 * std::sin(b) * std::sin(b) +
                               0.1 * std::pow(c, 4) * std::sin(a)};
  };
  const double expected[] = {0.5576, 0.4424, 0.2437};
  const auto r = total_sobol_indices(p, {"y"}, ishigami, 20000, 11);
  for (int i = 0; i < 3; ++i) {
    INFO("x" << i + 1 << ": " << r.total[0][i].value << " [" << r.total[0][i].low << ", "
             << r.total[0][i].high << "]");
    CHECK(r.total[0][i].value == Approx(expected[i]).margin(0.02));
    CHECK(r.total[0][i].low <= expected[i] + 0.01);
    CHECK(r.total[0][i].high >= expected[i] - 0.01);
  }
  CHECK(r.evaluations == 20000L * 5);
  // convergence: a tenth of the samples, an interval sqrt(10) = 3.2 times wider
  const auto coarse = total_sobol_indices(p, {"y"}, ishigami, 2000, 11);
  for (int i = 0; i < 3; ++i)  // the bootstrap interval narrows about as 1/sqrt(N)
    CHECK(coarse.total[0][i].high - coarse.total[0][i].low >
          2.0 * (r.total[0][i].high - r.total[0][i].low));
}

TEST_CASE(
    "an additive function's total indices are its variance shares, a parameter it ignores gets 0",
    "[assessment]") {
  std::vector<Distribution> p{{"a", Distribution::Kind::kNormal, 10.0, 0.1},
                              {"b", Distribution::Kind::kLognormal, 5.0, 0.2},
                              {"c", Distribution::Kind::kNormal, 3.0, 0.3}};
  const auto f = [](const std::vector<double>& x) {
    return std::vector<double>{2.0 * x[0] + 1.0 * x[1]};
  };
  const double va = 4.0 * 1.0, vb = 1.0 * 1.0;  // (2 * 0.1 * 10)^2 and (0.2 * 5)^2
  const auto r = total_sobol_indices(p, {"y"}, f, 20000, 3);
  CHECK(r.total[0][0].value == Approx(va / (va + vb)).margin(0.02));
  CHECK(r.total[0][1].value == Approx(vb / (va + vb)).margin(0.02));
  CHECK(r.total[0][2].value == 0.0);
}

TEST_CASE("rows whose run fails are dropped and counted", "[assessment]") {
  std::vector<Distribution> p{{"a", Distribution::Kind::kNormal, 1.0, 0.5}};
  const auto f = [](const std::vector<double>& x) {
    return std::vector<double>{x[0] < 0.0 ? NAN : x[0]};
  };
  const auto r = total_sobol_indices(p, {"y"}, f, 1000, 5);
  CHECK(r.failed > 0);
  CHECK(r.total[0][0].value == Approx(1.0).margin(0.1));  // one parameter carries all the variance
}
