// Student's t quantiles and intervals against the printed tables (e.g. NIST/SEMATECH e-Handbook
// of Statistical Methods, 1.3.6.7.2, "Critical values of the Student's t distribution").
#include <catch2/catch.hpp>
#include <cmath>

#include "statistics/t_interval.hpp"

using namespace iwb;

TEST_CASE("two-sided 95 % t quantiles are the tables' values", "[statistics]") {
  CHECK(statistics::t_quantile(1) == Approx(12.706).margin(5e-4));
  CHECK(statistics::t_quantile(2) == Approx(4.303).margin(5e-4));
  CHECK(statistics::t_quantile(4) == Approx(2.776).margin(5e-4));
  CHECK(statistics::t_quantile(10) == Approx(2.228).margin(5e-4));
  CHECK(statistics::t_quantile(100000) == Approx(1.960).margin(5e-4));  // the normal's
  CHECK(statistics::t_quantile(9, 0.90) == Approx(1.833).margin(5e-4));
}

TEST_CASE("a t-interval of a mean, and the values a half-width needs", "[statistics]") {
  CHECK_FALSE(statistics::t_half_width(1.0, 1).has_value());  // one run has no interval
  CHECK(*statistics::t_half_width(0.008, 3) ==
        Approx(4.303 * 0.008 / std::sqrt(3.0)).epsilon(1e-3));
  // t_{n-1} / sqrt(n) for n = 6, 7: 2.571 / 2.449 = 1.050, 2.447 / 2.646 = 0.925
  CHECK(statistics::values_needed(1.0, 1.0) == 7);
  CHECK(statistics::values_needed(1.0, 1.06) == 6);
  CHECK(statistics::values_needed(1.0, 9.0) == 2);               // 12.706 / sqrt(2) = 8.98
  CHECK_FALSE(statistics::values_needed(0.0, 1.0).has_value());  // no scatter: nothing to resolve
  CHECK_FALSE(statistics::values_needed(1.0, 0.01, 100).has_value());  // beyond 100 values
}
