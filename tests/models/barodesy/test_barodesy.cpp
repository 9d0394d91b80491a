// Barodesy for clay (src/models/barodesy, seed 8.2): the asymptotic facts barodesy is built on,
// each derived by hand from eqs. 8.1-8.15 as corrected (README.md), and reference values of an
// independent implementation of the same equations (Python with mpmath at 50 digits, written
// outside the repository from the equations alone; README.md says how).
#include <catch2/catch.hpp>
#include <cmath>

#include "algebra/ops.hpp"
#include "models/barodesy/barodesy_law.hpp"
#include "models/registry.hpp"
#include "support/fixtures.hpp"

using namespace iwb;
using Ops = algebra::Tensor3Ops;
using Tensor = Ops::Tensor<double>;

namespace {

models::BarodesyParameters london() {
  return {0.11, 0.016, 22.6 * M_PI / 180.0, 1.375, 100.0};
}  // Table 8.1
models::BarodesyParameters kaolin() {
  return {0.065, 0.01, 27.5 * M_PI / 180.0, 0.88, 20.0};
}

models::BarodesyConstants constants(const models::BarodesyParameters& p) {
  return models::make_barodesy_constants(p, {});
}

Tensor rate(const Tensor& T, double e, const Tensor& D, const models::BarodesyConstants& c) {
  return models::BarodesyLaw::rate<Ops, double>(T, e, D, c);
}

double e_on_ncl(const models::BarodesyParameters& p, double mean) {
  return std::exp(p.N - p.lambda_star * std::log(mean)) - 1.0;
}

// d ln(1+e) / d ln p of the isotropic stretching `sign` 1 from an isotropic state at p on the NCL.
double isotropic_slope(const models::BarodesyParameters& par, double p, double sign) {
  const auto c = constants(par);
  const Tensor D = sign * Tensor::Identity();
  const Tensor dT = rate(-p * Tensor::Identity(), e_on_ncl(par, p), D, c);
  return D.trace() / (-dT.trace() / 3.0 / p);  // d ln(1+e) = tr D
}

}  // namespace

TEST_CASE(
    "barodesy: c2 = -3 (1 + sqrt2) / 2 for K0 = 1 - sin phi_c (eq. 8.11 with K_c - K_0), c1 puts "
    "K_c at m = 0",
    "[models][barodesy]") {
  // with Jaky's K0, K0 (1 - K_c) / (K_c (1 - K0)) = 2 for every phi: c2 does not depend on phi_c
  for (const auto& p : {london(), kaolin()}) {
    const auto c = constants(p);
    CHECK(c.c2 == Approx(-1.5 * (1.0 + std::sqrt(2.0))).epsilon(1e-14));
    CHECK(1.0 - 1.0 / (1.0 + c.c1 * c.c2 * c.c2) == Approx(c.K_c).epsilon(1e-14));  // K(m = 0)
    const double K0 = 1.0 - std::sin(p.phi_c), m = 1.5;  // oedometric D^0: delta = -1
    CHECK(1.0 - 1.0 / (1.0 + c.c1 * (m - c.c2) * (m - c.c2)) == Approx(K0).epsilon(1e-14));
  }
}

TEST_CASE(
    "barodesy: the rate at a general point equals an independent implementation (London and "
    "Kaolin)",
    "[models][barodesy]") {
  Tensor T, D;
  T << -100, -10, 0, -10, -80, 0, 0, 0, -80;
  D << -0.3, 0.2, 0, 0.2, 0.1, 0, 0, 0, 0.05;
  const auto l = constants(london());
  CHECK(l.c3 == Approx(-154.7018984957858).epsilon(1e-13));  // the unloading entry of 8.12
  CHECK(l.c6 == Approx(0.5638576557576654).epsilon(1e-13));
  const Tensor rl = rate(T, 0.9, D, l);
  CHECK(rl(0, 0) == Approx(-2981.12866202292).epsilon(1e-12));
  CHECK(rl(0, 1) == Approx(927.5965006090955).epsilon(1e-12));
  CHECK(rl(1, 1) == Approx(-1544.198567363036).epsilon(1e-12));
  CHECK(rl(2, 2) == Approx(-1602.641071921261).epsilon(1e-12));
  const auto k = constants(kaolin());
  CHECK(k.c3 == Approx(-100.952091037393).epsilon(1e-13));  // the shear entry
  CHECK(k.c6 == Approx(0.2708746366080944).epsilon(1e-13));
  const Tensor rk = rate(T, 0.9, D, k);
  CHECK(rk(0, 0) == Approx(440.5269888800019).epsilon(1e-12));
  CHECK(rk(0, 1) == Approx(949.8368708090918).epsilon(1e-12));
  CHECK(rk(1, 1) == Approx(1092.858417320647).epsilon(1e-12));
  CHECK(rk(2, 2) == Approx(1072.729479626477).epsilon(1e-12));
}

TEST_CASE(
    "barodesy: isotropic compression on the NCL follows lambda* exactly, first unloading kappa_eff",
    "[models][barodesy]") {
  for (const auto& p : {london(), kaolin()}) {
    const auto c = constants(p);
    for (double mean : {10.0, 100.0, 1000.0}) {
      CHECK(isotropic_slope(p, mean, -1.0) == Approx(-p.lambda_star).epsilon(1e-12));
      // delta = sqrt3 from the NCL: f + g = -sqrt3 / (c3 kappa*) + 2 (2^(c5 lambda*) - 1), so the
      // slope is 1 / (1/kappa* - (2/sqrt3) c3 (2^(c5 lambda*) - 1)): kappa* only as c3 -> 0
      // (README.md)
      const double kappa_eff =
          1.0 / (1.0 / p.kappa_star -
                 2.0 / std::sqrt(3.0) * c.c3 * (std::pow(2.0, c.c5 * p.lambda_star) - 1.0));
      CHECK(isotropic_slope(p, mean, 1.0) == Approx(-kappa_eff).epsilon(1e-12));
    }
  }
}

TEST_CASE(
    "barodesy: at the critical state (delta = 0, e = e_c, T^0 = R^0) the stress rate vanishes, "
    "sigma_3/sigma_1 = K_c",
    "[models][barodesy]") {
  for (const auto& p : {london(), kaolin()}) {
    const auto c = constants(p);
    const double s1 = 150.0, mean = s1 * (1.0 + 2.0 * c.K_c) / 3.0;
    const Tensor T = -Eigen::Vector3d(s1, c.K_c * s1, c.K_c * s1).asDiagonal().toDenseMatrix();
    const double e_c = std::exp(p.N - p.lambda_star * std::log(2.0 * mean)) - 1.0;  // eq. 8.7
    const Tensor D =
        Eigen::Vector3d(-1.0, 0.5, 0.5).asDiagonal();  // isochoric triaxial compression
    CHECK(rate(T, e_c, D, c).norm() < 1e-12 * std::abs(c.c3) * T.norm() * D.norm());
    // phi_c from sigma_3 / sigma_1 = (1 - sin phi) / (1 + sin phi)
    CHECK(std::asin((1.0 - c.K_c) / (1.0 + c.K_c)) == Approx(p.phi_c).epsilon(1e-14));
  }
}

TEST_CASE(
    "barodesy: a proportional oedometric path approaches K0 = 1 - sin phi_c and the NCL's slope "
    "lambda*",
    "[models][barodesy]") {
  models::ModelInputs in{{{"barodesy_clay",
                           {{"lambda_star", 0.11},
                            {"kappa_star", 0.016},
                            {"phi_c_deg", 22.6},
                            {"N", 1.375},
                            {"G0_over_p", 100.0}}}},
                         "test",
                         {}};
  const auto model = test::make("barodesy-clay3d", in);
  const auto s0 = model->initial_state({10.0, 1.0, e_on_ncl(london(), 10.0)});
  driver::RunSettings settings;
  const auto r =
      driver::run_element_test(*model, s0, driver::oedometric_path(10.0, 10000.0, 600), settings);
  REQUIRE(r.complete());
  const auto& a = r.rows[r.rows.size() - 11].state;
  const auto& b = r.rows.back().state;
  const auto p = [&](const models::StateVector& x) { return -(x(0) + x(1) + x(2)) / 3.0; };
  CHECK(b(1) / b(0) == Approx(1.0 - std::sin(22.6 * M_PI / 180.0)).epsilon(1e-3));
  CHECK((std::log(1.0 + b(6)) - std::log(1.0 + a(6))) / (std::log(p(b)) - std::log(p(a))) ==
        Approx(-0.11).epsilon(1e-3));
}

TEST_CASE(
    "barodesy-clay3d: CV simple shear from the isotropic NCL equals an independent integration",
    "[models][barodesy]") {
  test::ShearSpec s;
  s.model = "barodesy-clay3d";
  s.inputs = test::shipped("table_8_1_london_clay.toml");
  s.bc = {driver::BoundaryKind::kCV, 0.0};
  s.K0 = 1.0;
  s.e0 = e_on_ncl(london(), 100.0);
  s.gamma = 0.3;
  s.increments = 300;
  s.settings.integrator.rtol = 1e-10;
  const auto r = test::shear(s);
  REQUIRE(r.result.complete());
  const auto& t =
      r.result.rows.back().state;  // T_11, T_22, T_33, T_12: RK4, 30000 steps, independent code
  CHECK(t(0) == Approx(-51.73515643393).epsilon(1e-8));
  CHECK(t(1) == Approx(-51.73515643393).epsilon(1e-8));
  CHECK(t(2) == Approx(-46.54921896640).epsilon(1e-8));
  CHECK(t(3) == Approx(22.57646079743).epsilon(1e-8));
}

TEST_CASE(
    "barodesy: OCR 1 is the state boundary surface: the isotropic NCL at K = 1, the oedometric "
    "asymptote at K0, e_c at K_c",
    "[models][barodesy]") {
  const auto in = test::shipped("table_8_1_london_clay.toml");
  const auto c = constants(london());
  for (const std::string name : {"barodesy-clay", "barodesy-clay3d"}) {
    const auto model = test::make(name, in);
    const auto start = [&](double sigma_n, double K0) {
      models::InitialState s{sigma_n, K0, 0.0};
      s.named["OCR"] = 1.0;
      return model->void_ratio(model->initial_state(s));
    };
    CHECK(start(100.0, 1.0) == Approx(e_on_ncl(london(), 100.0)).epsilon(1e-14));
    // the oedometric asymptote at p = 100 kPa of an independent integration (RK4 of the rate to
    // eps_1 = 2)
    const double K0 = 1.0 - std::sin(london().phi_c);
    CHECK(start(300.0 / (1.0 + 2.0 * K0), K0) == Approx(1.323218403992).epsilon(1e-10));
    // at K_c: delta = 0, (1+e) = (1+e_c), eq. 8.7
    const double p = 100.0 * (1.0 + 2.0 * c.K_c) / 3.0;
    CHECK(start(100.0, c.K_c) ==
          Approx(std::exp(london().N - london().lambda_star * std::log(2.0 * p)) - 1.0)
              .epsilon(1e-12));
  }
}
