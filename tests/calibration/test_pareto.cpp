// The Pareto front between objective groups (issue 38 item 3): on targets one parameter set made,
// the point at the given weights finds that set again; on two groups made by different sets, the
// front trades one group's misfit against the other's monotonically.
#include <catch2/catch.hpp>
#include <cmath>

#include "calibration/pareto.hpp"
#include "calibration/synthetic.hpp"
#include "common/errors.hpp"
#include "support/fixtures.hpp"

using namespace iwb;
using calibration::ObjectiveGroup;
using driver::BoundaryKind;
using soil_test::SoilTestKind;

namespace {

soil_test::SoilTest synthetic_test(SoilTestKind kind, BoundaryKind bc, double e0,
                                   const models::ModelInputs& set) {
  calibration::SyntheticSpec s;
  s.kind = kind, s.boundary = bc, s.e0 = e0;
  if (kind == SoilTestKind::kOedometer)
    s.sigma0_kPa = 10.0, s.sigma_max_kPa = 2000.0, s.sigma_end_kPa = 100.0, s.rows = 20;
  else
    s.gamma_max = 1.0, s.rows = 40;
  auto t = calibration::synthesise(s, set);
  t.name = fmt::format("{} {} e0 {}", to_string(kind), driver::to_string(bc), e0);
  return t;
}

std::vector<soil_test::SoilTest> design(const models::ModelInputs& oedometer_set,
                                        const models::ModelInputs& shear_set) {
  return {synthetic_test(SoilTestKind::kOedometer, BoundaryKind::kCNL, 0.85, oedometer_set),
          synthetic_test(SoilTestKind::kSimpleShear, BoundaryKind::kCNL, 0.65, shear_set),
          synthetic_test(SoilTestKind::kSimpleShear, BoundaryKind::kCNL, 0.90, shear_set),
          synthetic_test(SoilTestKind::kSimpleShear, BoundaryKind::kCV, 0.70, shear_set)};
}

void describe_front(const calibration::ParetoFront& f) {
  for (const auto& p : f.points)
    UNSCOPED_INFO("share " << p.share << (p.given ? " (given)" : "") << ": " << to_string(f.a)
                           << " " << p.rms_a << ", " << to_string(f.b) << " " << p.rms_b
                           << ", evaluations " << p.result.evaluations);
  for (const auto& n : f.notes) UNSCOPED_INFO(n);
}

}  // namespace

TEST_CASE("a front over targets of one set finds the set at the point that weights every group",
          "[calibration]") {
  const auto hostun = test::table_5_2_hostun();
  const auto truth = hostun.tables.at("hypoplastic");
  const auto tests = design(hostun, hostun);
  const auto f = calibration::trace_front(tests, {}, ObjectiveGroup::kOedometer,
                                          ObjectiveGroup::kDilatancy, 4);
  describe_front(f);
  REQUIRE(f.points.size() == 5);  // four ratios about the given one, and the given
  const auto& given = f.given();
  // Every group weight 1: the oedometer's 20 loading and 10 unloading steps (30 residuals after
  // its start) against 2 dilatancy residuals for each of the 2 CNL tests
  CHECK(given.share == Approx(30.0 / 34.0));
  for (const auto& p : given.result.parameters) {
    INFO(p.key << " = " << p.value << " +- " << p.sigma << ", true " << truth.at(p.key));
    CHECK(std::abs(p.value - truth.at(p.key)) <= std::max(3.0 * p.sigma, 1e-4 * truth.at(p.key)));
  }
  // one set made every group: every point of the front fits both to the integrator's noise
  for (const auto& p : f.points) {
    CHECK(p.rms_a < 1e-3);
    CHECK(p.rms_b < 1e-3);
  }
}

// The oedometer made with h_s 1 MPa, the shear tests with 4 MPa: no h_s and n fit both, so more
// weight on the oedometer buys its fit with the shear tests'. Only h_s and n are free, the rest
// fixed at Hostun's values (which both sets share). The shear paths are some 1e5 times more
// sensitive to h_s in mean square than the oedometer (first runs: at even weights the oedometer
// RMS stayed at 10.6 of 10.6, and it fell halfway only near a ratio of 1e5), so the shear group
// is given weight 1e-5 to centre the front's six decades on the trade.
TEST_CASE("a front between two conflicting groups is monotonic", "[calibration]") {
  const auto hostun = test::table_5_2_hostun();
  auto stiffer = hostun;
  stiffer.tables["hypoplastic"]["hs_kPa"] = 4e6;
  const auto tests = design(hostun, stiffer);
  calibration::CalibrationOptions o;
  o.weights[ObjectiveGroup::kShear] = 1e-5;
  o.fixed = hostun.tables.at("hypoplastic");
  o.fixed.erase("hs_kPa"), o.fixed.erase("n");
  const auto f =
      calibration::trace_front(tests, o, ObjectiveGroup::kOedometer, ObjectiveGroup::kShear, 4);
  describe_front(f);
  REQUIRE(f.points.size() == 5);  // the given ratio r_0 times 10^-3, 10^-1, 10, 10^3, and r_0
  CHECK(f.notes.empty());         // the path found no local optimum
  for (std::size_t i = 1; i < f.points.size(); ++i) {
    INFO("shares " << f.points[i - 1].share << " -> " << f.points[i].share);
    CHECK(f.points[i].share > f.points[i - 1].share);
    CHECK(f.points[i].rms_a <= f.points[i - 1].rms_a * (1 + 1e-6));
    CHECK(f.points[i].rms_b >= f.points[i - 1].rms_b * (1 - 1e-6));
  }
  // a real trade: each group fits clearly better at its own end of the front
  CHECK(f.points.back().rms_a < 0.5 * f.points.front().rms_a);
  CHECK(f.points.front().rms_b < 0.5 * f.points.back().rms_b);
  // h_s moves from the shear tests' 4 MPa towards the oedometer's 1 MPa as the share grows
  const auto hs = [](const calibration::ParetoPoint& p) {
    for (const auto& e : p.result.parameters)
      if (e.key == "hs_kPa") return e.value;
    return std::nan("");
  };
  CHECK(hs(f.points.front()) > hs(f.points.back()));
  for (const auto& p : f.points)
    for (const auto& e : p.result.parameters)
      if (e.fixed) CHECK(e.value == o.fixed.at(e.key));
}

TEST_CASE("a front is refused for one group twice, too few points or a group without residuals",
          "[calibration]") {
  const auto hostun = test::table_5_2_hostun();
  const std::vector<soil_test::SoilTest> oedometer_only = {
      synthetic_test(SoilTestKind::kOedometer, BoundaryKind::kCNL, 0.85, hostun)};
  CHECK_THROWS_WITH(calibration::parse_pareto_groups("shear,shear"),
                    Catch::Contains("the two groups must differ"));
  CHECK_THROWS_WITH(calibration::parse_pareto_groups("shear"),
                    Catch::Contains("expected two groups A,B"));
  CHECK_THROWS_WITH(calibration::trace_front(oedometer_only, {}, ObjectiveGroup::kOedometer,
                                             ObjectiveGroup::kShear, 2),
                    Catch::Contains("--points 2"));
  CHECK_THROWS_WITH(calibration::trace_front(oedometer_only, {}, ObjectiveGroup::kOedometer,
                                             ObjectiveGroup::kDilatancy, 3),
                    Catch::Contains("no test given has residuals of group 'dilatancy'"));
  calibration::CalibrationOptions unknown;
  unknown.fixed = {{"phi_c", 30.0}};
  CHECK_THROWS_WITH(calibration::calibrate(oedometer_only, unknown),
                    Catch::Contains("--fix phi_c: [hypoplastic] has no calibrated parameter"));
  calibration::CalibrationOptions outside;
  outside.fixed = {{"n", 1.5}};
  CHECK_THROWS_WITH(calibration::calibrate(oedometer_only, outside),
                    Catch::Contains("--fix n=1.5: outside the declared range"));
}
