// The micro-polar hypoplastic column (src/column/README.md): its homogeneous branch against an
// oracle written outside the workbench, its equilibrium, where its band forms, its convergence
// with the element size, and the plate's conditions.
#include <catch2/catch.hpp>
#include <cmath>

#include "column/column.hpp"
#include "column/column_scene.hpp"
#include "common/errors.hpp"
#include "io/parameter_file.hpp"

using namespace iwb;
using namespace iwb::column;

namespace {

// Herle & Gudehus's (1999) Karlsruhe sand, the oracle's set (tests/column/
// oracle_vw_simple_shear.py): phi_c 30 deg, h_s 5.8 GPa, n 0.28, e_d0 0.53, e_c0 0.84, e_i0 1.00,
// alpha 0.13, beta 1.05.
models::HypoplasticParameters karlsruhe() {
  return {30.0 * M_PI / 180.0, 5.8e6, 0.28, 0.53, 0.84, 1.00, 0.13, 1.05};
}

models::HypoplasticParameters truth_grains() {
  const auto tables = io::load_parameter_file("data/params/truth_grains_epsd2.toml");
  return models::HypoplasticParameters::from(tables.at("hypoplastic"), "truth_grains_epsd2");
}

// The truth scene's column: 14 d50 of 2 mm grains under CNL 50 kPa, 10 mm of travel.
ColumnSpec truth_column(double elements_per_d50, WallRotation wall) {
  ColumnSpec s;
  s.soil = truth_grains();
  s.elements = int(14 * elements_per_d50);
  s.e0 = 0.64;
  s.wall_rotation = wall;
  s.increments = 500;
  return s;
}

double peak_height(const ColumnProfile& p) {
  std::size_t k = 0;
  for (std::size_t j = 1; j < p.shear_rate.size(); ++j)
    if (p.shear_rate[j] > p.shear_rate[k]) k = j;
  return p.z_over_d50[k];
}

}  // namespace

// Without rotations, uniform and untriggered, the column has nothing to localise it: it shears as
// one element of simple shear under CNL. The oracle integrates von Wolffersdorff's law in
// homogeneous simple shear (Jaumann rate, K0 0.5, forward Euler in d gamma 2e-4) and printed for
// e0 0.60 at 100 kPa: peak tau/sigma_n 0.67445 at gamma 0.059; normal strain (dilation positive)
// 0.008445 at gamma 0.1 and 0.030020 at 0.3.
TEST_CASE(
    "column: without rotations or a trigger it shears homogeneously, as von Wolffersdorff's "
    "simple shear of an independent oracle",
    "[column]") {
  ColumnSpec s;
  s.soil = karlsruhe();
  s.d50_mm = 0.5;
  s.height_mm = 7.0;
  s.elements = 7;
  s.e0 = 0.60;
  s.sigma_n0_kPa = 100.0;
  s.polar = false;
  s.travel_mm = 0.3 * s.height_mm;
  s.increments = 1500;
  s.profiles = 1;
  const auto r = run_column(s);
  REQUIRE(r.status == "complete");
  double peak = 0.0, gamma_at_peak = 0.0;
  for (const auto& row : r.rows)
    if (row.tau_kPa / row.sigma_n_kPa > peak) {
      peak = row.tau_kPa / row.sigma_n_kPa;
      gamma_at_peak = row.u_mm / s.height_mm;
    }
  CHECK(peak == Approx(0.67445).margin(0.002));
  CHECK(gamma_at_peak == Approx(0.059).margin(0.004));
  CHECK(r.rows[500].u_n_mm / s.height_mm == Approx(0.008445).margin(3e-4));
  CHECK(r.rows[1500].u_n_mm / s.height_mm == Approx(0.030020).margin(5e-4));
  const auto& p = r.profiles.back();  // the velocity linear over the height it has now
  const double H = s.height_mm + r.rows.back().u_n_mm;
  for (std::size_t j = 0; j < p.z_over_d50.size(); ++j)
    CHECK(p.vx_over_vwall[j] == Approx(1.0 - p.z_over_d50[j] * s.d50_mm / H).margin(1e-6));
}

// The balances the solution must satisfy whatever the law: tau on horizontal planes and sigma_zz
// the same in every element (forces along and across the wall), and between two elements the
// couple stress's step equal to the asymmetric shear over the node's half-elements,
// m_j - m_{j-1} = [L_{j-1} (T12 - T21)_{j-1} + L_j (T12 - T21)_j] / 2 over the elements' lengths
// (moments).
TEST_CASE("column: forces and moments balance in every element and node", "[column]") {
  auto s = truth_column(2.0, WallRotation::kFree);
  s.travel_mm = 4.0;
  s.increments = 200;
  const auto r = run_column(s);
  REQUIRE(r.status == "complete");
  const auto& p = r.profiles.back();
  const double tol = 1e-5 * s.sigma_n0_kPa;
  double largest_moment = 0.0;
  for (std::size_t j = 0; j < p.z_over_d50.size(); ++j) {
    CHECK(p.tau_kPa[j] == Approx(p.tau_kPa[0]).margin(tol));
    CHECK(p.sigma_zz_kPa[j] == Approx(s.sigma_n0_kPa).margin(tol));
    largest_moment = std::max(largest_moment, std::abs(p.m_kPa_mm[j]));
    if (j == 0) continue;
    // tau_zx = -T12, tau_xz = -T21
    const double asym = -p.length_mm[j - 1] * (p.tau_kPa[j - 1] - p.T21_kPa[j - 1]) -
                        p.length_mm[j] * (p.tau_kPa[j] - p.T21_kPa[j]);
    CHECK(p.m_kPa_mm[j] - p.m_kPa_mm[j - 1] == Approx(0.5 * asym).margin(tol * p.length_mm[j]));
  }
  CHECK(largest_moment > 1.0);  // the couple stress is there to be balanced (kPa mm)
}

// Where the band forms follows from the ends alone: a wall whose grains turn freely (m = 0) is
// weaker than the clamped plate (w = 0), so the band forms at the wall; with both ends held the
// column is symmetric under a half-turn about its mid-height, and so is the band.
TEST_CASE(
    "column: a wall that lets its grains turn draws the band to it, two held ends keep it in "
    "the middle",
    "[column]") {
  const auto free = run_column(truth_column(2.0, WallRotation::kFree));
  const auto held = run_column(truth_column(2.0, WallRotation::kFixed));
  REQUIRE(free.status == "complete");
  REQUIRE(held.status == "complete");
  CHECK(peak_height(free.profiles.back()) < 1.0);
  CHECK(peak_height(held.profiles.back()) == Approx(7.0).margin(0.5));
  const auto& p = held.profiles.back();
  const std::size_t n = p.shear_rate.size();
  for (std::size_t j = 0; j < n; ++j)
    CHECK(p.shear_rate[j] == Approx(p.shear_rate[n - 1 - j]).margin(0.02 * p.shear_rate[n / 2]));
}

// The polar terms give the band a width of its own (about d50 times a factor of the soil): it
// holds when the elements are halved. Without them the softening has no length and the band is
// one element, whatever its size (a 1 % looser element at the wall triggers it).
TEST_CASE(
    "column: the band converges with the element size, and without the polar terms it "
    "collapses into one element",
    "[column]") {
  std::vector<double> width, u_n;
  for (double per_d50 : {2.0, 4.0}) {
    const auto r = run_column(truth_column(per_d50, WallRotation::kFree));
    REQUIRE(r.status == "complete");
    width.push_back(band_widths(r.profiles.back()).fwhm_d50);
    u_n.push_back(r.rows.back().u_n_mm);
  }
  INFO("FWHM " << width[0] << ", " << width[1] << " d50; u_n " << u_n[0] << ", " << u_n[1]);
  CHECK(width[1] > 2.0);  // several elements wide
  CHECK(std::abs(width[1] / width[0] - 1.0) < 0.05);
  CHECK(std::abs(u_n[1] / u_n[0] - 1.0) < 0.02);

  std::vector<double> plain_u_n;
  for (double per_d50 : {1.0, 2.0}) {
    auto s = truth_column(per_d50, WallRotation::kFree);
    s.polar = false;
    s.imperfection = 0.01;
    s.travel_mm = 4.0;
    s.increments = 100;
    const auto r = run_column(s);
    REQUIRE(r.status == "complete");
    INFO(per_d50 << " elements per d50");
    // the shear rate's FWHM between element centres is at most one element
    CHECK(band_widths(r.profiles.back()).fwhm_d50 <= 1.0 / per_d50 + 1e-9);
    plain_u_n.push_back(r.rows.back().u_n_mm);
  }
  // and the dilation, all of it in that element, falls with the element's size
  CHECK(plain_u_n[1] < 0.75 * plain_u_n[0]);
}

TEST_CASE("column: under CNS sigma_n rises by K u_n, under CV the plate stays and sigma_n moves",
          "[column]") {
  auto s = truth_column(1.0, WallRotation::kFree);
  s.travel_mm = 2.0;
  s.increments = 100;
  s.top = TopBoundary::kCNS;
  s.stiffness_kPa_per_mm = 200.0;
  const auto cns = run_column(s);
  REQUIRE(cns.status == "complete");
  // to the column's balance: 1e-4 sigma_n0 where Newton stalls (column.cpp)
  for (const auto& row : cns.rows)
    CHECK(row.sigma_n_kPa - 50.0 == Approx(200.0 * row.u_n_mm).margin(5e-3));
  CHECK(cns.rows.back().u_n_mm > 0.01);  // dense: it dilates, and sigma_n with it
  s.top = TopBoundary::kCV;
  const auto cv = run_column(s);
  REQUIRE(cv.status == "complete");
  for (const auto& row : cv.rows) CHECK(row.u_n_mm == 0.0);
  CHECK(cv.rows.back().sigma_n_kPa > 55.0);  // the dilation it is denied raises sigma_n
}

// A wall that slips: its pull on the soil saturates at tan(delta) sigma_n (smoothly, column.cpp),
// so once it slides tau / sigma_n sits at tan(delta) from below, and the slip takes up all the
// wall's travel that the soil above no longer follows.
TEST_CASE("column: a wall slides under the soil once tau reaches tan(delta) sigma_n", "[column]") {
  auto s = truth_column(1.0, WallRotation::kFree);
  s.wall_friction = 0.3;  // below the soil's peak (0.58 on this column without slip)
  s.travel_mm = 4.0;
  s.increments = 200;
  const auto r = run_column(s);
  REQUIRE(r.status == "complete");
  const auto& end = r.rows.back();
  CHECK(end.tau_kPa / end.sigma_n_kPa <= 0.3 + 1e-4);  // to the balance, 1e-4 sigma_n0
  CHECK(end.tau_kPa / end.sigma_n_kPa > 0.299);
  const auto& before = r.rows[r.rows.size() / 2];
  CHECK((end.slip_mm - before.slip_mm) / (end.u_mm - before.u_mm) > 0.99);
}

// The wall's rule from R_n (column_scene.hpp), against numbers computed by hand: eq. 5.35 gives
// kappa_r = 0.25 log10(R_n) + 1.05 = 0.8 at R_n 0.1 and 0.8995 at 0.25; with phi_c 30 deg, sin
// phi_r = kappa_r / 2, and the critical simple-shear ratio of phi_r (the root of sqrt2 eta a / 3 =
// sqrt(1 - eta^2 / 4) - eta / (2 sqrt3), a of phi_r; bisected outside the code) is 0.45004 and
// 0.50265.
TEST_CASE("column: a scene's wall slips at the seed's kappa_r below R_n 0.5 and sticks from it",
          "[column]") {
  const double phi_c = 30.0 * M_PI / 180.0;
  CHECK(std::isinf(wall_from_roughness(0.5, phi_c).friction));
  CHECK(std::isinf(wall_from_roughness(1.0, phi_c).friction));
  CHECK(wall_from_roughness(0.1, phi_c).friction == Approx(0.45004).epsilon(1e-4));
  CHECK(wall_from_roughness(0.25, phi_c).friction == Approx(0.50265).epsilon(1e-4));
  CHECK(wall_from_roughness(0.1, phi_c).rotation == WallRotation::kFree);
}

// The truth scene as a column: 40 mm of specimen less the 12 mm clamped under the plate, 2 mm
// grains, CNL 50 kPa, 10 mm of travel, its sawtooth of R_n 0.5 without slip.
TEST_CASE("column: a DEM scene gives the column its height, grains, plate, travel and wall",
          "[column]") {
  ColumnSpec s;
  s.soil = truth_grains();
  const auto c = on_scene(s, dem::load_scene("data/convergence/truth_clamped/scenes/s1.toml"), 4.0);
  CHECK(c.height_mm == Approx(28.0));
  CHECK(c.d50_mm == Approx(2.0));
  CHECK(c.elements == 56);
  CHECK(c.sigma_n0_kPa == Approx(50.0));
  CHECK(c.top == TopBoundary::kCNL);
  CHECK(c.travel_mm == Approx(10.0));
  CHECK(std::isinf(c.wall_friction));
  CHECK(start_void_ratio({"data/convergence/truth_clamped/runs/s1"}) > 0.6);
}

// The wall zone's void ratio against the plate's rise, by mass alone: a zone of fixed height Z
// above the wall dilating from e0 to e has pushed out of its top the grains that raised the plate
// (at e0, where the soil above it keeps its void ratio), Z (1 + e0) / (Z - u_n) = 1 + e, so
// u_n = Z (e - e0) / (1 + e). With Z the column's height, what leaves the zone is the top u_n of
// a soil that hardly changed (the band is at the wall).
TEST_CASE("column: the wall zone's void ratio carries the plate's rise, by mass alone",
          "[column]") {
  auto s = truth_column(2.0, WallRotation::kFree);
  s.travel_mm = 4.0;
  s.increments = 200;
  CHECK(wall_zone_of(s) == Approx(14.0));  // by default the DEM's: min(10 d50, half the height)
  s.wall_zone_mm = s.height_mm;
  const auto r = run_column(s);
  REQUIRE(r.status == "complete");
  REQUIRE(peak_height(r.profiles.back()) < 1.0);
  CHECK(r.rows.front().e_wall_zone == Approx(s.e0));
  const auto& end = r.rows.back();
  REQUIRE(end.u_n_mm > 0.1);
  const double Z = s.wall_zone_mm;
  CHECK(Z * (end.e_wall_zone - s.e0) / (1.0 + end.e_wall_zone) ==
        Approx(end.u_n_mm).epsilon(0.005));
}

// Profiles where a DEM run has its windows: at the first increment's end at or past each travel
// (500 increments of 0.02 mm), and at the end of the travel once.
TEST_CASE("column: profiles at given travels, a DEM run's windows, and only rising ones",
          "[column]") {
  auto s = truth_column(1.0, WallRotation::kFree);
  s.profile_at_mm = {0.71, 2.5, 9.99};
  const auto r = run_column(s);
  REQUIRE(r.status == "complete");
  REQUIRE(r.profiles.size() == 3);
  CHECK(r.profiles[0].u_mm == Approx(0.72));
  CHECK(r.profiles[1].u_mm == Approx(2.5));
  CHECK(r.profiles[2].u_mm == Approx(10.0));
  s.profile_at_mm = {0.71, 2.5};
  const auto ended = run_column(s);
  REQUIRE(ended.profiles.size() == 3);
  CHECK(ended.profiles[2].u_mm == Approx(10.0));
  s.profile_at_mm = {2.5, 0.71};
  CHECK_THROWS_AS(run_column(s), InputError);
  s.profile_at_mm = {12.0};
  CHECK_THROWS_AS(run_column(s), InputError);
  // the truth's first seed wrote its profiles at these travels (its profiles.csv)
  const auto w = profile_windows("data/convergence/truth_clamped/runs/s1", 10.0);
  REQUIRE(w.size() == 5);
  CHECK(w.front() == Approx(1.598506371));
  CHECK(w.back() == Approx(9.637687011));
}
