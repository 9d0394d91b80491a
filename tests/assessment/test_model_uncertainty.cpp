// Model uncertainty at the seed's objective points (issue 17; eqs. 4.3, 4.4, 4.15): facts of
// constructed curves whose points are known by hand, and the seed's own Appendix B numbers.
#include <catch2/catch.hpp>
#include <cmath>

#include "assessment/model_uncertainty.hpp"

using namespace iwb::assessment;

namespace {

// tau rises linearly to 60 kPa at u = 2 mm, falls linearly to 50 kPa at 4 mm and stays to 10 mm;
// the normal quantity grows as 0.1 u. Peak at 2 mm, before the last fifth (8-10 mm).
ResponseCurve peaked(double tau_scale = 1.0, double normal_scale = 1.0) {
  ResponseCurve c;
  for (int i = 0; i <= 1000; ++i) {
    const double u = 0.01 * i;
    const double t = u < 2.0 ? 30.0 * u : u < 4.0 ? 60.0 - 5.0 * (u - 2.0) : 50.0;
    c.u_x.push_back(u), c.tau.push_back(tau_scale * t), c.normal.push_back(normal_scale * 0.1 * u);
  }
  return c;
}

}  // namespace

TEST_CASE("a model equal to the reference has no model uncertainty", "[assessment]") {
  const auto r = model_uncertainty(peaked(), peaked(), 0.004);
  CHECK(r.peaked);
  REQUIRE(r.shear.size() == 4);
  CHECK(r.shear[0].name == "hardening");
  CHECK(r.shear[0].reference == Approx(30.0));  // halfway to the peak, u = 1 mm
  CHECK(r.shear[1].reference == Approx(60.0));  // the peak
  CHECK(r.shear[2].reference ==
        Approx(50.0));  // halfway from the peak (2 mm) to the last fifth (8 mm): the plateau
  CHECK(r.shear[3].reference == Approx(50.0));  // the last fifth's mean
  CHECK(r.shear_norm == 0.0);
  CHECK(r.normal_norm == 0.0);
}

TEST_CASE("a model 10 % off at every point: each UA is 0.1 / 1.645, their norm twice that",
          "[assessment]") {
  const auto r = model_uncertainty(peaked(), peaked(1.1, 0.8), 0.004);
  for (const auto& p : r.shear) CHECK(p.ua == Approx(0.1 / 1.645).epsilon(1e-9));
  CHECK(r.shear_norm == Approx(2.0 * 0.1 / 1.645).epsilon(1e-9));  // sqrt(4) points
  for (const auto& p : r.normal) CHECK(p.ua == Approx(0.2 / 1.645).epsilon(1e-9));
  CHECK(r.normal_norm == Approx(std::sqrt(2.0) * 0.2 / 1.645).epsilon(1e-9));
}

TEST_CASE("a reference that hardens to its end has hardening and residual points only",
          "[assessment]") {
  ResponseCurve c;
  for (int i = 0; i <= 100; ++i)
    c.u_x.push_back(0.1 * i), c.tau.push_back(10.0 * std::sqrt(0.1 * i)), c.normal.push_back(0.0);
  const auto r = model_uncertainty(c, c, 0.004);
  CHECK_FALSE(r.peaked);
  REQUIRE(r.shear.size() == 2);
  CHECK(r.shear[0].name == "hardening");
  CHECK(r.shear[0].u_x == Approx(5.0));
  CHECK(r.shear[1].name == "residual");
}

TEST_CASE(
    "a model that stops early counts as 0 beyond its end, a model that does not dilate misses by "
    "1/1.645",
    "[assessment]") {
  auto stopped = peaked();
  stopped.u_x.resize(300), stopped.tau.resize(300), stopped.normal.resize(300);  // to u = 2.99 mm
  const auto r = model_uncertainty(peaked(), stopped, 0.004);
  CHECK(r.shear[0].ua == 0.0);  // hardening at 1 mm and the peak are reached
  CHECK(r.shear[1].ua == 0.0);
  CHECK(r.shear[2].ua == Approx(1.0 / 1.645));
  CHECK(r.shear[3].ua == Approx(1.0 / 1.645));
  const auto flat = model_uncertainty(peaked(), peaked(1.0, 0.0), 0.004);
  CHECK(flat.normal_norm == Approx(std::sqrt(2.0) / 1.645));
}

TEST_CASE(
    "the normal points' denominator has a floor: a dilation near 0 does not make a miss infinite",
    "[assessment]") {
  const auto r = model_uncertainty(peaked(1.0, 1e-6), peaked(1.0, 0.0), 0.004);
  for (const auto& p : r.normal) CHECK(p.ua == Approx(std::abs(p.reference) / (1.645 * 0.004)));
}

TEST_CASE("the global uncertainty combines in quadrature: the seed's Appendix B (ERRATA 16)",
          "[assessment]") {
  // Shahrour & Rezaie dense, 100 kPa: MC's UA_model 0.672 and UA_par 0.23 give 0.710; HY's 0.285
  // and 0.19 give 0.343 (the seed's Table B.1). eq. 4.4 as printed, sqrt(0.672 + 0.23) = 0.950.
  CHECK(root_sum_square({0.672, 0.23}) == Approx(0.710).margin(0.0005));
  CHECK(root_sum_square({0.285, 0.19}) == Approx(0.343).margin(0.0005));
}
