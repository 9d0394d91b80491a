// Levene's test about the median and the pooled SD (issue 36) against an implementation built
// outside the workbench: the p-values are SciPy 1.10's `scipy.stats.levene(*groups,
// center='median')` on the same numbers (Debian bookworm's python3-scipy, run once by hand), the
// pooled SD its formula by hand.
#include <catch2/catch.hpp>
#include <cmath>
#include <stdexcept>

#include "statistics/equal_scatter.hpp"

using namespace iwb;

TEST_CASE("Brown-Forsythe's W and p equal SciPy's levene(center='median')", "[statistics]") {
  const std::vector<std::vector<double>> g = {
      {1.00, 1.05, 0.93}, {0.50, 0.56, 0.47, 0.52}, {2.1, 1.8, 2.4}, {0.98, 1.02, 1.01}};
  const auto t = statistics::brown_forsythe(g);
  CHECK(t.statistic == Approx(3.270132406125152).epsilon(1e-12));
  CHECK(t.p_value == Approx(0.07302871459756649).epsilon(1e-9));
  CHECK(t.groups == 4);
  CHECK(t.values == 13);
  const auto u = statistics::brown_forsythe({{1, 2, 3}, {10, 20, 30}, {5, 5.1, 5.2}});
  CHECK(u.statistic == Approx(3.5604395604395602).epsilon(1e-12));
  CHECK(u.p_value == Approx(0.0956235687160329).epsilon(1e-9));
  // the same groups relative to their means (how the verdicts pool: tolerances are relative)
  std::vector<std::vector<double>> rel;
  for (const auto& x : g) {
    double m = 0.0;
    for (const double v : x) m += v / double(x.size());
    std::vector<double> r;
    for (const double v : x) r.push_back(v / m);
    rel.push_back(r);
  }
  const auto tr = statistics::brown_forsythe(rel);
  CHECK(tr.statistic == Approx(1.4626645628623849).epsilon(1e-12));
  CHECK(tr.p_value == Approx(0.2888619222138269).epsilon(1e-9));
  const auto p = statistics::pooled_sd(rel);
  CHECK(p.degrees_of_freedom == 9);
  CHECK(p.sd == Approx(0.08519115987299912).epsilon(1e-12));
}

TEST_CASE("equal-scatter statistics refuse groups too small to have a scatter", "[statistics]") {
  CHECK_THROWS_AS(statistics::brown_forsythe({{1.0, 2.0, 3.0}}), std::invalid_argument);
  CHECK_THROWS_AS(statistics::brown_forsythe({{1.0, 2.0}, {1.0}}), std::invalid_argument);
  CHECK_THROWS_AS(statistics::pooled_sd({{1.0}}), std::invalid_argument);
  // no spread within any group: nothing to test, p = 1
  CHECK(statistics::brown_forsythe({{1.0, 1.0}, {2.0, 2.0}}).p_value == 1.0);
}
