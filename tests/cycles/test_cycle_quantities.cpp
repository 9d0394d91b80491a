// The per-cycle quantities on a constructed loop whose answers are known in closed form: an
// elastic-perfectly plastic interface (stiffness k, strength tau_y) driven through the wall's
// program, with sigma_n, u_n and the band's void ratio prescribed as functions of the travel.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

#include "common/errors.hpp"
#include "cycles/cycle_quantities.hpp"

using namespace iwb;

namespace {

constexpr double kA = 1.0, kK = 80.0,
                 kTauY = 10.0;  // mm, kPa/mm, kPa: elastic over 2 tau_y / k = 0.25 mm
constexpr int kCycles = 3;
constexpr double kPost = 2.0;
// a row spacing that puts no row on a reversal nor on a cycle's end
constexpr double kRowTravel = 0.00137;

double triangle(double s) {  // the wall's program as a function of its travel
  const double cycles = 4.0 * kA * kCycles;
  if (s >= cycles) return s - cycles;
  const double phase = s / kA;
  return kA * (std::abs(std::fmod(phase + 3.0, 4.0) - 2.0) - 1.0);
}
double sigma_n_of(double s) {
  return 50.0 * std::exp(-s / 20.0);
}
double u_n_of(double s) {
  return 0.01 * s;
}
double e_band_of(double s) {
  return 0.7 + 0.001 * s;
}

cycles::Path loop() {
  cycles::Path p;
  double tau = 0.0;
  for (double s = 0.0; s <= 4.0 * kA * kCycles + kPost + 1e-12; s += kRowTravel) {
    const double u = triangle(s);
    if (!p.u_x_mm.empty()) tau = std::clamp(tau + kK * (u - p.u_x_mm.back()), -kTauY, kTauY);
    p.travel_mm.push_back(s), p.u_x_mm.push_back(u), p.tau_kPa.push_back(tau),
        p.sigma_n_kPa.push_back(sigma_n_of(s));
    p.u_n_mm.push_back(u_n_of(s)), p.e_band.push_back(e_band_of(s));
  }
  return p;
}

const cycles::Program kProgram{kA, kCycles, kPost};

}  // namespace

TEST_CASE("an elastic-perfectly plastic loop: peaks, degradation, ratcheting, stiffness, energy",
          "[cycles]") {
  const auto q = cycles::cyclic_quantities(loop(), kProgram);
  REQUIRE(q.cycles.size() == std::size_t(kCycles));
  CHECK(q.sigma_n0_kPa == Approx(50.0));
  // a row is within k h = 0.11 kPa of the corner it straddles
  const double tau_margin = kK * kRowTravel;
  for (const auto& c : q.cycles) {
    INFO("cycle " << c.number);
    const double end = 4.0 * kA * c.number;
    // tau = +tau_y last at the cycle's end (u_x = 0 going up), -tau_y last at the reversal at -A;
    // sigma_n falls, so those are the peaks of tau/sigma_n
    CHECK(c.peak_friction_positive == Approx(kTauY / sigma_n_of(end)).epsilon(1e-3));
    CHECK(c.peak_friction_negative == Approx(kTauY / sigma_n_of(end - kA)).epsilon(1e-3));
    CHECK(c.sigma_n_end_kPa == Approx(sigma_n_of(end)).epsilon(1e-6));
    CHECK(c.sigma_n_ratio == Approx(std::exp(-end / 20.0)).epsilon(1e-6));
    CHECK(c.u_n_end_mm == Approx(u_n_of(end)).epsilon(1e-6));
    CHECK(c.u_n_increment_mm == Approx(0.04).epsilon(1e-6));
    REQUIRE(c.e_band_end.has_value());
    CHECK(*c.e_band_end == Approx(e_band_of(end)).epsilon(1e-6));
    // after a reversal: elastic over 0.1 A (secant k), plastic before 0.5 A (secant 2 tau_y / 0.5
    // A)
    for (const auto* r : {&c.at_plus, &c.at_minus}) {
      CHECK(r->secant_10_kPa_per_mm == Approx(kK).margin(tau_margin / (0.1 * kA)));
      CHECK(r->secant_50_kPa_per_mm ==
            Approx(2.0 * kTauY / (0.5 * kA)).margin(tau_margin / (0.5 * kA)));
      CHECK(std::abs(r->tau_kPa) == Approx(kTauY).margin(tau_margin));
    }
    CHECK(c.at_plus.u_x_mm == kA);
    CHECK(c.at_minus.u_x_mm == -kA);
    REQUIRE(c.at_plus.e_band.has_value());
    CHECK(*c.at_plus.e_band == Approx(e_band_of(end - 3.0 * kA)).epsilon(1e-6));
    // the loop's area: 4 tau_y A - 4.5 tau_y^2 / k from the virgin start, then the closed
    // parallelogram 4 tau_y (A - tau_y / k)
    const double area =
        c.number == 1 ? 4 * kTauY * kA - 4.5 * kTauY * kTauY / kK : 4 * kTauY * (kA - kTauY / kK);
    CHECK(c.dissipated_energy_J_m2 ==
          Approx(area).margin(4 * tau_margin * kRowTravel + 1e-3 * area));
  }
  REQUIRE(q.post_cyclic.has_value());
  const double end = 4.0 * kA * kCycles + kPost;
  CHECK(q.post_cyclic->peak_friction == Approx(kTauY / sigma_n_of(end)).epsilon(1e-3));
  CHECK(q.post_cyclic->u_x_at_peak_mm == Approx(kPost).margin(kRowTravel));
  CHECK(q.post_cyclic->u_n_change_mm == Approx(u_n_of(end) - u_n_of(end - kPost)).epsilon(1e-3));
}

void keep_rows(cycles::Path& p, std::size_t keep) {
  for (auto* v : {&p.travel_mm, &p.u_x_mm, &p.u_n_mm, &p.sigma_n_kPa, &p.tau_kPa, &p.e_band})
    v->resize(keep);
}

TEST_CASE("a run's last row short of its end by less than a row spacing still ends its last cycle",
          "[cycles]") {
  auto p = loop();
  keep_rows(p, std::size_t(4.0 * kA * kCycles / kRowTravel) + 1);  // the last row 0.00017 mm short
  REQUIRE(p.travel_mm.back() < 4.0 * kA * kCycles);
  const auto q = cycles::cyclic_quantities(p, kProgram);
  CHECK(q.cycles.size() == std::size_t(kCycles));
  CHECK_FALSE(q.post_cyclic.has_value());
}

TEST_CASE("cycles the rows do not reach are left out, and a path that is not cyclic is refused",
          "[cycles]") {
  auto p = loop();
  keep_rows(p, std::size_t(6.0 * kA / kRowTravel));  // one and a half cycles
  const auto q = cycles::cyclic_quantities(p, kProgram);
  CHECK(q.cycles.size() == 1);
  CHECK_FALSE(q.post_cyclic.has_value());
  CHECK_THROWS_AS(cycles::cyclic_quantities(p, {0.0, 3, 0.0}), InputError);
  std::swap(p.travel_mm[3], p.travel_mm[4]);
  CHECK_THROWS_WITH(cycles::cyclic_quantities(p, kProgram),
                    Catch::Contains("travel of a cyclic path decreases"));
  p.tau_kPa.pop_back();
  CHECK_THROWS_WITH(cycles::cyclic_quantities(p, kProgram), Catch::Contains("differ in length"));
}
