// The rate of a curve over a stated span (statistics/local_rate.hpp), on curves whose answer is
// known by hand:
//   - a parabola y = -c (s - 5)^2, c = 0.1: each block's least-squares slope over rows placed
//     symmetrically in it is the derivative at the block's centre, -2c (x_k - 5); over [1, 5] in
//     8 blocks of 0.5 (centres 1.25 ... 4.75) their mean is the derivative at 3, 0.4, and their SD
//     is 2c sqrt(sum (x_k - 3)^2 / 7) = 0.2 sqrt(10.5 / 7) = 0.24495, so the 95 % half-width is
//     t_{0.975,7} 0.24495 / sqrt 8 = 2.3646 x 0.086603 = 0.20478;
//   - a line of slope 0.3 with noise of +-0.02 drawn from a fixed generator: the interval covers
//     0.3, while the largest slope over sliding windows (the rule this replaced) lies above it.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <vector>

#include "statistics/local_rate.hpp"

using namespace iwb;

namespace {
struct Rows {
  std::vector<double> s, y;
};

// Rows every 0.01 from 0 to 10, each the centre of its own 0.01 cell: a block of 0.5 holds 50 rows
// placed symmetrically about its centre.
template <class F>
Rows rows(F f) {
  Rows r;
  for (int i = 0; i < 1000; ++i) r.s.push_back(0.005 + 0.01 * i), r.y.push_back(f(r.s.back()));
  return r;
}
}  // namespace

TEST_CASE(
    "local rate: a parabola's rate is its derivative at the centre, its interval the blocks' "
    "spread",
    "[statistics]") {
  const auto r = rows([](double s) { return -0.1 * (s - 5.0) * (s - 5.0); });
  const auto rate = statistics::local_rate(r.s, r.y, 3.0, 2.0, 0.5);
  REQUIRE(rate);
  CHECK(rate->blocks == 8);
  CHECK(rate->from == Approx(1.0));
  CHECK(rate->to == Approx(5.0));
  CHECK(rate->rate == Approx(0.4).epsilon(1e-6));
  CHECK(rate->half_width == Approx(0.20478).epsilon(1e-3));
}

TEST_CASE("local rate: a span that meets the rows' start keeps its length", "[statistics]") {
  const auto r = rows([](double s) { return 0.25 * s; });
  const auto rate = statistics::local_rate(r.s, r.y, 0.5, 2.0, 0.5);
  REQUIRE(rate);
  CHECK(rate->from == Approx(0.005));
  CHECK(rate->to == Approx(4.005));
  CHECK(rate->rate == Approx(0.25).epsilon(1e-9));
  CHECK(rate->half_width == Approx(0.0).margin(1e-9));
  CHECK_FALSE(statistics::local_rate(r.s, r.y, 5.0, 0.5, 0.5));  // 2 blocks: no interval
}

TEST_CASE("local rate: on a noisy line the interval covers the slope, the largest window does not",
          "[statistics]") {
  std::mt19937 generator(7);  // the standard fixes mt19937's sequence
  const auto r =
      rows([&](double s) { return 0.3 * s + 0.04 * (double(generator()) / 4294967295.0 - 0.5); });
  const auto rate = statistics::local_rate(r.s, r.y, 5.0, 2.0, 0.5);
  REQUIRE(rate);
  CHECK(std::abs(rate->rate - 0.3) <= rate->half_width);
  CHECK(rate->half_width < 0.02);
  // the replaced rule: the largest least-squares slope over 0.2-wide windows (20 rows) anywhere
  double largest = -INFINITY;
  for (std::size_t i = 0; i + 20 <= r.s.size(); ++i) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (std::size_t j = i; j < i + 20; ++j)
      sx += r.s[j], sy += r.y[j], sxx += r.s[j] * r.s[j], sxy += r.s[j] * r.y[j];
    largest = std::max(largest, (20 * sxy - sx * sy) / (20 * sxx - sx * sx));
  }
  CHECK(largest > rate->rate + rate->half_width);
}
