// Hypoplastic Cam clay (src/models/hcc, src/models/clay): facts derived from the equations of
// seed 6.2.2 and modified Cam clay, never from the code: the normal compression and first
// unloading slopes, the NCL through N, the critical state under CV, reduced = 3D (ERRATA 13).
#include <catch2/catch.hpp>
#include <cmath>

#include "algebra/ops.hpp"
#include "models/clay/hypoplastic_cam_clay.hpp"
#include "support/clay.hpp"
#include "support/fixtures.hpp"
#include "support/reduced_vs_3d.hpp"

namespace iwb {

namespace {

using Ops = algebra::Tensor3Ops;
using Tensor = Ops::Tensor<double>;

models::ModelInputs table_6_1(double kappa_r = 1.0) {
  return test::table_6_1(models::RoughnessScheme::kArnoldHerle, kappa_r);
}

models::HypoplasticCamClayConstants constants() {
  const auto in = table_6_1();
  return models::make_hypoplastic_cam_clay_constants(test::clay_parameters(in), in.roughness);
}

double e_on_ncl(double p) {
  return test::e_on_table_6_1_ncl(p);
}

double isotropic_slope(double p, double rate) {
  return test::isotropic_slope<models::HypoplasticCamClayLaw>(constants(), p, rate);
}

const double kM25 = 6.0 * std::sin(25.0 * M_PI / 180.0) / (3.0 - std::sin(25.0 * M_PI / 180.0));

// CV simple shear of a normally consolidated start, as data/tests/hcc_cv_table_6_1.toml.
test::Run cv_shear(const std::string& model, double gamma, double kappa_r = 1.0,
                   double e0 = 0.7185) {
  test::ShearSpec s;
  s.model = model;
  s.inputs = table_6_1(kappa_r);
  s.bc = {driver::BoundaryKind::kCV, 0.0};
  s.K0 = 1.0 - std::sin(25.0 * M_PI / 180.0);
  s.e0 = e0;
  s.gamma = gamma;
  s.increments = 2000;
  return test::shear(s);
}

}  // namespace

TEST_CASE("hcc: isotropic loading on the NCL follows lambda*, the first unloading step kappa*",
          "[models][hcc]") {
  for (double p : {10.0, 100.0, 1000.0}) {
    CHECK(isotropic_slope(p, -1e-4) == Approx(-0.1).epsilon(1e-12));   // lambda*: compression
    CHECK(isotropic_slope(p, +1e-4) == Approx(-0.01).epsilon(1e-12));  // kappa*: unloading
  }
}

TEST_CASE("hcc: oedometric loading ends on the normal compression line, slope lambda*, OCR 1",
          "[models][hcc]") {
  const auto in = test::shipped("table_6_4_cyclic.toml");  // lambda* = 0.128
  const auto model = test::make("hcc3d", in);
  const auto s0 = model->initial_state({10.0, 1.0 - std::sin(22.0 * M_PI / 180.0), 2.3});
  driver::RunSettings settings;
  const auto r =
      driver::run_element_test(*model, s0, driver::oedometric_path(10.0, 1000.0, 400), settings);
  REQUIRE(r.complete());
  const auto& a = r.rows[r.rows.size() - 11].state;
  const auto& b = r.rows.back().state;
  const auto p = [&](const models::StateVector& x) { return -(x(0) + x(1) + x(2)) / 3.0; };
  const double slope =
      (std::log(1.0 + b(6)) - std::log(1.0 + a(6))) / (std::log(p(b)) - std::log(p(a)));
  CHECK(slope == Approx(-0.128).epsilon(1e-4));
  CHECK(model->diagnostics(b)[2].value == Approx(1.0).epsilon(1e-4));
}

TEST_CASE(
    "hcc: the isotropic NCL passes through N at 1 kPa, and on it OCR = 1 (eq. 6.7, ERRATA 15)",
    "[models][hcc]") {
  const auto c = constants();
  for (double p : {1.0, 50.0, 800.0}) {
    const auto d = models::HypoplasticCamClayLaw::diagnostics({3.0 * p, p, 0.0}, e_on_ncl(p), c);
    CHECK(d[1].value == Approx(p).epsilon(1e-12));  // p_e* = p on the isotropic NCL
    CHECK(d[2].value == Approx(1.0).epsilon(1e-12));
  }
  CHECK(std::log(1.0 + e_on_ncl(1.0)) == Approx(1.0));
}

TEST_CASE(
    "hcc: CV shear of a normally consolidated clay ends at the critical state, q = M p, p_e* = 2p",
    "[models][hcc]") {
  const auto r = cv_shear("hcc", 0.3);
  REQUIRE(r.result.complete());
  const auto end = r.last();
  const double p = (end.sigma_n + 2.0 * *end.sigma_p) / 3.0;
  const double q = std::sqrt(std::pow(end.sigma_n - *end.sigma_p, 2) + 3.0 * end.tau_x * end.tau_x);
  CHECK(q / p == Approx(kM25).epsilon(1e-3));
  const std::size_t last = r.result.rows.size() - 1;
  CHECK(r.diagnostic("p_e_kPa", last) / (2.0 * r.diagnostic("mean_stress_kPa", last)) ==
        Approx(1.0).epsilon(1e-3));
  CHECK(r.last_e() == 0.7185);  // constant volume
}

TEST_CASE("hcc: the reduced interface form equals the 3D form in simple shear (ERRATA 13)",
          "[models][hcc]") {
  for (auto kind : {driver::BoundaryKind::kCV, driver::BoundaryKind::kCNL})
    test::check_reduced_equals_3d(test::table_6_1_shear(kind), "hcc", "hcc3d");
}

TEST_CASE(
    "hcc: a smoother wall (kappa_r < 1) lowers the critical shear stress by M(phi_c kappa_r) (eq. "
    "6.22)",
    "[models][hcc]") {
  // e0 on the smaller ASBS of kappa_r = 0.7 (inside the rough wall's): both end at p = p_e*/2
  const auto rough = cv_shear("hcc", 0.3, 1.0, 0.67);
  const auto smooth = cv_shear("hcc", 0.3, 0.7, 0.67);
  REQUIRE(smooth.result.complete());
  const auto end = smooth.last();
  const double p = (end.sigma_n + 2.0 * *end.sigma_p) / 3.0;
  const double q = std::sqrt(std::pow(end.sigma_n - *end.sigma_p, 2) + 3.0 * end.tau_x * end.tau_x);
  const double s = std::sin(0.7 * 25.0 * M_PI / 180.0);
  CHECK(q / p == Approx(6.0 * s / (3.0 - s)).epsilon(1e-3));
  CHECK(end.tau_x < 0.8 * rough.last().tau_x);
}

TEST_CASE("hcc: a start above the normal compression line is refused, naming the ASBS",
          "[models][hcc]") {
  const auto model = test::make("hcc", table_6_1());
  CHECK_THROWS_WITH(model->initial_state({100.0, 0.6, 0.9}),
                    Catch::Contains("asymptotic state boundary surface"));
}

}  // namespace iwb

namespace iwb {

TEST_CASE("hcc: every clay model is rate independent: rate(s, l d) = l rate(s, d) for l > 0",
          "[models][hcc]") {
  for (const std::string name : {"hcc", "hcc3d", "hcc-igs", "hcc3d-igs"}) {
    const auto& spec = models::find_model(name);
    const auto model = test::make(name, test::shipped(spec.declaration.example_parameters));
    auto s = model->initial_state(
        models::offer(spec, test::shipped(spec.declaration.example_parameters),
                      {{"sigma_n_kPa", 100.0}, {"e0", spec.declaration.example_start.at("e0")}}));
    for (const models::InterfaceStrain d :
         {models::InterfaceStrain{-1e-4, 3e-4, 1e-4}, models::InterfaceStrain{2e-4, -1e-4, 0.0}}) {
      models::StateVector r1, r2;
      model->rate(s, d, r1);
      for (double l : {1e-3, 0.5, 7.0}) {
        model->rate(s, {l * d.eps_n, l * d.gamma_x, l * d.gamma_y}, r2);
        INFO(name);
        CHECK((r2 - l * r1).cwiseAbs().maxCoeff() <= 1e-12 * l * r1.cwiseAbs().maxCoeff());
      }
    }
  }
}

}  // namespace iwb

namespace iwb {

TEST_CASE("hcc: a start given by OCR lands where the OCR diagnostic says it is", "[models][hcc]") {
  const auto& spec = models::find_model("hcc");
  const auto in = test::table_6_1(models::RoughnessScheme::kArnoldHerle);
  const auto model = spec.make(in);
  for (double ocr : {1.0, 2.0, 8.0}) {
    auto start = models::offer(spec, in, {{"sigma_n_kPa", 100.0}});
    start.named["OCR"] = ocr;
    const auto s = model->initial_state(start);
    CHECK(model->diagnostics(s)[2].value == Approx(ocr).epsilon(1e-12));
  }
}

}  // namespace iwb
