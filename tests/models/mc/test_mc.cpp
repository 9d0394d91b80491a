// The Mohr-Coulomb interface model (src/models/mc, seed 3.3.1): facts of elastic-perfectly
// plastic Coulomb friction with a non-associated flow rule, each derived by hand from eqs.
// 3.36-3.41 (compression positive, README.md), not from the code: the elastic slope G, the
// strength sigma_n tan(phi_i) + c, the dilation rate tan(psi) under CNL, the stress path on the
// yield line under CV and CNS, the yield condition to round-off after every increment, the
// consistent tangent against central differences.
#include <catch2/catch.hpp>
#include <cmath>

#include "models/registry.hpp"
#include "support/fixtures.hpp"
#include "support/increment_derivative.hpp"

using namespace iwb;
using driver::BoundaryKind;

namespace {

constexpr double kE = 60000.0, kNu = 0.33, kPhi = 35.0, kPsi = 5.0, kC = 1.0;  // Table 4.3
const double kG = kE / (2.0 * (1.0 + kNu));
const double kEoed = 2.0 * kG * (1.0 - kNu) / (1.0 - 2.0 * kNu);
const double kTanPhi = std::tan(kPhi * M_PI / 180.0), kTanPsi = std::tan(kPsi * M_PI / 180.0);

models::ModelInputs inputs(double psi = kPsi, double cutoff = 0.0) {
  return {{{"mohr_coulomb",
            {{"E_kPa", kE},
             {"nu", kNu},
             {"phi_i_deg", kPhi},
             {"psi_deg", psi},
             {"c_kPa", kC},
             {"tension_cutoff_kPa", cutoff}}}},
          "test",
          {}};
}

test::Run shear(driver::BoundaryCondition bc, double psi = kPsi) {
  test::ShearSpec s;
  s.model = "mc";
  s.inputs = inputs(psi);
  s.bc = bc;
  s.gamma = 0.05;
  s.increments = 200;
  auto r = test::shear(s);
  REQUIRE(r.result.complete());
  return r;
}

double f_yield(const test::Run& r, std::size_t i) {
  return r.diagnostic("f_yield", i);
}

}  // namespace

TEST_CASE("mc under CNL: slope G, then tau = sigma_n tan(phi_i) + c and du_n/du_x = tan(psi)",
          "[models]") {
  const auto r = shear({BoundaryKind::kCNL, 0.0});
  const auto& rows = r.result.rows;
  // elastic: the first increment (gamma 2.5e-4, tau 5.6 kPa: far from the strength)
  CHECK(r.model->stress(rows[1].state).tau_x == Approx(kG * rows[1].gamma_x).epsilon(1e-12));
  const double strength = 100.0 * kTanPhi + kC;
  const auto& last = rows.back();
  CHECK(r.model->stress(last.state).tau_x == Approx(strength).epsilon(1e-12));
  const auto& before = rows[rows.size() - 2];
  CHECK((last.eps_n - before.eps_n) / (last.gamma_x - before.gamma_x) ==
        Approx(kTanPsi).epsilon(1e-9));
  for (std::size_t i = 0; i < rows.size(); ++i) CHECK(f_yield(r, i) <= 1e-12 * strength);
}

TEST_CASE(
    "mc under CV: the stress climbs the yield line, sigma_n rises with dilatancy, stays with psi = "
    "0",
    "[models]") {
  const auto r = shear({BoundaryKind::kCV, 0.0});
  const auto& rows = r.result.rows;
  const auto a = r.model->stress(rows[rows.size() - 2].state),
             b = r.model->stress(rows.back().state);
  CHECK((b.tau_x - a.tau_x) / (b.sigma_n - a.sigma_n) ==
        Approx(kTanPhi).epsilon(1e-9));  // on f = 0
  CHECK(b.sigma_n > 300.0);              // psi 5 deg at gamma 0.05: E_oed lambda tan(psi) is large
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const double f = f_yield(r, i);
    CHECK((f < 0.0 || std::abs(f) <= 1e-12 * (1.0 + b.sigma_n)));
  }
  const auto flat = shear({BoundaryKind::kCV, 0.0}, 0.0);
  CHECK(flat.model->stress(flat.result.rows.back().state).sigma_n == Approx(100.0).epsilon(1e-12));
  CHECK(flat.model->stress(flat.result.rows.back().state).tau_x ==
        Approx(100.0 * kTanPhi + kC).epsilon(1e-12));
}

TEST_CASE("mc under CNS: sigma_n follows K u_n on the yield line", "[models]") {
  const double K = 2000.0;  // kPa per unit normal strain
  const auto r = shear({BoundaryKind::kCNS, K});
  const auto& rows = r.result.rows;
  const auto first = r.model->stress(rows.front().state), last = r.model->stress(rows.back().state);
  CHECK(last.sigma_n - first.sigma_n == Approx(K * rows.back().eps_n).epsilon(1e-9));
  CHECK(last.tau_x == Approx(last.sigma_n * kTanPhi + kC).epsilon(1e-12));
  CHECK(last.sigma_n > first.sigma_n);  // dilation against the spring
}

TEST_CASE("mc: the closed-form increment's Dual derivative is its central difference", "[models]") {
  const auto m = models::find_model("mc").make(inputs());
  models::StateVector s(5);
  s << -100.0, 60.0, 20.0, 0.0, 0.0;  // inside; the increment below crosses the surface
  test::check_increment_derivative(
      *m, s, {{1e-4, 2e-3, 5e-4}, {-2e-4, 1e-3, 0.0}, {3e-5, 1e-5, 0.0}}, 1e-8, 1e-6, 1e-6);
}

TEST_CASE("mc: at rest (no shear, no increment) the increment's tangent is elastic: G and E_oed",
          "[models]") {
  // the tangent a caller starts Newton from (a pile under load control, an FE code's first
  // iteration): d tau / d gamma = G and d sigma_n / d eps_n = E_oed at tau = 0 and d = 0, whatever
  // direction the shear will take (seen 0 in tau while the direction of a zero tau was undefined)
  const auto m = models::find_model("mc").make(inputs());
  models::StateVector s(5);
  s << -100.0, 0.0, 0.0, 0.0, 0.0;
  models::StateVectorT<Dual> sd = s.cast<Dual>(), by_gamma, by_eps;
  m->update(sd, {Dual(0.0), make_variable(0.0), Dual(0.0)}, by_gamma);
  CHECK(derivative_of(by_gamma(1)) == Approx(kG).epsilon(1e-12));  // tau_x
  CHECK(derivative_of(by_gamma(0)) == Approx(0.0).margin(1e-12));  // T_n
  m->update(sd, {make_variable(0.0), Dual(0.0), Dual(0.0)}, by_eps);
  CHECK(derivative_of(by_eps(0)) ==
        Approx(kEoed).epsilon(1e-12));  // -sigma_n rises: T_n = -sigma_n
}

TEST_CASE("mc: an opening past the cut-off leaves sigma_n there and the shear on the surface",
          "[models]") {
  const auto m = models::find_model("mc").make(inputs(kPsi, 0.5));
  models::StateVector s(5), out(5);
  s << -10.0, 5.0, 0.0, 0.0, 0.0;
  m->update(s, {1e-3, 0.0, 0.0}, out);  // opens by 60 kPa worth of normal strain
  CHECK(-out(0) == Approx(-0.5));
  CHECK(std::abs(out(1)) <= kC - 0.5 * kTanPhi + 1e-12);
  CHECK(out(3) > 0.0);  // the overshoot is plastic opening
}

TEST_CASE("mc refuses psi above phi_i and a cut-off beyond the apex, naming the keys", "[models]") {
  const auto& spec = models::find_model("mc");
  CHECK_THROWS_WITH(spec.make(inputs(40.0)), Catch::Contains("psi_deg = 40 above phi_i_deg = 35"));
  CHECK_THROWS_WITH(spec.make(inputs(kPsi, 10.0)),
                    Catch::Contains("tension_cutoff_kPa = 10 beyond the yield surface's apex"));
}
