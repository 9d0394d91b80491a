// The API t-z curve as an interface law (src/models/api_tz): facts derived by hand from the
// backbone the codes publish, not from the code: under CNL the sand curve rises with slope
// t_max / z_peak to t_max = sigma_n tan(delta), reached at u = z_peak, and stays there; no
// dilatancy, so sigma_n stays put under CV and CNS; an imposed normal strain moves tau with t_max;
// unloading is elastic at the initial slope; the clay curve passes through the published z/D
// points; the increment's Dual derivative is its central difference.
#include <catch2/catch.hpp>
#include <cmath>

#include "analysis/stability.hpp"
#include "models/registry.hpp"
#include "support/fixtures.hpp"
#include "support/increment_derivative.hpp"

using namespace iwb;
using driver::BoundaryKind;

namespace {

constexpr double kDelta = 32.0, kZPeak = 2.54, kKn = 1.0e5;  // data/params/api_tz_sand.toml
const double kTanDelta = std::tan(kDelta * M_PI / 180.0);
const double kTMax = 100.0 * kTanDelta;  // at the gold paths' 100 kPa

// The sand backbone (API: linear to t_max at z_peak, flat after), at 100 kPa.
double sand_curve(double u_mm) {
  return kTMax * std::min(u_mm / kZPeak, 1.0);
}

models::ModelInputs api_inputs(double shape, double z_peak_mm, double t_res, double d_s_mm) {
  models::ModelInputs in{{{"api_tz",
                           {{"delta_deg", kDelta},
                            {"z_peak_mm", z_peak_mm},
                            {"shape", shape},
                            {"t_res_ratio", t_res},
                            {"k_n_kPa_per_mm", kKn}}}},
                         "test",
                         {}};
  in.shear_zone_mm = d_s_mm;
  return in;
}

test::Run shear_api(driver::BoundaryCondition bc, double d_s_mm) {
  test::ShearSpec s;
  s.model = "api-tz";
  s.inputs = test::shipped("api_tz_sand.toml");
  s.inputs.shear_zone_mm = d_s_mm;
  s.bc = bc;
  s.gamma = 4.0 / d_s_mm;  // 4 mm of slip
  s.increments = 400;
  auto r = test::shear(s);
  REQUIRE(r.result.complete());
  return r;
}

// Slides the state by `du_mm` in `steps` equal increments of pure shear (d_s = `d_s_mm`).
models::StateVector slide(const models::Model& m, models::StateVector s, double du_mm, int steps,
                          double d_s_mm) {
  models::StateVector out(s.size());
  for (int i = 0; i < steps; ++i) {
    m.update(s, {0.0, du_mm / steps / d_s_mm, 0.0}, out);
    s = out;
  }
  return s;
}

models::StateVector at_rest(double sigma_n) {
  models::StateVector s(4);
  s << -sigma_n, 0.0, 0.0, 0.0;
  return s;
}

}  // namespace

TEST_CASE("api-tz under CNL: slope t_max / z_peak, t_max = sigma_n tan(delta) from u = z_peak on",
          "[models]") {
  for (double d_s : {1.0, 2.5}) {  // the same curve in displacement
    INFO("d_s = " << d_s << " mm");
    const auto r = shear_api({BoundaryKind::kCNL, 0.0}, d_s);
    const auto& rows = r.result.rows;
    bool peak_seen = false;
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const double u = rows[i].gamma_x * d_s, tau = r.model->stress(rows[i].state).tau_x;
      INFO("u = " << u << " mm");
      CHECK(tau == Approx(sand_curve(u)).epsilon(1e-12).margin(1e-12));
      CHECK(rows[i].eps_n == 0.0);  // no dilatancy: nothing moves u_n under CNL
      if (u >= kZPeak * (1.0 + 1e-12)) {
        CHECK(tau == Approx(kTMax).epsilon(1e-14));  // the strength, to round-off
        CHECK(r.diagnostic("mobilisation", i) == Approx(1.0).epsilon(1e-14));
        if (!peak_seen) {  // the first row past z_peak: the one before was still rising
          CHECK(r.model->stress(rows[i - 1].state).tau_x < kTMax);
          peak_seen = true;
        }
      }
    }
    CHECK(peak_seen);
    // the slope before the peak, from the first increment: t_max / z_peak
    const double u1 = rows[1].gamma_x * d_s;
    CHECK(r.model->stress(rows[1].state).tau_x / u1 == Approx(kTMax / kZPeak).epsilon(1e-12));
  }
}

TEST_CASE("api-tz under CV and CNS keeps sigma_n (no dilatancy) and follows the CNL curve",
          "[models]") {
  for (const driver::BoundaryCondition bc :
       {driver::BoundaryCondition{BoundaryKind::kCV, 0.0},
        driver::BoundaryCondition{BoundaryKind::kCNS, 2000.0}}) {
    const auto r = shear_api(bc, 1.0);
    for (const auto& row : r.result.rows) {
      const auto st = r.model->stress(row.state);
      CHECK(st.sigma_n == Approx(100.0).epsilon(1e-12));
      CHECK(st.tau_x == Approx(sand_curve(row.gamma_x)).epsilon(1e-12).margin(1e-12));
    }
  }
}

TEST_CASE("api-tz: an imposed normal strain moves t_max, and tau with it at the same t / t_max",
          "[models]") {
  const auto m = models::find_model("api-tz").make(api_inputs(0.0, kZPeak, 1.0, 1.0));
  models::StateVector out(4);
  // sliding at the peak: tau stays sigma_n' tan(delta) at the new sigma_n' = 100 - k_n du_n
  const auto sliding = slide(*m, at_rest(100.0), 4.0, 40, 1.0);
  REQUIRE(sliding(1) == Approx(kTMax).epsilon(1e-14));
  const double du_n = 1.0e-4;  // mm of opening: -10 kPa
  m->update(sliding, {du_n, 0.1, 0.0}, out);
  CHECK(-out(0) == Approx(100.0 - kKn * du_n).epsilon(1e-14));
  CHECK(out(1) == Approx((100.0 - kKn * du_n) * kTanDelta).epsilon(1e-14));
  m->update(sliding, {-du_n, 0.1, 0.0}, out);  // closing: +10 kPa, still at the peak
  CHECK(out(1) == Approx((100.0 + kKn * du_n) * kTanDelta).epsilon(1e-14));
  // before the peak (u = z_peak / 2): t / t_max = 1/2 is kept when only sigma_n changes
  const auto rising = slide(*m, at_rest(100.0), kZPeak / 2.0, 10, 1.0);
  m->update(rising, {du_n, 0.0, 0.0}, out);
  CHECK(out(1) == Approx(0.5 * (100.0 - kKn * du_n) * kTanDelta).epsilon(1e-13));
}

TEST_CASE("api-tz unloads at the initial slope and slides back at -t_max after 2 z_peak",
          "[models]") {
  const auto m = models::find_model("api-tz").make(api_inputs(0.0, kZPeak, 1.0, 1.0));
  const double u1 = 5.0;  // mm, past the peak
  auto s = slide(*m, at_rest(100.0), u1, 500, 1.0);
  REQUIRE(s(1) == Approx(kTMax).epsilon(1e-14));
  CHECK(s(3) == Approx(u1 - kZPeak).epsilon(1e-12));  // the slip beyond the elastic z_peak
  for (double back : {0.5, 2.0, 2 * kZPeak - 0.01, 2 * kZPeak + 0.5, 4.0 * kZPeak}) {
    const auto t = slide(*m, s, -back, 200, 1.0);
    const double expected = std::max(kTMax - kTMax / kZPeak * back, -kTMax);
    INFO("reversed by " << back << " mm");
    CHECK(t(1) == Approx(expected).epsilon(1e-11).margin(1e-11));
  }
}

TEST_CASE("api-tz with the clay shape passes through the published z/D points", "[models]") {
  const double D = 600.0, t_res = 0.8;  // mm; t_res / t_max within API's 0.70-0.90
  const auto m = models::find_model("api-tz").make(api_inputs(1.0, 0.01 * D, t_res, 1.0));
  const double step = 1e-4 * D;  // every published z/D is a whole number of steps
  struct Point {
    int steps;
    double t_over_tmax;
  };
  // API RP 2GEO (README.md): z/D 0.0016 ... 0.0100, then t_res at 0.0200 and beyond; 0.0150 halfway
  for (const Point p :
       {Point{16, 0.30}, Point{31, 0.50}, Point{57, 0.75}, Point{80, 0.90}, Point{100, 1.00},
        Point{150, 0.5 * (1.0 + t_res)}, Point{200, t_res}, Point{300, t_res}}) {
    const auto s = slide(*m, at_rest(100.0), p.steps * step, p.steps, 1.0);
    INFO("z/D = " << p.steps * 1e-4);
    CHECK(s(1) / kTMax == Approx(p.t_over_tmax).epsilon(1e-12));
  }
  // unloading from z/D = 0.0057 at the initial slope 0.30 t_max / (0.0016 D)
  const auto loaded = slide(*m, at_rest(100.0), 57 * step, 57, 1.0);
  const auto back = slide(*m, loaded, -10 * step, 10, 1.0);
  CHECK((loaded(1) - back(1)) / (10 * step) == Approx(0.30 * kTMax / (0.0016 * D)).epsilon(1e-12));
}

TEST_CASE("api-tz: the closed-form increment's Dual derivative is its central difference",
          "[models]") {
  for (double shape : {0.0, 1.0}) {
    const auto m = models::find_model("api-tz").make(api_inputs(shape, 2.0, 0.8, 1.0));
    models::StateVector s(4);
    s << -100.0, 20.0, 5.0, 0.1;  // inside; the increments below load, cross and unload
    const std::vector<models::InterfaceStrain> increments{
        {1e-5, 0.5, 0.1}, {-2e-5, 3.0, 0.0}, {3e-6, -0.2, 0.05}};
    test::check_increment_derivative(*m, s, increments, 1e-9, 1e-6, 1e-6);
    for (const auto& d : increments) {  // and in the shear, what a pile's Newton needs
      models::StateVectorT<Dual> sd = s.cast<Dual>(), out;
      m->update(sd, {Dual(d.eps_n), make_variable(d.gamma_x), Dual(d.gamma_y)}, out);
      models::StateVector up, down;
      const double h = 1e-7;
      m->update(s, {d.eps_n, d.gamma_x + h, d.gamma_y}, up);
      m->update(s, {d.eps_n, d.gamma_x - h, d.gamma_y}, down);
      for (int i = 0; i < 4; ++i)
        CHECK(derivative_of(out(i)) ==
              Approx((up(i) - down(i)) / (2 * h)).epsilon(1e-6).margin(1e-6));
    }
  }
}

TEST_CASE("api-tz refuses a shape other than 0 or 1 and a start without compression", "[models]") {
  const auto& spec = models::find_model("api-tz");
  CHECK_THROWS_WITH(spec.make(api_inputs(0.5, kZPeak, 1.0, 1.0)),
                    Catch::Contains("shape = 0.5 is neither 0"));
  const auto m = spec.make(api_inputs(0.0, kZPeak, 1.0, 1.0));
  CHECK_THROWS_WITH(m->initial_state({0.0, 1.0, 0.8}), Catch::Contains("needs compression"));
}

TEST_CASE("api-tz: the stability sweep completes every point, finite", "[models]") {
  const auto& spec = models::find_model("api-tz");
  CHECK(analysis::density_axis_of(spec) == analysis::DensityAxis::kNone);
  const auto results =
      analysis::run_stability_sweep(spec, test::shipped(spec.declaration.example_parameters),
                                    analysis::StabilitySweep::reduced());
  CHECK(results.size() == 27);  // 3 BCs x 3 stresses x (2 increment sizes + 1 cyclic)
  for (const auto& r : results) {
    INFO(driver::to_string(r.point.boundary)
         << " " << r.point.sigma_n_kPa << " kPa: " << r.message);
    CHECK(r.outcome == analysis::Outcome::kComplete);
    CHECK(std::isfinite(r.tau_end_kPa));
  }
}
