// The calibration's objective groups (issue 38 item 3): the peak dilatancy rate against paths of
// known slope, what each group takes from each kind of test, and the weights' refusals.
#include <catch2/catch.hpp>
#include <cmath>

#include "calibration/objectives.hpp"
#include "common/errors.hpp"

using namespace iwb;
using calibration::ObjectiveGroup;

namespace {

// e = e0 + k (1 + e0) gamma up to gamma_knee, constant after: eps_n = k gamma there, so every
// window inside the ramp has the slope k exactly, and windows straddling the knee less.
soil_test::SoilTest ramp_then_flat(double e0, double k, double gamma_knee,
                                   driver::BoundaryKind bc = driver::BoundaryKind::kCNL) {
  soil_test::SoilTest t;
  t.kind = soil_test::SoilTestKind::kSimpleShear;
  t.boundary = bc;
  t.sigma0_kPa = 50.0, t.e0 = e0;
  for (int i = 0; i <= 200; ++i) {
    const double g = 0.0025 * i;
    t.control.push_back(g);
    t.e.push_back(e0 + k * (1.0 + e0) * std::min(g, gamma_knee));
    t.tau_kPa.push_back(30.0), t.sigma_n_kPa.push_back(50.0), t.eps_v.push_back(0.0);
  }
  return t;
}

calibration::Simulated as_measured(const soil_test::SoilTest& t) {
  calibration::Simulated s;
  s.tau_kPa = t.tau_kPa, s.sigma_n_kPa = t.sigma_n_kPa, s.eps_v = t.eps_v, s.e = t.e;
  return s;
}

}  // namespace

TEST_CASE("the peak dilatancy rate is the slope d eps_n / d gamma of the steepest window",
          "[calibration]") {
  const auto t = ramp_then_flat(0.65, 0.27, 0.2);
  CHECK(calibration::peak_dilatancy_rate(t.control, t.e, t.rows()) == Approx(0.27).epsilon(1e-12));
  // the first rows only: the same slope, before the knee
  CHECK(calibration::peak_dilatancy_rate(t.control, t.e, 20) == Approx(0.27).epsilon(1e-12));
  // contraction throughout: the peak is the least negative slope, -0.05
  const auto c = ramp_then_flat(0.85, -0.05, 1.0);
  CHECK(calibration::peak_dilatancy_rate(c.control, c.e, c.rows()) == Approx(-0.05).epsilon(1e-12));
  // A ramp shorter than the window: no window lies inside it, so the peak is below its slope but
  // above the share of the ramp a window holds (0.01 of 0.04 -> a quarter)
  const auto short_ramp = ramp_then_flat(0.65, 0.3, 0.01);
  const double r = calibration::peak_dilatancy_rate(short_ramp.control, short_ramp.e, 201);
  CHECK(r < 0.3);
  CHECK(r > 0.25 * 0.3);
}

TEST_CASE("the dilatancy group judges a CNL test's peak rate and end, and nothing else",
          "[calibration]") {
  const auto t = ramp_then_flat(0.65, 0.27, 0.2);
  std::vector<double> r;
  calibration::append_group_residuals(ObjectiveGroup::kDilatancy, t, as_measured(t), r);
  REQUIRE(r.size() == 2);
  CHECK(r[0] == Approx(0.0).margin(1e-9));
  CHECK(r[1] == Approx(0.0).margin(1e-9));
  r.clear();
  // a model dilating as fast but for longer, to an end 0.004 looser: the same rate, the end 2
  // declared scatters (0.002) off
  const auto longer = ramp_then_flat(0.65, 0.27, 0.2 + 0.004 / (0.27 * 1.65));
  calibration::append_group_residuals(ObjectiveGroup::kDilatancy, t, as_measured(longer), r);
  CHECK(r[0] == Approx(0.0).margin(1e-9));
  CHECK(r[1] == Approx(2.0));
  // a model dilating at 0.37 instead: one declared rate scatter is 0.01, so 10 units
  auto faster = ramp_then_flat(0.65, 0.37, 0.2);
  r.clear();
  calibration::append_group_residuals(ObjectiveGroup::kDilatancy, t, as_measured(faster), r);
  CHECK(r[0] == Approx((0.37 - 0.27) / calibration::kDilatancyRateScale));
  // a CV test has no dilatancy residual (its dilatancy is in sigma_n, the shear group); a model
  // that stopped early leaves two unreached residuals
  r.clear();
  const auto cv = ramp_then_flat(0.65, 0.0, 0.2, driver::BoundaryKind::kCV);
  calibration::append_group_residuals(ObjectiveGroup::kDilatancy, cv, as_measured(cv), r);
  CHECK(r.empty());
  auto stopped = as_measured(t);
  stopped.e.resize(50);
  calibration::append_group_residuals(ObjectiveGroup::kDilatancy, t, stopped, r);
  CHECK(r.size() == 2);
  // the path groups: a shear test gives two residuals a row after the start (tau and e under
  // CNL) to the shear group and none to the oedometer group
  r.clear();
  calibration::append_group_residuals(ObjectiveGroup::kOedometer, t, as_measured(t), r);
  CHECK(r.empty());
  calibration::append_group_residuals(ObjectiveGroup::kShear, t, as_measured(t), r);
  CHECK(r.size() == 2 * (t.rows() - 1));
}

TEST_CASE("objective weights are parsed and bad ones refused naming the item", "[calibration]") {
  const auto w = calibration::parse_weights({"dilatancy=10", "oedometer=0.5"});
  CHECK(w[ObjectiveGroup::kDilatancy] == 10.0);
  CHECK(w[ObjectiveGroup::kOedometer] == 0.5);
  CHECK(w[ObjectiveGroup::kShear] == 1.0);
  const auto refused = [](std::vector<std::string> items, const std::string& words) {
    INFO(items.front());
    CHECK_THROWS_WITH(calibration::parse_weights(items), Catch::Contains(words));
  };
  refused({"dilation=2"}, "unknown objective group 'dilation'");
  refused({"shear=-1"}, "--weight shear=-1: the weight must be a finite number >= 0");
  refused({"shear=nan"}, "shear=nan");
  refused({"shear=2x"}, "shear=2x");
  refused({"shear"}, "expected GROUP=WEIGHT");
  refused({"shear=1", "shear=2"}, "weighted twice");
  refused({"shear=0", "oedometer=0", "dilatancy=0", "cyclic=0"},
          "every objective group has weight 0");
}
