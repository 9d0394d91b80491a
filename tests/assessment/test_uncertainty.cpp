// Parameter uncertainty by Latin hypercube (src/assessment/uncertainty.hpp): facts of the sampling
// itself, independent of any model: one sample per stratum of each parameter, the marginals' mean
// and COV recovered, and a quantity that is a parameter has that parameter's COV.
#include <catch2/catch.hpp>
#include <cmath>

#include "assessment/uncertainty.hpp"

using namespace iwb::assessment;

TEST_CASE("a Latin hypercube puts one sample in each of the N equally probable strata",
          "[assessment]") {
  const std::vector<Distribution> p{{"a", Distribution::Kind::kNormal, 10.0, 0.2},
                                    {"b", Distribution::Kind::kLognormal, 4.0, 0.3}};
  const int n = 500;
  const auto x = latin_hypercube(p, n, 1);
  for (std::size_t j = 0; j < p.size(); ++j) {
    std::vector<int> hits(n, 0);
    for (const auto& row : x) {
      // the stratum of a sample: its probability times N (the CDF inverted by bisection on
      // quantile)
      double lo = 0.0, hi = 1.0;
      for (int k = 0; k < 60; ++k)
        (p[j].quantile(0.5 * (lo + hi)) < row[j] ? lo : hi) = 0.5 * (lo + hi);
      ++hits[std::min(n - 1, int(lo * n))];
    }
    for (int h : hits) CHECK(h == 1);
  }
}

TEST_CASE("the CV of a quantity that is one parameter is that parameter's COV, lognormal or normal",
          "[assessment]") {
  const std::vector<Distribution> p{{"phi", Distribution::Kind::kLognormal, 33.5, 0.3},
                                    {"nu", Distribution::Kind::kNormal, 0.35, 0.1}};
  const auto r = parameter_uncertainty(
      p, {"phi", "nu"}, [](const std::vector<double>& x) { return x; }, 10000, 3);
  CHECK(r.quantities[0].mean == Approx(33.5).epsilon(2e-3));
  CHECK(r.quantities[0].cv == Approx(0.3).epsilon(1e-2));
  CHECK(r.quantities[1].cv == Approx(0.1).epsilon(1e-2));
  CHECK(r.failed == 0);
}
