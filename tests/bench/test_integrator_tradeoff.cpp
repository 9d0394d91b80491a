// The integrator trade-off measured by `iwb bench integrators`, as numeric facts on rate
// evaluations and errors (never on times): Euler is first order, the adaptive pairs get more
// accurate as the tolerance tightens and pay for it in evaluations.
#include <catch2/catch.hpp>

#include "bench/integrator_bench.hpp"
#include "support/fixtures.hpp"

using namespace iwb;

namespace {
// A short path keeps the test in the default suite; 20 increments of 1e-3 reach the peak region.
bench::TradeoffPath short_path() {
  bench::TradeoffPath tp;
  tp.gamma = 0.02;
  tp.increments = 20;
  return tp;
}

std::vector<bench::TradeoffSetting> only(const std::string& scheme, int max_substeps,
                                         double min_rtol) {
  std::vector<bench::TradeoffSetting> out;
  for (const auto& s : bench::tradeoff_settings(max_substeps, min_rtol))
    if (s.scheme == scheme) out.push_back(s);
  return out;
}
}  // namespace

TEST_CASE("integrators: explicit Euler error halves when the substeps double (first order)") {
  for (auto bc : {driver::BoundaryKind::kCNL, driver::BoundaryKind::kCV}) {
    const auto pts = bench::run_tradeoff(models::find_model("hvwe"), test::table_5_3_toyoura(), bc,
                                         short_path(), only("euler", 64, 1e-2));
    REQUIRE(pts.size() == 7);                           // n = 1 ... 64
    for (std::size_t i = 2; i + 1 < pts.size(); ++i) {  // from n = 4: the asymptotic range
      INFO(driver::to_string(bc) << " n = " << pts[i].parameter << ": " << pts[i].error << " -> "
                                 << pts[i + 1].error);
      CHECK(pts[i].error / pts[i + 1].error == Approx(2.0).margin(0.25));
      CHECK(pts[i + 1].rate_evaluations > pts[i].rate_evaluations);
    }
  }
}

TEST_CASE("integrators: the adaptive error falls as the tolerance tightens, at more evaluations") {
  // Increments of 5e-3: with 1e-3 one rk54 step per increment already meets every tolerance down
  // to 1e-6 and the error cannot fall (measured: 1.1e-8 flat), which says nothing about control.
  bench::TradeoffPath coarse = short_path();
  coarse.increments = 4;
  for (const std::string pair : {"rk32", "rk54"}) {
    const auto pts = bench::run_tradeoff(models::find_model("hvwe"), test::table_5_3_toyoura(),
                                         driver::BoundaryKind::kCNS, coarse, only(pair, 1, 1e-7));
    REQUIRE(pts.size() == 6);  // rtol 1e-2 ... 1e-7
    for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
      INFO(pair << " rtol " << pts[i].parameter << ": " << pts[i].error << ", "
                << pts[i].rate_evaluations);
      CHECK(pts[i + 1].error <= pts[i].error);
      CHECK(pts[i + 1].rate_evaluations >= pts[i].rate_evaluations);
    }
    CHECK(pts.back().error < pts.front().error / 100.0);
    CHECK(pts.back().error < 1e-6);
  }
}
