// Clough & Duncan's hyperbolic interface model (src/models/hyperbolic, seed 3.3.2): the facts the
// paper builds it on, each from the closed forms, not from the code: under CNL tau follows the
// hyperbola u / (1/K_si + R_f u / tau_f) (eq. 3.51) up to tau_f = sigma_n tan(delta) and stays
// there; the response in displacement does not depend on d_s; unloading and reloading below the
// largest stress level are elastic with K_ur; the normal stress is uncoupled (no dilatancy).
#include <catch2/catch.hpp>
#include <cmath>

#include "models/registry.hpp"
#include "support/fixtures.hpp"

using namespace iwb;
using driver::BoundaryKind;

namespace {

constexpr double kKI = 37500, kKur = 56250, kN = 0.35, kRf = 0.875, kDelta = 32, kPa = 101.325,
                 kGw = 9.81;  // Table 4.4
const double kTauF = 100.0 * std::tan(kDelta * M_PI / 180.0);
const double kKsi = kKI * kGw * std::pow(100.0 / kPa, kN) * 1e-3;  // kPa/mm at 100 kPa (eq. 3.49)

double hyperbola(double u_mm) {
  return std::min(kTauF, u_mm / (1.0 / kKsi + kRf * u_mm / kTauF));
}

models::ModelInputs inputs(double d_s_mm) {
  auto in = test::shipped("table_4_4_hyperbolic.toml");
  in.shear_zone_mm = d_s_mm;
  return in;
}

test::Run shear(driver::BoundaryCondition bc, double d_s_mm, double gamma) {
  test::ShearSpec s;
  s.model = "hyperbolic";
  s.inputs = inputs(d_s_mm);
  s.bc = bc;
  s.gamma = gamma;
  s.increments = 400;
  auto r = test::shear(s);
  REQUIRE(r.result.complete());
  return r;
}

}  // namespace

TEST_CASE("hyperbolic under CNL follows eq. 3.51 to tau_f and stays there, whatever d_s",
          "[models]") {
  for (double d_s : {1.0, 2.5}) {
    const auto r =
        shear({BoundaryKind::kCNL, 0.0}, d_s, 2.0 / d_s);  // 2 mm of displacement either way
    INFO("d_s = " << d_s << " mm");
    for (const auto& row : r.result.rows) {
      const double u = row.gamma_x * d_s;
      CHECK(r.model->stress(row.state).tau_x == Approx(hyperbola(u)).epsilon(2e-5));
      CHECK(row.eps_n == 0.0);  // no dilatancy: nothing moves the normal strain under CNL
    }
    CHECK(r.model->stress(r.result.rows.back().state).tau_x == Approx(kTauF).epsilon(1e-4));
  }
}

TEST_CASE("hyperbolic under CV keeps sigma_n: the normal stress is uncoupled (eq. 3.53)",
          "[models]") {
  const auto r = shear({BoundaryKind::kCV, 0.0}, 1.0, 1.0);
  for (const auto& row : r.result.rows)
    CHECK(r.model->stress(row.state).sigma_n == Approx(100.0).epsilon(1e-12));
}

TEST_CASE("hyperbolic unloads and reloads with K_ur below the largest stress level, with K_s at it",
          "[models]") {
  const auto m = models::find_model("hyperbolic").make(inputs(1.0));
  const double k_ur = kKur * kGw * std::pow(100.0 / kPa, kN) * 1e-3;  // kPa/mm
  models::StateVector s(4), ds(4);
  const double tau = 40.0;
  s << -100.0, tau, 0.0, tau / kTauF;  // on the loading branch at its largest level
  m->rate(s, {0.0, -1.0, 0.0}, ds);    // unloading (per unit strain = per mm at d_s 1 mm)
  CHECK(ds(1) == Approx(-k_ur).epsilon(1e-12));
  CHECK(ds(3) == 0.0);
  m->rate(s, {0.0, 1.0, 0.0}, ds);  // loading on: eq. 3.52
  CHECK(ds(1) == Approx(kKsi * std::pow(1.0 - kRf * tau / kTauF, 2)).epsilon(1e-12));
  s(3) = 0.9;  // the level reached before was higher: reloading is elastic
  m->rate(s, {0.0, 1.0, 0.0}, ds);
  CHECK(ds(1) == Approx(k_ur).epsilon(1e-12));
  // degree one in the stretching, on each branch
  models::StateVector twice(4);
  m->rate(s, {0.0, 2.0, 0.0}, twice);
  CHECK(twice(1) == Approx(2.0 * ds(1)).epsilon(1e-14));
}
