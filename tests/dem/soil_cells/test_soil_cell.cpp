// The DEM soil cell (`iwb dem soiltest`) with real LIGGGHTS and YADE runs on the smoke scene's
// grains: the physical facts of an oedometer and of simple shear, and that `read_soil_test` (what
// `iwb calibrate` reads) accepts the output.
#include <fmt/core.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <map>

#include "dem/soil_cells/soil_cell.hpp"
#include "io/csv_table.hpp"
#include "io/run_directory.hpp"
#include "soil_test/soil_test.hpp"

using namespace iwb;
namespace fs = std::filesystem;
using soil_test::SoilTestKind;

namespace {

const std::string kSmokeScene = "data/scenes/smoke.toml";

soil_test::SoilTest run_cell(const dem::SoilCellSpec& spec, const std::string& name,
                             const std::string& scene = kSmokeScene) {
  const auto dir = fs::path(IWB_TEST_RUNS_DIR) / "dem" / "soil" / spec.engine / name;
  const dem::RunOptions opt{dir, 1, false, true, "tests", nullptr, nullptr, {}};
  const auto outcome = dem::run_soil_test(io::read_file(scene), scene, spec, opt);
  REQUIRE(outcome.status == "complete");
  const auto m = nlohmann::json::parse(io::read_file(dir / "manifest.json"));
  CHECK(m["source"] == "dem:" + spec.engine);
  CHECK(m["scene"]["sha256"] == io::sha256_hex(io::read_file(scene)));
  return soil_test::read_soil_test(dir);  // throws if the contract does not hold
}

// d e / d ln sigma_v between rows i and j: the compression (or swelling) index, natural log.
double index(const soil_test::SoilTest& t, std::size_t i, std::size_t j) {
  return -(t.e[j] - t.e[i]) / std::log(t.control[j] / t.control[i]);
}

// An extra column of the cell's timeseries.csv (read_soil_test reads only the contract's columns).
double extra(const soil_test::SoilTest& t, const std::string& name, std::size_t row) {
  return io::read_csv_table(fs::path(t.name) / "timeseries.csv").values(name).at(row);
}

dem::SoilCellSpec small_cell(SoilTestKind test) {
  dem::SoilCellSpec c;
  c.test = test;
  c.height_d50 = 6.0;  // ~360 grains
  return c;
}

// Loose: a dense cell of these soft grains (E = 1e8 Pa) is nearly elastic, and its unloading
// branch is only ~5 % stiffer than its loading branch (measured); a loose one compacts plastically.
void check_oedometer(const std::string& engine) {
  auto c = small_cell(SoilTestKind::kOedometer);
  c.engine = engine;
  c.density = dem::SoilDensity::kLoose;
  c.sigma_max_kPa = 160.0;
  c.load_levels = 4;
  c.unload_levels = 2;
  c.level_windows = 1;
  const auto t = run_cell(c, "oedometer");
  REQUIRE(t.rows() == 7);
  const std::size_t top = t.loading_end();
  REQUIRE(top == 4);
  CHECK(t.control.front() == Approx(10.0).epsilon(0.05));  // the servo reached the levels
  CHECK(t.control[top] == Approx(160.0).epsilon(0.05));
  CHECK(t.control.back() == Approx(10.0).epsilon(0.05));
  for (std::size_t i = 1; i <= top; ++i) CHECK(t.e[i] < t.e[i - 1]);  // loading compresses
  for (std::size_t i = top + 1; i < t.rows(); ++i)
    CHECK(t.e[i] >= t.e[i - 1] - 1e-4);  // no further compaction
  // Unloading is stiffer: less void-ratio change per log-stress than on the loading branch.
  // Measured cs/cc: 0.66 (LIGGGHTS), 0.73 (YADE); a dense, nearly elastic cell gives ~0.95.
  const double cc = index(t, 0, top), cs = index(t, t.rows() - 1, top);
  INFO("compression index " << cc << ", swelling index " << cs);
  CHECK(cc > 0.0);
  CHECK(cs < 0.8 * cc);
  // Zero lateral strain: K0 of a sand on first loading, 1 - sin(phi) ~ 0.3-0.6; allow a cell's
  // scatter.
  const double k0 = extra(t, "K0", top);
  CHECK(k0 > 0.25);
  CHECK(k0 < 0.9);
  CHECK(extra(t, "overlap_mean_over_d50_estimate", top) < 0.03);
}

}  // namespace

// heavy since 2026-12-02 (issue 60, the default suite's 6 minutes): the soil cells stay in the
// default suite through the periodic cell's CV and CNL test
TEST_CASE("DEM soil cell oedometer compresses on loading and swells less on unloading",
          "[dem][soil][heavy]") {
  check_oedometer("liggghts");
}

TEST_CASE("YADE soil cell oedometer compresses on loading and swells less on unloading",
          "[dem][soil][yade][heavy]") {
  check_oedometer("yade");
}

namespace {

// max_row_deviation: how far one row's sigma_n may stray from the CNL target.
void check_simple_shear(const std::string& engine, double max_row_deviation) {
  auto c = small_cell(SoilTestKind::kSimpleShear);
  c.engine = engine;
  // I = 1e-3 (DEM.md): at 2e-3 the servo trailed a dense 602-grain cell's dilation by 6 %.
  c.gamma = 0.5;
  c.inertial_number = 1e-3;
  std::map<std::string, soil_test::SoilTest> t;
  for (const auto bc : {driver::BoundaryKind::kCNL, driver::BoundaryKind::kCV})
    for (const auto density : {dem::SoilDensity::kDense, dem::SoilDensity::kLoose}) {
      c.boundary = bc;
      c.density = density;
      const std::string name = fmt::format("{}-{}", driver::to_string(bc), dem::to_string(density));
      t[name] = run_cell(c, name);
    }
  for (const auto& [name, s] : t) {
    INFO(name);
    CHECK(s.control.back() > 0.45);
    if (name.rfind("CV", 0) == 0) {
      for (std::size_t i = 0; i < s.rows(); ++i)
        CHECK(std::abs(s.e[i] - s.e0) < 0.005);  // volume held
    } else {
      // sigma_n held on average, in its scatter and in every row (one row is one instant).
      double sum = 0.0, squares = 0.0, n = 0.0;
      for (std::size_t i = s.rows() / 10; i < s.rows(); ++i, n += 1.0) {
        const double deviation = s.sigma_n_kPa[i] / 50.0 - 1.0;
        CHECK(std::abs(deviation) < max_row_deviation);
        sum += deviation, squares += deviation * deviation;
      }
      CHECK(std::abs(sum / n) < 0.02);
      CHECK(std::sqrt(squares / n) < 0.03);
    }
  }
  CHECK(t["CNL-dense"].e0 < t["CNL-loose"].e0);
  // Dense dilates (e rises), loose contracts or dilates less.
  CHECK(t["CNL-dense"].e.back() - t["CNL-dense"].e0 > t["CNL-loose"].e.back() - t["CNL-loose"].e0);
  const auto peak_ratio = [](const soil_test::SoilTest& s) {
    double best = 0.0;
    for (std::size_t i = 0; i < s.rows(); ++i)
      best = std::max(best, s.tau_kPa[i] / s.sigma_n_kPa[i]);
    return best;
  };
  CHECK(peak_ratio(t["CNL-dense"]) > peak_ratio(t["CNL-loose"]));
  // Under CV a dense specimen tends to dilate: sigma_n rises; a loose one's falls or rises less.
  CHECK(t["CV-dense"].sigma_n_kPa.back() > t["CV-loose"].sigma_n_kPa.back());
}

}  // namespace

TEST_CASE(
    "DEM soil cell simple shear keeps its boundary condition and dense dilates more than loose",
    "[dem][soil][heavy]") {
  check_simple_shear("liggghts", 0.05);
}

TEST_CASE(
    "YADE soil cell simple shear keeps its boundary condition and dense dilates more than loose",
    "[dem][soil][yade][heavy]") {
  // YADE's Python servo updates every 10 steps: its rows scatter by 1.6-1.7 % RMS around a mean
  // within 0.4 % of the target, single rows up to 10 % (measured, smoke cell).
  check_simple_shear("yade", 0.12);
}

// The truth's stiff grains (E 6.9e8 Pa) prepared dense, i.e. frictionless, in a 360-grain cell.
// At 200 kPa the specimen used to slide sideways as a whole (nothing resists it between flat-ended
// periodic sides and frictionless contacts) until its kinetic energy was ~8e-5 J and the
// consolidation was never accepted; at 10 kPa the plate's servo, at kp 1 and a loop number of 4,
// jumped between -2 and +9 kPa. Both consolidated, the first row of the test starts at its target.
// Sheared (at the test's friction) the plate's own force must hold its target too: at the
// interface scenes' default gains the 10 kPa cell's plate chattered from step to step between
// about -10 and +29 kPa (a mean of 10: dem/scene/scene.hpp, servo_loop_number), rows reading
// either.
TEST_CASE("DEM soil cell: stiff grains prepared dense consolidate at 10 and at 200 kPa",
          "[dem][liggghts][heavy]") {
  auto c = small_cell(SoilTestKind::kSimpleShear);
  c.height_d50 = 6.0;
  c.gamma = 0.02;
  for (const double sigma : {10.0, 200.0}) {
    c.sigma0_kPa = sigma;
    const auto t = run_cell(c, fmt::format("stiff-dense-{:g}", sigma), "data/scenes/truth.toml");
    INFO(sigma << " kPa");
    CHECK(t.sigma_n_kPa.front() == Approx(sigma).epsilon(0.05));
    const auto plate =
        io::read_csv_table(fs::path(t.name) / "timeseries.csv").values("sigma_plate_kPa");
    const auto [lo, hi] = std::minmax_element(plate.begin(), plate.end());
    INFO("plate's stress while shearing: " << *lo << " to " << *hi << " kPa");
    CHECK(*lo > 0.75 * sigma);
    CHECK(*hi < 1.25 * sigma);
  }
}

// A soil test beside an interface run compares like with like only at the density of that run's
// specimen: as-scene prepares the cell with the scene's own preparation friction (the truth's 0.1),
// where dense and loose replace it by 0 and 1.
TEST_CASE("DEM soil cell: as-scene density prepares the cell as the scene's specimen", "[dem]") {
  const std::string scene = "data/scenes/truth.toml";
  const auto text = io::read_file(scene);
  REQUIRE(dem::parse_scene(text, scene).consolidation.friction == Approx(0.1));
  dem::SoilCellSpec c;
  c.test = SoilTestKind::kSimpleShear;
  const auto friction = [&](const char* density) {
    c.density = dem::parse_soil_density(density, "--density");
    CHECK(dem::to_string(c.density) == std::string(density));
    return dem::parse_scene(dem::cell_scene_text(text, scene, c), "cell").consolidation.friction;
  };
  CHECK(friction("as-scene") == Approx(0.1));
  CHECK(friction("dense") == 0.0);
  CHECK(friction("loose") == 1.0);
  CHECK_THROWS_WITH(dem::parse_soil_density("medium", "--density"), Catch::Contains("as-scene"));
}

// The same for the rolling resistance while consolidating: the interface specimen's own in an
// as-scene cell, the grains' (the truth's 0.1) in the standard dense and loose ones.
TEST_CASE("DEM soil cell: as-scene keeps the specimen's consolidation rolling friction", "[dem]") {
  const std::string scene = "data/scenes/truth.toml";
  std::string text = io::read_file(scene);
  const auto at = text.find("[specimen]\n");
  REQUIRE(at != std::string::npos);
  text.insert(at + 11, "consolidation_rolling_friction = 0.5\n");
  REQUIRE(dem::parse_scene(text, scene).consolidation.rolling_friction == Approx(0.5));
  dem::SoilCellSpec c;
  c.test = SoilTestKind::kSimpleShear;
  const auto rolling = [&](const char* density) {
    c.density = dem::parse_soil_density(density, "--density");
    return dem::parse_scene(dem::cell_scene_text(text, scene, c), "cell")
        .consolidation.rolling_friction;
  };
  CHECK(rolling("as-scene") == Approx(0.5));
  CHECK(rolling("dense") == Approx(0.1));
  CHECK(rolling("loose") == Approx(0.1));
}

// The cyclic cell (issue 34): the plate's amplitude is A x target height in d50 x d50 (the
// contract's gamma = travel / height), three cycles and nothing after them, and a row every
// fortieth of A so that a reversal's secant at 10 % of A has rows to rest on.
TEST_CASE("DEM soil cell: cyclic shear moves the plate by A times the target height",
          "[dem][cyclic]") {
  const std::string scene = "data/scenes/truth.toml";
  const auto text = io::read_file(scene);
  dem::SoilCellSpec c;
  c.test = SoilTestKind::kCyclicShear;
  c.boundary = driver::BoundaryKind::kCV;
  c.gamma_amplitude = 0.005;
  c.cycles = 3;
  c.height_d50 = 12.0;
  const auto cell = dem::parse_scene(dem::cell_scene_text(text, scene, c), "cell");
  const double d50 = dem::parse_scene(text, scene).particles.d50_m;
  const double A = 0.005 * 12.0 * d50;  // 0.12 mm for d50 = 2 mm
  CHECK(cell.shear.amplitude_m == Approx(A));
  CHECK(cell.shear.cycles == 3);
  CHECK(cell.shear.travel_m() == Approx(12.0 * A));  // 4 A a cycle, no post-cyclic shear
  CHECK(cell.outputs.timeseries_every_m == Approx(A / 40.0));
  CHECK(cell.boundary.kind == driver::BoundaryKind::kCV);
}
