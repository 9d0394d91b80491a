// Calibration from soil tests (issue 7, item 2): on synthetic targets made by vw3d with Table 5.2
// Hostun, the staged fit finds the parameters again within their reported uncertainty, and
// flags what the tests cannot determine.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <regex>

#include "bench/calibration_bench.hpp"
#include "calibration/calibrate.hpp"
#include "calibration/seed_scatter.hpp"
#include "calibration/synthetic.hpp"
#include "models/hypoplastic/calibration_recipe.hpp"
#include "support/fixtures.hpp"

using namespace iwb;
using driver::BoundaryKind;
using soil_test::SoilTestKind;

namespace {

soil_test::SoilTest target(SoilTestKind kind, BoundaryKind bc, double e0, const std::string& name,
                           const models::ModelInputs& truth = test::table_5_2_hostun(),
                           double sigma_max_kPa = 5000.0) {
  return bench::synthetic_soil_test(kind, bc, e0, name, truth, sigma_max_kPa);
}

std::vector<soil_test::SoilTest> hostun_targets() {
  return bench::hostun_soil_tests(test::table_5_2_hostun());
}

void explain(const calibration::CalibrationResult& r, const models::ParameterValues& truth) {
  for (const auto& n : r.notes) UNSCOPED_INFO(n);
  UNSCOPED_INFO(r.seconds << " s, " << r.evaluations << " evaluations, s2 " << r.s2);
  for (const auto& t : r.tests)
    for (const auto& c : t.rmse)
      UNSCOPED_INFO(t.name << ": RMSE " << c.column << " " << c.rmse << " (" << t.status << ")");
  for (const auto& p : r.parameters)
    UNSCOPED_INFO(p.key << " = " << p.value << " +- " << p.sigma << " (at scatter "
                        << p.sigma_at_scatter << "; true " << truth.at(p.key) << ") " << p.how);
}

const calibration::ParameterEstimate& estimate(const calibration::CalibrationResult& r,
                                               const std::string& key) {
  for (const auto& p : r.parameters)
    if (p.key == key) return p;
  throw std::logic_error(key);
}

}  // namespace

// Noise-free targets: the fit residual is the integrator's (rtol 1e-7), so the Gauss-Newton sigma
// is tiny and the stated tolerance kRecoveryTolerance (relative) applies where it is larger than 3
// sigma.
TEST_CASE("calibration recovers the Hostun parameters from synthetic vw3d soil tests",
          "[calibration]") {
  constexpr double kRecoveryTolerance = 1e-4;
  const auto tests = hostun_targets();
  const auto r = calibration::calibrate(tests);
  const auto truth = test::table_5_2_hostun().tables.at("hypoplastic");
  explain(r, truth);
  // its cost is `iwb bench calibration`'s figure (about 11 s of CPU), not a check here
  CHECK(r.converged);
  for (const auto& p : r.parameters) {
    INFO(p.key << " = " << p.value << " +- " << p.sigma << ", true " << truth.at(p.key));
    CHECK(p.identified);
    CHECK(std::isfinite(p.sigma));
    CHECK(std::abs(p.value - truth.at(p.key)) <=
          std::max(3.0 * p.sigma, kRecoveryTolerance * truth.at(p.key)));
  }
  // the staged estimate of phi_c (stage A) already within 0.1 deg: the critical ratio is the
  // model's
  CHECK(r.notes.front().find("phi_c = 31.0") != std::string::npos);
  for (const auto& t : r.tests) {
    INFO(t.name);
    CHECK(t.status == "complete");
    CHECK(t.rows_reached == t.rows);
    for (const auto& c : t.rmse)
      CHECK(c.rmse < (c.column == "e" ? 1e-4 : 0.05));  // kPa for stresses
  }
}

// Issue 20 item 3's design on Table 5.2 Toyoura: a dense and a loose oedometer (10 -> 2000 ->
// 100 kPa) and one medium-dense CNL and CV simple shear. With 30 Levenberg-Marquardt iterations the
// joint fit stopped unconverged at RMS 0.37 scatter units, h_s 2.40e6 (true 2.6e6), n 0.284
// (0.27), e_d0 0.521 (0.61), alpha 0.322 (0.25): 5-11 of its own sigmas off. Run to convergence
// (155 iterations), every parameter is found again.
TEST_CASE("calibration recovers the Toyoura parameters from two oedometers, CNL and CV",
          "[calibration]") {
  constexpr double kRecoveryTolerance = 1e-4;
  const auto toyoura = test::table_5_2_toyoura();
  const std::vector<soil_test::SoilTest> tests = {
      target(SoilTestKind::kOedometer, BoundaryKind::kCNL, 0.70, "dense oedometer", toyoura, 2000),
      target(SoilTestKind::kOedometer, BoundaryKind::kCNL, 0.95, "loose oedometer", toyoura, 2000),
      target(SoilTestKind::kSimpleShear, BoundaryKind::kCNL, 0.75, "CNL", toyoura),
      target(SoilTestKind::kSimpleShear, BoundaryKind::kCV, 0.75, "CV", toyoura)};
  const auto r = calibration::calibrate(tests);
  const auto truth = toyoura.tables.at("hypoplastic");
  explain(r, truth);
  CHECK(r.converged);
  for (const auto& p : r.parameters) {
    INFO(p.key << " = " << p.value << " +- " << p.sigma << ", true " << truth.at(p.key));
    CHECK(p.identified);
    CHECK(std::abs(p.value - truth.at(p.key)) <=
          std::max(3.0 * p.sigma, kRecoveryTolerance * truth.at(p.key)));
  }
}

// Two loose shear tests and no oedometer: the critical state (phi_c, e_c0) and the dilatancy near
// it (alpha) are there, the compression law (h_s, n), the stiffness exponent beta and the limits
// e_d0, e_i0 are not. The calibration must flag them rather than print a number, and set the
// limits from e_c0.
TEST_CASE("calibration flags what loose-only tests cannot identify", "[calibration]") {
  std::vector<soil_test::SoilTest> tests = {
      target(SoilTestKind::kSimpleShear, BoundaryKind::kCNL, 0.90, "loose CNL"),
      target(SoilTestKind::kSimpleShear, BoundaryKind::kCV, 0.88, "loose CV")};
  const auto r = calibration::calibrate(tests);
  const auto truth = test::table_5_2_hostun().tables.at("hypoplastic");
  explain(r, truth);
  for (const std::string key : {"hs_kPa", "n", "beta", "ed0", "ei0"}) {
    INFO(key);
    CHECK_FALSE(estimate(r, key).identified);
  }
  CHECK(std::isinf(estimate(r, "ed0").sigma));
  CHECK(estimate(r, "ed0").how.find("0.6 e_c0") != std::string::npos);
  CHECK(estimate(r, "ei0").value == Approx(calibration::kEi0OverEc0 * estimate(r, "ec0").value));
  for (const std::string key : {"phi_c_deg", "ec0", "alpha"}) CHECK(estimate(r, key).identified);
  CHECK(estimate(r, "phi_c_deg").value == Approx(31.0).margin(0.05));
  CHECK(estimate(r, "ec0").value == Approx(0.96).margin(0.015));  // traded against h_s, n
  // The factors stand in for e_d0 and e_i0 (true 0.635 and 1.135 e_c0 for Hostun, taken as 0.6
  // and 1.2): e_c0 is biased by them (0.949 against 0.96), far beyond its statistical sigma
  // (3.6e-4); its sigma carries the factors' share and covers the miss.
  const auto& ec0 = estimate(r, "ec0");
  INFO("e_c0 " << ec0.value << " +- " << ec0.sigma << " (statistical " << ec0.sigma_statistical
               << ", systematic " << ec0.sigma_systematic << ")");
  CHECK(std::abs(ec0.value - 0.96) > 3.0 * ec0.sigma_statistical);
  CHECK(std::abs(ec0.value - 0.96) <= 3.0 * ec0.sigma);
  CHECK(std::abs(estimate(r, "alpha").value - 0.13) <= 3.0 * estimate(r, "alpha").sigma);
}

// A fit of the DEM soil cells takes 25 s to 25 min and printed nothing until its end. With a
// period of 0 it reports every evaluation, so the lines are the evaluations one for one, in the
// order the recipe runs its stages and then the joint fit, each naming its phase of all.
TEST_CASE("a calibration reports its progress: each phase of the recipe, then the joint fit",
          "[calibration]") {
  std::vector<soil_test::SoilTest> tests = {
      target(SoilTestKind::kSimpleShear, BoundaryKind::kCNL, 0.90, "loose CNL"),
      target(SoilTestKind::kSimpleShear, BoundaryKind::kCV, 0.88, "loose CV")};
  std::vector<std::string> lines;
  calibration::CalibrationOptions o;
  o.progress = [&lines](const std::string& l) { lines.push_back(l); };
  o.progress_every_s = 0.0;
  o.max_evaluations_per_stage = 20;  // the lines, not the fit, are under test
  o.max_evaluations_joint = 10;
  o.polish_iterations = 2;
  const auto r = calibration::calibrate(tests, o);
  REQUIRE(int(lines.size()) == r.evaluations);
  const std::regex line(
      R"(calibrating: (.+), phase ([0-9]+) of ([0-9]+), evaluation ([0-9]+), RMS [0-9.e+-]+ scatter units, [0-9]+ s)");
  int phase = 0, evaluation = 0;
  for (const auto& l : lines) {
    std::smatch m;
    INFO(l);
    REQUIRE(std::regex_match(l, m, line));
    const bool in_order = std::stoi(m[2]) >= phase && std::stoi(m[2]) <= std::stoi(m[3]) &&
                          std::stoi(m[4]) == evaluation + 1;
    REQUIRE(in_order);  // phases only advance, each within all, evaluations one by one
    phase = std::stoi(m[2]);
    evaluation = std::stoi(m[4]);
  }
  CHECK_THAT(lines.front(), Catch::StartsWith("calibrating: stage "));
  CHECK_THAT(lines.back(), Catch::Contains("joint fit of"));
  const std::string last = lines.back();
  const auto of = last.find(" of ", last.find("phase "));
  CHECK(last.substr(last.find("phase ") + 6, of - last.find("phase ") - 6) ==
        last.substr(of + 4, last.find(',', of) - of - 4));  // the joint fit is the last phase
}

TEST_CASE("a test held out of a fit is predicted: its own set reproduces it, another set does not",
          "[calibration]") {
  const auto truth = test::table_5_2_hostun();
  const auto t = target(SoilTestKind::kSimpleShear, BoundaryKind::kCNL, 0.65, "dense CNL");
  const auto same = calibration::test_fit(t, "vw3d", truth);
  REQUIRE(same.status == "complete");
  REQUIRE(same.rmse.size() == 3);  // e, tau, sigma_n
  for (const auto& c : same.rmse) {
    INFO(c.column);
    CHECK(c.rmse < 1e-9 * (1.0 + std::abs(c.end_measured)));
    CHECK(c.end_model == Approx(c.end_measured).epsilon(1e-9));
  }
  auto other = truth;
  other.tables.at("hypoplastic")["phi_c_deg"] += 2.0;  // more shear stress at the end
  const auto off = calibration::test_fit(t, "vw3d", other);
  CHECK(off.rmse[1].column == "tau_kPa");
  CHECK(off.rmse[1].end_model > off.rmse[1].end_measured);
}

TEST_CASE("a localised cell's low bulk void ratio does not leave the loose tests' starts above e_i",
          "[calibration]") {
  // A DEM cell that localises ends at a stationary bulk e below the critical state line (only its
  // band is at the critical state). Here the loose CNL test, the one that ends at a critical
  // state, has its last fifth 0.3 lower, as if so measured: e_c0 from it (about 0.96 - 0.3) would
  // put e_i at the test's own start below its e0 of 0.90, and a fit starting there would have
  // nothing to follow.
  std::vector<soil_test::SoilTest> tests = {
      target(SoilTestKind::kOedometer, BoundaryKind::kCNL, 0.85, "oedometer"),
      target(SoilTestKind::kSimpleShear, BoundaryKind::kCNL, 0.65, "dense CNL"),
      target(SoilTestKind::kSimpleShear, BoundaryKind::kCNL, 0.90, "loose CNL, localised")};
  auto& loose = tests[2];
  for (std::size_t i = 0; i < loose.rows(); ++i)
    if (loose.control[i] >= 0.8 * loose.control.back()) loose.e[i] -= 0.3;
  // What is asserted happens in the staged fit (C raises the start, D fits alpha and beta); the
  // joint fit after it only has to run on the raised starts, so it gets a short budget (the full
  // one spent 14000 evaluations, two minutes, moving none of the checks below).
  calibration::CalibrationOptions short_joint;
  short_joint.max_evaluations_joint = 20;
  short_joint.polish_iterations = 5;
  const auto r = calibration::calibrate(tests, short_joint);
  const auto truth = test::table_5_2_hostun().tables.at("hypoplastic");
  explain(r, truth);
  bool raised = false;
  double density_stage_rms =
      NAN;  // "D: alpha = .., beta = .. from all tests, RMS residual X (...)"
  for (const auto& n : r.notes) {
    raised = raised || n.find("raised from") != std::string::npos;
    if (n.rfind("D:", 0) == 0)
      density_stage_rms = std::stod(n.substr(n.find("RMS residual ") + 13));
  }
  CHECK(raised);
  // alpha and beta are fitted from starts every test admits: without the raise the loose test is
  // refused at every trial and the stage ends on the bounds of alpha and beta at RMS ~780
  CHECK(density_stage_rms < 50.0);
  for (const auto& t : r.tests) {
    INFO(t.name << ": " << t.status);
    CHECK(t.status.rfind("refused", 0) != 0);
  }
}

TEST_CASE("the truth grains' 27 DEM soil tests calibrate with every parameter identified",
          "[calibration][heavy]") {
  // The committed soil tests of data/calibration/truth_grains_epsd2/ (three seeds, the held-out
  // design left out), as `make.sh calibrate` fits them. One of them ends at a stationary bulk e
  // below the critical state line (a localised cell): from that start the fit stopped at RMS 756
  // with alpha, beta and phi_c unidentified until the start was made admissible.
  std::vector<soil_test::SoilTest> tests;
  for (const auto& seed :
       std::filesystem::directory_iterator("data/calibration/truth_grains_epsd2"))
    if (seed.path().filename().string().rfind("seed", 0) == 0)
      for (const auto& t : std::filesystem::directory_iterator(seed.path()))
        if (t.path().filename() != "simpleshear-CNL-dense-200")
          tests.push_back(soil_test::read_soil_test(t.path()));
  REQUIRE(tests.size() == 27);
  calibration::measure_seed_scatter(tests);
  const auto r = calibration::calibrate(tests);
  for (const auto& n : r.notes) UNSCOPED_INFO(n);
  CHECK(r.s2 < 9.0);  // RMS below 3 scatter units
  for (const auto& p : r.parameters) {
    INFO(p.key << " = " << p.value << ": " << p.how);
    CHECK(p.identified);
  }
}
