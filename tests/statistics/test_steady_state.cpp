// The steady state of a DEM curve (statistics/steady_state.hpp) on curves whose answer is known by
// construction: an exponential decay from 0.65 to 0.45 over a decay length of 3 mm after a peak at
// 2 mm, with a fixed zig-zag of +-0.01 standing in for the grains' stick-slip. By hand: at the
// centre of the last fifth of 20 mm (18 mm) the decay has 0.2 exp(-16/3) = 0.00097 to go, 0.2 %
// of the window's mean: steady; of 10 mm (9 mm), 0.2 exp(-7/3) = 0.019, 4.1 %: not steady, and
// over 8 mm of decay (2.7 lengths) the end 0.45 is resolved. A straight fall has no end to
// extrapolate, and a flat curve is steady.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "statistics/steady_state.hpp"

using namespace iwb;

namespace {
struct Curve {
  std::vector<double> s, y;
};

// Rows every 0.02 mm to `end`: a rise to the peak at 2 mm, then f(s) after it.
template <class F>
Curve curve(double end, F f) {
  Curve c;
  for (int i = 0; i * 0.02 <= end + 1e-9; ++i) {
    const double s = i * 0.02, zigzag = (i % 2 == 0 ? 0.01 : -0.01);
    c.s.push_back(s);
    c.y.push_back((s < 2.0 ? 0.65 * s / 2.0 : f(s)) + zigzag);
  }
  return c;
}

double decay(double s) {
  return 0.45 + 0.2 * std::exp(-(s - 2.0) / 3.0);
}
}  // namespace

TEST_CASE("steady state: a decay seen for 18 mm is steady and its end is recovered",
          "[statistics]") {
  const auto c = curve(20.0, decay);
  const auto fit = statistics::fit_decay(c.s, c.y, 2.0);
  REQUIRE(fit);
  CHECK(fit->steady == Approx(0.45).margin(0.002));
  CHECK(fit->length == Approx(3.0).epsilon(0.05));
  const auto st = statistics::steady_state(c.s, c.y, 2.0, 16.0, 1.0);
  REQUIRE(st);
  CHECK(st->steady);
  CHECK(std::abs(st->remaining) == Approx(0.2 * std::exp(-16.0 / 3.0)).margin(2e-4));
  REQUIRE(st->extrapolated);
  CHECK(*st->extrapolated == Approx(0.45).margin(0.002));
}

TEST_CASE("steady state: the same decay stopped at 10 mm is not steady, its end extrapolated",
          "[statistics]") {
  const auto c = curve(10.0, decay);
  const auto st = statistics::steady_state(c.s, c.y, 2.0, 8.0, 0.5);
  REQUIRE(st);
  CHECK_FALSE(st->steady);
  CHECK(st->remaining == Approx(0.2 * std::exp(-7.0 / 3.0)).margin(0.002));
  REQUIRE(st->extrapolated);  // 8 mm of decay over a length of 3: resolved
  CHECK(*st->extrapolated == Approx(0.45).margin(0.005));
}

TEST_CASE("steady state: a straight fall has no end to extrapolate, and a flat curve is steady",
          "[statistics]") {
  const auto fall = curve(10.0, [](double s) { return 0.65 - 0.02 * (s - 2.0); });
  const auto st = statistics::steady_state(fall.s, fall.y, 2.0, 8.0, 0.5);
  REQUIRE(st);
  CHECK_FALSE(st->steady);  // a line is a decay of unbounded length: its end lies far below
  CHECK_FALSE(st->extrapolated);
  // a rise of 10 % over the last fifth after a settled decay: a trend, not a steady state
  const auto rise =
      curve(20.0, [](double s) { return decay(s) * (s > 16.0 ? 1.0 + 0.025 * (s - 16.0) : 1.0); });
  const auto up = statistics::steady_state(rise.s, rise.y, 2.0, 16.0, 1.0);
  REQUIRE(up);
  CHECK_FALSE(up->steady);
  CHECK(up->window_drift == Approx(0.1 * 0.45).epsilon(0.2));
  const auto flat = curve(10.0, [](double) { return 0.45; });
  const auto level = statistics::steady_state(flat.s, flat.y, 2.0, 8.0, 0.5);
  REQUIRE(level);
  CHECK(level->steady);
}
