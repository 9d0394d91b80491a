// The intergranular strain calibrated on cyclic soil tests (issue 34 item 3): from synthetic
// cyclic simple-shear tests made by vw3d-igs with seed Table 5.3 Toyoura, the fit of
// [intergranular_strain] with [hypoplastic] held finds R, m_R, m_T, beta_r and chi again within
// the sigmas it reports at the declared scatter, starting from the middle of its boxes.
#include <catch2/catch.hpp>
#include <cmath>

#include "calibration/calibrate.hpp"
#include "calibration/synthetic.hpp"
#include "common/errors.hpp"
#include "support/cyclic_soil_tests.hpp"
#include "support/fixtures.hpp"

using namespace iwb;
using driver::BoundaryKind;

namespace {

// Two amplitudes, one inside the elastic range R = 1e-4 and one well beyond it, under CV and CNL:
// the small one measures the stiffness factors, the large one how fast delta swings (beta_r, chi).
std::vector<soil_test::SoilTest> cyclic_targets() {
  return {test::cyclic_soil_test(BoundaryKind::kCV, 5e-4),
          test::cyclic_soil_test(BoundaryKind::kCV, 2e-3),
          test::cyclic_soil_test(BoundaryKind::kCNL, 5e-4),
          test::cyclic_soil_test(BoundaryKind::kCNL, 2e-3)};
}

calibration::CalibrationOptions igs_options() {
  calibration::CalibrationOptions o;
  o.model = "vw3d-igs";
  o.table = "intergranular_strain";
  o.held["hypoplastic"] = test::table_5_3_toyoura().tables.at("hypoplastic");
  return o;
}

}  // namespace

TEST_CASE("a synthetic intergranular-strain set is recovered from cyclic simple shear",
          "[calibration][cyclic]") {
  const auto r = calibration::calibrate(cyclic_targets(), igs_options());
  const auto truth = test::table_5_3_toyoura_igs();
  for (const auto& n : r.notes) UNSCOPED_INFO(n);
  REQUIRE(r.table == "intergranular_strain");
  REQUIRE(r.parameters.size() == truth.size());
  for (const auto& p : r.parameters) {
    INFO(p.key << " = " << p.value << " +- " << p.sigma_at_scatter << " (true " << truth.at(p.key)
               << ") " << p.how);
    CHECK(p.identified);
    CHECK(std::abs(p.value - truth.at(p.key)) <= p.sigma_at_scatter);
    // noise-free target: the estimate is the truth to the integrator's tolerance
    CHECK(p.value == Approx(truth.at(p.key)).epsilon(1e-3));
  }
  REQUIRE(r.objectives.size() == 1);  // only the cyclic group has residuals
  CHECK(r.objectives.front().group == calibration::ObjectiveGroup::kCyclic);
  // the held table is carried into the result, so that its parameter file runs vw3d-igs
  CHECK(r.inputs().tables.at("hypoplastic") == igs_options().held.at("hypoplastic"));
}

TEST_CASE("fitting the intergranular strain without the hypoplastic set held is refused",
          "[calibration][cyclic]") {
  auto o = igs_options();
  o.held.clear();
  REQUIRE_THROWS_WITH(calibration::calibrate(cyclic_targets(), o),
                      Catch::Contains("[hypoplastic] held") && Catch::Contains("--params"));
  o = igs_options();
  o.table = "barodesy";
  REQUIRE_THROWS_WITH(
      calibration::calibrate(cyclic_targets(), o),
      Catch::Contains("--table barodesy") && Catch::Contains("hypoplastic, intergranular_strain"));
}

TEST_CASE("a synthetic cyclic test is a triangle wave of the amplitude", "[calibration][cyclic]") {
  const auto t = test::cyclic_soil_test(BoundaryKind::kCV, 2e-3);
  // two cycles of four quarters of 12 rows, and the start
  REQUIRE(t.rows() == 2 * 4 * 12 + 1);
  CHECK(t.control.front() == 0.0);
  CHECK(t.control[12] == Approx(2e-3));               // +A after a quarter
  CHECK(t.control[36] == Approx(-2e-3));              // -A after three
  CHECK(t.control[48] == Approx(0.0).margin(1e-15));  // 0 after a cycle
  CHECK(t.control.back() == Approx(0.0).margin(1e-15));
  // constant volume: e never moves; the first reversal unloads (tau falls)
  CHECK(t.e.back() == Approx(t.e.front()));
  CHECK(t.tau_kPa[13] < t.tau_kPa[12]);
}

TEST_CASE("cyclic tests with the cyclic group weighed 0 leave nothing to fit",
          "[calibration][cyclic]") {
  auto o = igs_options();
  o.weights[calibration::ObjectiveGroup::kCyclic] = 0.0;
  REQUIRE_THROWS_WITH(calibration::calibrate({test::cyclic_soil_test(BoundaryKind::kCV, 5e-4)}, o),
                      Catch::Contains("no test gives a residual to a group of weight > 0"));
}

// Seed 5.44's m_T <= m_R, declared as the table's order: a target on the order (m_T = m_R) is found
// from inside the box although every trial beyond it would be refused by the model: the fit
// moves m_T as its share below m_R, so that no trial meets that wall of refusals.
TEST_CASE("a target on the order m_T = m_R is recovered, held by the declared order",
          "[calibration][cyclic]") {
  auto truth = test::table_5_3_toyoura();
  truth.tables.at("intergranular_strain")["m_T"] = 5.0;  // = m_R
  std::vector<soil_test::SoilTest> tests;
  for (const auto bc : {BoundaryKind::kCV, BoundaryKind::kCNL})
    for (const double amplitude : {5e-4, 2e-3})
      tests.push_back(test::cyclic_soil_test(bc, amplitude, truth));
  const auto r = calibration::calibrate(tests, igs_options());
  for (const auto& p : r.parameters) {
    INFO(p.key << " = " << p.value << " (" << p.how << ")");
    CHECK(p.value == Approx(truth.tables.at("intergranular_strain").at(p.key)).epsilon(1e-3));
  }
}
