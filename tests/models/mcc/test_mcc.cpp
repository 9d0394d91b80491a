// Modified Cam clay (src/models/mcc, seed 8.3): facts of the critical state model derived by hand
// from eqs. 8.18-8.20 (Wood 2000, natural-strain slopes), never from the code: the undrained end
// p_cs = p0 / 2^((lambda - kappa)/lambda) whatever the increment, q = M p and p_c = 2p at the
// critical state, the K0 normal compression line's slope lambda, the elastic shear modulus inside
// the ellipse, f = 0 to round-off after every plastic increment, reduced = 3D in simple shear, and
// the Dual derivative of an increment against central differences.
#include <catch2/catch.hpp>
#include <cmath>

#include "algebra/ops.hpp"
#include "models/mcc/modified_cam_clay.hpp"
#include "models/registry.hpp"
#include "support/fixtures.hpp"
#include "support/increment_derivative.hpp"
#include "support/reduced_vs_3d.hpp"

using namespace iwb;
using driver::BoundaryKind;

namespace {

constexpr double kLambda = 0.161, kKappa = 0.062, kM = 0.88, kNu = 0.31;  // Table 8.1, London clay

models::ModelInputs london(double nu = kNu) {
  return {{{"modified_cam_clay", {{"lambda", kLambda}, {"kappa", kKappa}, {"M", kM}, {"nu", nu}}}},
          "test",
          {}};
}

test::ShearSpec spec(driver::BoundaryCondition bc, double gamma, int increments, double K0 = 1.0) {
  test::ShearSpec s;
  s.model = "mcc";
  s.inputs = london();
  s.bc = bc;
  s.K0 = K0;
  s.e0 = 1.0;
  s.gamma = gamma;
  s.increments = increments;
  return s;
}

test::Run complete_shear(const test::ShearSpec& s) {
  auto r = test::shear(s);
  REQUIRE(r.result.complete());
  return r;
}

}  // namespace

TEST_CASE(
    "mcc under CV from the isotropic NCL ends at p0 / 2^((lambda - kappa)/lambda), q = M p, "
    "whatever the increment",
    "[models][mcc]") {
  // e constant: kappa ln(p/p0) + (lambda - kappa) ln(p_c/p0) = 0 with p_c = 2p at the critical
  // state
  const double p_cs = 100.0 / std::pow(2.0, (kLambda - kKappa) / kLambda);
  for (int increments : {40, 4000}) {
    const auto r = complete_shear(spec({BoundaryKind::kCV, 0.0}, 3.0, increments));
    const std::size_t last = r.result.rows.size() - 1;
    INFO(increments << " increments");
    CHECK(r.diagnostic("mean_stress_kPa", last) == Approx(p_cs).epsilon(1e-6));
    CHECK(r.diagnostic("eta_over_M", last) == Approx(1.0).epsilon(1e-6));
  }
}

TEST_CASE("mcc under CNL reaches the critical state: q = M p, p_c = 2p", "[models][mcc]") {
  const auto r = complete_shear(spec({BoundaryKind::kCNL, 0.0}, 3.0, 3000, 0.7));
  const auto& last = r.result.rows.back().state;
  const double p = r.diagnostic("mean_stress_kPa", r.result.rows.size() - 1);
  CHECK(r.diagnostic("eta_over_M", r.result.rows.size() - 1) == Approx(1.0).epsilon(1e-4));
  CHECK(last(last.size() - 1) == Approx(2.0 * p).epsilon(1e-4));
}

TEST_CASE("mcc: after every plastic increment the state is on the ellipse to round-off",
          "[models][mcc]") {
  for (auto bc : {driver::BoundaryCondition{BoundaryKind::kCNL, 0.0},
                  driver::BoundaryCondition{BoundaryKind::kCNS, 500.0},
                  driver::BoundaryCondition{BoundaryKind::kCV, 0.0}}) {
    const auto r = complete_shear(spec(bc, 0.3, 300, 0.7));
    for (std::size_t i = 1; i < r.result.rows.size(); ++i)
      CHECK(std::abs(r.diagnostic("f_yield", i)) < 1e-13);
  }
}

TEST_CASE("mcc: oedometric loading on the NCL follows the slope lambda of eps_v against ln p",
          "[models][mcc]") {
  // on the ellipse at a constant stress ratio p_c is proportional to p: eps_v = kappa ln p +
  // (lambda - kappa) ln p_c
  const auto model = test::make("mcc3d", london());
  const auto s0 = model->initial_state({10.0, 0.7, 1.0});
  const auto r = driver::run_element_test(*model, s0, driver::oedometric_path(10.0, 1000.0, 400),
                                          driver::RunSettings{});
  REQUIRE(r.complete());
  const auto& a = r.rows[r.rows.size() - 11].state;
  const auto& b = r.rows.back().state;
  const auto p = [&](const models::StateVector& x) { return -(x(0) + x(1) + x(2)) / 3.0; };
  CHECK((std::log(1.0 + b(6)) - std::log(1.0 + a(6))) / (std::log(p(b)) - std::log(p(a))) ==
        Approx(-kLambda).epsilon(1e-4));
}

TEST_CASE("mcc: inside the ellipse the shear modulus is 3 (1 - 2 nu) p / (2 kappa (1 + nu))",
          "[models][mcc]") {
  const auto m = models::find_model("mcc").make(london());
  models::InitialState init{100.0, 1.0, 1.0};
  init.named["OCR"] = 2.0;
  const auto s = m->initial_state(init);
  models::StateVector out;
  m->update(s, {0.0, 1e-6, 0.0}, out);
  const double G = 3.0 * (1.0 - 2.0 * kNu) * 100.0 / (2.0 * kKappa * (1.0 + kNu));
  CHECK(m->stress(out).tau_x == Approx(G * 1e-6).epsilon(1e-9));
  CHECK(m->stress(out).sigma_n ==
        Approx(100.0).epsilon(1e-12));  // isotropic elasticity: no dilatancy
}

TEST_CASE("mcc = mcc3d in simple shear (the return acts on p and the deviator only)",
          "[models][mcc]") {
  for (auto kind : {BoundaryKind::kCV, BoundaryKind::kCNL})
    test::check_reduced_equals_3d(spec({kind, 0.0}, 0.3, 600, 0.7), "mcc", "mcc3d");
}

TEST_CASE("mcc: the increment's Dual derivative is its central difference", "[models][mcc]") {
  const auto m = models::find_model("mcc3d").make(london());
  const auto s = m->initial_state({100.0, 0.7, 1.0});  // on the ellipse: the increments load it
  test::check_increment_derivative(
      *m, s, {{-1e-3, 2e-3, 5e-4}, {2e-4, 1e-2, 0.0}, {1e-3, 1e-4, 0.0}}, 1e-7, 1e-5, 1e-4);
}

namespace {

using Tensor3 = algebra::Tensor3Ops::Tensor<double>;

models::CamClayParameters london_parameters() {
  return {kLambda, kKappa, kM, kNu};
}

Tensor3 diagonal(double a, double r) {
  return Eigen::Vector3d(a, r, r).asDiagonal();
}

}  // namespace

TEST_CASE(
    "mcc: undrained triaxial compression from the isotropic NCL ends at q = M p, p = p0 / "
    "2^((lambda-kappa)/lambda)",
    "[models][mcc]") {
  models::CamClayPoint<algebra::Tensor3Ops, double> s{diagonal(-100.0, -100.0), 100.0};
  // to an axial strain of 2 in steps of 1e-3: the end is exact whatever the step (e constant)
  for (int i = 0; i < 2000; ++i)
    s = models::cam_clay_increment<algebra::Tensor3Ops, double>(s, diagonal(-1e-3, 0.5e-3),
                                                                london_parameters());
  const models::CamClayInvariants<algebra::Tensor3Ops, double> inv(s.T);
  CHECK(inv.p == Approx(100.0 / std::pow(2.0, (kLambda - kKappa) / kLambda)).epsilon(1e-6));
  CHECK(inv.q == Approx(kM * inv.p).epsilon(1e-6));
}

TEST_CASE(
    "mcc: drained triaxial compression from the isotropic NCL ends at p = 3 p0 / (3 - M), "
    "eps_v = lambda ln(p/p0) + (lambda - kappa) ln 2",
    "[models][mcc]") {
  // sigma_3 held at p0: each axial increment's lateral strain found by the secant method. Axial
  // steps of 1e-3 to 10: the end depends on the step through neither the stress path (p = p0 + q/3)
  // nor the exact elastic and hardening laws.
  const double p0 = 100.0;
  models::CamClayPoint<algebra::Tensor3Ops, double> s{diagonal(-p0, -p0), p0};
  double eps_v = 0.0;  // compression positive
  for (int i = 0; i < 10000; ++i) {
    const auto lateral_error = [&](double d_r) {
      return models::cam_clay_increment<algebra::Tensor3Ops, double>(s, diagonal(-1e-3, d_r),
                                                                     london_parameters())
                 .T(1, 1) +
             p0;
    };
    double a = 0.0, b = 0.5e-3, fa = lateral_error(a), fb = lateral_error(b);
    for (int k = 0; k < 50 && std::abs(fb) > 1e-12 * p0; ++k) {
      const double c = b - fb * (b - a) / (fb - fa);
      a = b, fa = fb, b = c, fb = lateral_error(c);
    }
    s = models::cam_clay_increment<algebra::Tensor3Ops, double>(s, diagonal(-1e-3, b),
                                                                london_parameters());
    eps_v -= -1e-3 + 2.0 * b;
  }
  const models::CamClayInvariants<algebra::Tensor3Ops, double> inv(s.T);
  const double p_cs = 3.0 * p0 / (3.0 - kM);
  CHECK(inv.p == Approx(p_cs).epsilon(1e-6));
  CHECK(inv.q == Approx(kM * p_cs).epsilon(1e-6));
  CHECK(eps_v ==
        Approx(kLambda * std::log(p_cs / p0) + (kLambda - kKappa) * std::log(2.0)).epsilon(1e-5));
}
