// Clay hypoplasticity with explicit asymptotic states (src/models/hce, src/models/clay): facts
// derived from the equations of seed 6.2.3 (ERRATA 11-14), never from the code.
#include <catch2/catch.hpp>
#include <cmath>

#include "algebra/ops.hpp"
#include "models/clay/explicit_asymptotic_clay.hpp"
#include "support/clay.hpp"
#include "support/fixtures.hpp"
#include "support/reduced_vs_3d.hpp"

namespace iwb {

namespace {

using Ops = algebra::Tensor3Ops;
using Tensor = Ops::Tensor<double>;

const double kPhi = 25.0 * M_PI / 180.0;  // Table 6.1

models::ModelInputs table_6_1(double kappa_r = 1.0) {
  return test::table_6_1(models::RoughnessScheme::kStutzMasin, kappa_r);
}

models::ExplicitAsymptoticClayConstants constants(double kappa_r = 1.0) {
  const auto in = table_6_1(kappa_r);
  return models::make_explicit_asymptotic_clay_constants(test::clay_parameters(in), in.roughness);
}

double isotropic_slope(double p, double rate) {
  return test::isotropic_slope<models::ExplicitAsymptoticClayLaw>(constants(), p, rate);
}

test::Run cv_shear(const std::string& model, double gamma, double kappa_r = 1.0,
                   double e0 = 0.7185) {
  test::ShearSpec s;
  s.model = model;
  s.inputs = table_6_1(kappa_r);
  if (model.rfind("hcc", 0) == 0) s.inputs.roughness.scheme = models::RoughnessScheme::kArnoldHerle;
  s.bc = {driver::BoundaryKind::kCV, 0.0};
  s.K0 = 1.0 - std::sin(kPhi);
  s.e0 = e0;
  s.gamma = gamma;
  s.increments = 2000;
  return test::shear(s);
}

}  // namespace

TEST_CASE("hce: isotropic loading on the NCL follows lambda*, the first unloading step kappa*",
          "[models][hce]") {
  for (double p : {10.0, 100.0, 1000.0}) {
    CHECK(isotropic_slope(p, -1e-4) == Approx(-0.1).epsilon(1e-12));
    CHECK(isotropic_slope(p, +1e-4) == Approx(-0.01).epsilon(1e-12));
  }
}

TEST_CASE(
    "hce: Matsuoka-Nakai's F_m is 0 for an isotropic stress and sin^2 phi on the cone (eq. 6.16)",
    "[models][hce]") {
  CHECK(std::abs(models::matsuoka_nakai<Ops, double>(-50.0 * Tensor::Identity())) < 1e-14);
  // triaxial compression on the Mohr-Coulomb = Matsuoka-Nakai compression meridian: s1/s3 = (1 +
  // sin)/(1 - sin)
  const double ratio = (1.0 + std::sin(kPhi)) / (1.0 - std::sin(kPhi));
  const Tensor T = -Eigen::Vector3d(100.0 * ratio, 100.0, 100.0).asDiagonal().toDenseMatrix();
  CHECK(models::matsuoka_nakai<Ops, double>(T) ==
        Approx(std::pow(std::sin(kPhi), 2)).epsilon(1e-12));
  // the reduced operators agree (tr X^3 only of the deviator)
  const algebra::ReducedOps::Tensor<double> reduced(-80.0, -50.0, 20.0, 5.0);
  Tensor embedded;
  embedded << -80.0, 20.0, 5.0, 20.0, -50.0, 0.0, 5.0, 0.0, -50.0;
  CHECK(models::matsuoka_nakai<algebra::ReducedOps, double>(reduced) ==
        Approx(models::matsuoka_nakai<Ops, double>(embedded)).epsilon(1e-12));
}

TEST_CASE("hce: CV shear ends at Matsuoka-Nakai's critical state, F_m = sin^2 phi_c, p_e* = 2p",
          "[models][hce]") {
  const auto r = cv_shear("hce", 0.3);
  REQUIRE(r.result.complete());  // ERRATA 12: with 0.3 in omega the rate stays finite
  const std::size_t last = r.result.rows.size() - 1;
  CHECK(r.diagnostic("F_m", last) == Approx(std::pow(std::sin(kPhi), 2)).epsilon(1e-3));
  CHECK(r.diagnostic("p_e_kPa", last) / (2.0 * r.diagnostic("mean_stress_kPa", last)) ==
        Approx(1.0).epsilon(1e-3));
  CHECK(r.diagnostic("f_d_over_f_dA", last) == Approx(1.0).epsilon(1e-3));
}

TEST_CASE("hce: the reduced interface form equals the 3D form in simple shear", "[models][hce]") {
  for (auto kind : {driver::BoundaryKind::kCV, driver::BoundaryKind::kCNL})
    test::check_reduced_equals_3d(test::table_6_1_shear(kind), "hce", "hce3d");
}

// Seed 6.4.2, Figure 6.3 (and ERRATA 12's reason for 0.3): HCE's critical state follows
// Matsuoka-Nakai, HCC's the circular M, so in simple shear HCE ends lower.
TEST_CASE(
    "hce and hcc under CV (Table 6.1, 100 kPa, gamma 0.2): HCE ends at the lower shear stress",
    "[models][hce]") {
  const auto hce = cv_shear("hce", 0.2);
  const auto hcc = cv_shear("hcc", 0.2);
  REQUIRE(hce.result.complete());
  REQUIRE(hcc.result.complete());
  CHECK(hce.last().tau_x < 0.9 * hcc.last().tau_x);
}

TEST_CASE(
    "hce: Stutz & Masin's roughness keeps nu at kappa_r = 1 and lowers the critical state below it",
    "[models][hce]") {
  const auto rough = constants(1.0);
  CHECK(rough.nu_ratio == Approx(0.2 / (1.0 - 0.4)).epsilon(1e-12));  // eq. 6.25 gives nu_r = nu
  const auto smooth = cv_shear("hce", 0.3, 0.7, 0.66);
  const auto full = cv_shear("hce", 0.3, 1.0, 0.66);
  REQUIRE(smooth.result.complete());
  const std::size_t last = smooth.result.rows.size() - 1;
  CHECK(smooth.diagnostic("F_m", last) == Approx(std::pow(std::sin(0.7 * kPhi), 2)).epsilon(1e-3));
  CHECK(smooth.last().tau_x < 0.8 * full.last().tau_x);
}

}  // namespace iwb

namespace iwb {

// f_d = (2p/p_e*)^alpha_f and f_d^A its value on the ASBS: a start at OCR has f_d/f_d^A =
// OCR^-alpha_f.
TEST_CASE("hce: a start given by OCR has f_d / f_d^A = OCR^-alpha_f", "[models][hce]") {
  const auto& spec = models::find_model("hce");
  const auto in = test::table_6_1(models::RoughnessScheme::kStutzMasin);
  const auto model = spec.make(in);
  const double alpha_f = constants().alpha_f;
  for (double ocr : {1.0, 2.0, 8.0}) {
    auto start = models::offer(spec, in, {{"sigma_n_kPa", 100.0}});
    start.named["OCR"] = ocr;
    const auto s = model->initial_state(start);
    CHECK(model->diagnostics(s)[3].value == Approx(std::pow(ocr, -alpha_f)).epsilon(1e-12));
  }
}

}  // namespace iwb
