// Welch's test, the prediction interval of one run and Benjamini-Hochberg, against an independent
// implementation: the expected figures were computed with SciPy 1.10 (scipy.stats.ttest_ind with
// equal_var=False, scipy.stats.t) and Benjamini & Hochberg's step-up rule written out by hand in
// numpy, outside this repository's code.
#include <catch2/catch.hpp>

#include "statistics/group_tests.hpp"

using namespace iwb;

TEST_CASE("Welch's test of two groups of seeds matches SciPy", "[statistics]") {
  const auto a = statistics::describe({0.418, 0.392, 0.447});
  const auto b = statistics::describe({0.343, 0.301, 0.385, 0.37});
  const auto d = statistics::compare_groups(a, b);
  REQUIRE(d);
  CHECK_FALSE(d->prediction_interval);
  CHECK(d->effect == Approx(-0.06925).margin(1e-12));
  CHECK(d->degrees_of_freedom == Approx(4.985616216165435).epsilon(1e-9));
  CHECK(d->p_value == Approx(0.03609332062368329).epsilon(1e-6));
  CHECK(d->half_width == Approx(0.06259376081893905).epsilon(1e-6));
}

TEST_CASE("one run against a group's 95 % prediction interval matches SciPy's t", "[statistics]") {
  const auto a = statistics::describe({1.6, 1.7, 1.5, 1.8, 1.65});
  const auto d = statistics::compare_groups(a, statistics::describe({2.43}));
  REQUIRE(d);
  CHECK(d->prediction_interval);
  CHECK(d->degrees_of_freedom == 4.0);
  CHECK(d->p_value == Approx(0.0031170422689728566).epsilon(1e-6));
  CHECK(d->half_width == Approx(0.34004369032912846).epsilon(1e-6));
  // one value against one value: nothing to test
  CHECK_FALSE(statistics::compare_groups(statistics::describe({1.0}), statistics::describe({2.0})));
}

TEST_CASE("Benjamini-Hochberg adjusts five p-values as the step-up rule does", "[statistics]") {
  // the five cells: only p 0.009 survives at q 0.05 once the family is counted
  const auto adjusted = statistics::benjamini_hochberg({0.009, 0.035, 0.17, 0.10, 0.08});
  REQUIRE(adjusted.size() == 5);
  CHECK(adjusted[0] == Approx(0.045));
  CHECK(adjusted[1] == Approx(0.0875));
  CHECK(adjusted[2] == Approx(0.17));
  CHECK(adjusted[3] == Approx(0.125));
  CHECK(adjusted[4] == Approx(0.125));
}

// Equal SDs 0.03 and an effect 0.04: Welch's t = 0.04 / (0.03 sqrt(2 / n)) on 2n - 2 degrees of
// freedom; SciPy's stats.t.sf gives p 0.0681 at n = 5 and 0.0436 at n = 6, 0.00236 at n = 13 and
// 0.00158 at n = 14.
TEST_CASE("the seeds a difference needs are the fewest at which its p falls to the level asked",
          "[statistics]") {
  const statistics::Sample a{3, 0.40, 0.03}, b{3, 0.36, 0.03};
  CHECK(statistics::seeds_to_resolve(a, b, -0.04, 0.05) == 6);
  // one claim of 24 at false-discovery rate 0.05: q / m
  CHECK(statistics::seeds_to_resolve(a, b, -0.04, 0.05 / 24) == 14);
  CHECK_FALSE(statistics::seeds_to_resolve(a, b, -0.04, 0.05 / 24, 13));
}

// Two one-sided tests, computed outside this code as SciPy 1.10's one-sided Welch tests of b
// shifted by the margin: max(ttest_ind(b + m, a, equal_var=False, alternative='greater'),
// ttest_ind(b - m, a, equal_var=False, alternative='less')).
TEST_CASE("equality within a margin is two one-sided Welch tests, as SciPy gives them",
          "[statistics]") {
  const auto a = statistics::describe({0.418, 0.392, 0.447});
  const auto b = statistics::describe({0.40, 0.43, 0.41, 0.425});
  const auto d = statistics::compare_groups(a, b);
  REQUIRE(d);
  CHECK(statistics::equivalence_p_value(*d, 0.05) == Approx(0.039508528666246163).epsilon(1e-6));
  // a margin narrower than the scatter shows nothing
  CHECK(statistics::equivalence_p_value(*d, 0.02) == Approx(0.1991520497277264).epsilon(1e-6));
  // SciPy's ttest_ind_from_stats at the same means and SDs: 6 seeds a group reach p <= 0.005
  CHECK(statistics::seeds_to_show_equal(a, b, d->effect, 0.05, 0.005) == 6);
  // an effect outside the margin is never shown equal, however many seeds
  CHECK_FALSE(statistics::seeds_to_show_equal(a, b, 0.06, 0.05, 0.005));
}
