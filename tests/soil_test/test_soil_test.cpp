// The soil-test run-directory contract: a written test reads back as it was, and malformed
// directories are refused with the file, line, key or column named.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "calibration/synthetic.hpp"
#include "common/errors.hpp"
#include "soil_test/soil_test.hpp"
#include "support/fixtures.hpp"

using namespace iwb;
namespace fs = std::filesystem;

namespace {

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::path(IWB_TEST_RUNS_DIR) / "soiltest" / name;
  fs::remove_all(dir);
  return dir;
}

soil_test::SoilTest small_oedometer() {
  calibration::SyntheticSpec s;
  s.sigma0_kPa = 10.0;
  s.sigma_max_kPa = 400.0;
  s.sigma_end_kPa = 50.0;
  s.e0 = 0.85;
  s.rows = 6;
  return calibration::synthesise(s, test::table_5_2_hostun());
}

void write_text(const fs::path& file, const std::string& text) {
  std::ofstream(file) << text;
}

std::string read_text(const fs::path& file) {
  std::ifstream in(file);
  return {std::istreambuf_iterator<char>(in), {}};
}

}  // namespace

TEST_CASE("a synthetic soil test is written and read back row by row", "[calibration]") {
  const auto t = small_oedometer();
  const auto dir = fresh_dir("roundtrip");
  soil_test::write_soil_test(t, dir, false, {});
  const auto back = soil_test::read_soil_test(dir);
  REQUIRE(back.rows() == t.rows());
  CHECK(back.rows() == 7 + 3);  // 6 loading steps + start, 3 unloading steps
  CHECK(back.kind == soil_test::SoilTestKind::kOedometer);
  CHECK(back.source == "synthetic:vw3d");
  CHECK(back.source_parameters["hypoplastic"]["hs_kPa"] == 1e6);
  CHECK(back.loading_end() == 6);
  for (std::size_t i = 0; i < t.rows(); ++i) {
    CHECK(back.e[i] == Approx(t.e[i]).epsilon(1e-11));
    CHECK(back.control[i] == Approx(t.control[i]).epsilon(1e-11));
  }
  CHECK(back.e[6] < back.e[0]);      // compressed
  CHECK(back.e.back() > back.e[6]);  // swells on unloading
}

TEST_CASE("malformed soil-test directories are refused naming file, line and column",
          "[calibration]") {
  const auto t = small_oedometer();
  const auto dir = fresh_dir("malformed");
  soil_test::write_soil_test(t, dir, false, {});
  const std::string csv = read_text(dir / "timeseries.csv");
  const std::string manifest = read_text(dir / "manifest.json");
  const auto refused = [&](const std::string& what) {
    CHECK_THROWS_WITH(soil_test::read_soil_test(dir), Catch::Contains(what));
  };
  SECTION("missing timeseries") {
    fs::remove(dir / "timeseries.csv");
    refused("timeseries.csv: missing");
  }
  SECTION("missing manifest") {
    fs::remove(dir / "manifest.json");
    refused("manifest.json: missing (not a soil-test directory)");
  }
  SECTION("missing column") {
    write_text(dir / "timeseries.csv",
               "sigma_v_kPa,eps_v,void_ratio\n10,0,0.8\n20,0.01,0.79\n40,0.02,0.78\n");
    refused("timeseries.csv: no column 'e'");
  }
  SECTION("NaN") {
    write_text(dir / "timeseries.csv",
               "sigma_v_kPa,eps_v,e\n10,0,0.8\n20,0.01,nan\n40,0.02,0.78\n");
    refused("timeseries.csv:3: column 'e' = 'nan' is not a finite number");
  }
  SECTION("non-monotonic loading") {
    write_text(dir / "timeseries.csv",
               "sigma_v_kPa,eps_v,e\n10,0,0.8\n40,0.01,0.79\n30,0.015,0.795\n50,0.02,0.78\n60,0.03,"
               "0.77\n");
    refused(
        "timeseries.csv:4: column 'sigma_v_kPa' = 30 after 40: the vertical stress must be "
        "strictly increasing");
  }
  SECTION("wrong kind and test") {
    auto m = nlohmann::json::parse(manifest);
    m["test"] = "triaxial";
    write_text(dir / "manifest.json", m.dump());
    refused(
        "manifest.json: key 'test' = \"triaxial\" should be \"oedometer\", \"simpleshear\" or "
        "\"cyclicshear\"");
  }
  SECTION("simple shear without a boundary") {
    auto m = nlohmann::json::parse(manifest);
    m["test"] = "simpleshear";
    m["sigma_n0_kPa"] = 100;
    write_text(dir / "manifest.json", m.dump());
    refused("manifest.json: missing key 'boundary'");
  }
  SECTION("negative e0") {
    auto m = nlohmann::json::parse(manifest);
    m["e0"] = -0.5;
    write_text(dir / "manifest.json", m.dump());
    refused("manifest.json: key 'e0' = -0.5 must be positive");
  }
}

TEST_CASE(
    "cyclic shear reads back with its reversals, a repeated or never-reversing gamma is "
    "refused",
    "[calibration][cyclic]") {
  calibration::SyntheticSpec s;
  s.model = "vw3d-igs";
  s.kind = soil_test::SoilTestKind::kCyclicShear;
  s.boundary = driver::BoundaryKind::kCV;
  s.e0 = 0.75;
  s.gamma_amplitude = 1e-3;
  s.cycles = 1;
  s.rows = 4;
  const auto t = calibration::synthesise(s, test::table_5_3_toyoura());
  const auto dir = fresh_dir("cyclic");
  soil_test::write_soil_test(t, dir, false, {});
  const auto back = soil_test::read_soil_test(dir);
  CHECK(back.kind == soil_test::SoilTestKind::kCyclicShear);
  REQUIRE(back.rows() == 17);
  CHECK(back.control[8] == Approx(0.0).margin(1e-15));  // half a cycle: back through zero
  const auto refused = [&](const std::string& csv, const std::string& what) {
    write_text(dir / "timeseries.csv", csv);
    CHECK_THROWS_WITH(soil_test::read_soil_test(dir), Catch::Contains(what));
  };
  const std::string header = "gamma,tau_kPa,sigma_n_kPa,e\n";
  refused(header + "0,0,100,0.75\n0.001,5,100,0.75\n0.001,5,100,0.75\n0,0,100,0.75\n",
          "timeseries.csv:4: column 'gamma' = 0.001 repeats the row before");
  refused(header + "0,0,100,0.75\n0.001,5,100,0.75\n0.002,6,100,0.75\n",
          "column 'gamma' never reverses: a cyclic shear test reverses at least once");
}

namespace {

// A simple-shear test as a periodic DEM cell writes it: 41 rows, gamma 0 to 0.4, and profile
// windows every 2 mm of an 8 mm travel (gamma 0.1, 0.2, 0.3, 0.4) with the given R^2.
fs::path periodic_cell_test(const std::string& name, const std::vector<double>& r2) {
  soil_test::SoilTest t;
  t.kind = soil_test::SoilTestKind::kSimpleShear;
  t.boundary = driver::BoundaryKind::kCNL;
  t.sigma0_kPa = 50.0;
  t.e0 = 0.6;
  t.source = "dem:liggghts";
  for (int i = 0; i <= 40; ++i) {
    t.control.push_back(0.01 * i);
    t.tau_kPa.push_back(30.0), t.sigma_n_kPa.push_back(50.0), t.e.push_back(0.6 + 0.001 * i);
  }
  nlohmann::json windows = nlohmann::json::array();
  for (std::size_t k = 0; k < r2.size(); ++k)
    windows.push_back({{"u_x_mm_window", 2.0 * double(k + 1)}, {"r2", r2[k]}});
  bool all = true;
  for (const double v : r2) all = all && v >= 0.9;
  const nlohmann::json manifest = {
      {"cell", "periodic"},
      {"gamma_reached", 0.4},
      {"cell_scene", {{"resolved", {{"shear", {{"travel_mm", 8.0}}}}}}},
      {"cell_summary",
       {{"profile_linearity_r2_by_window", windows},
        {"homogeneous", all},
        {"homogeneous_r2_threshold", 0.9}}}};
  const auto dir = fresh_dir(name);
  soil_test::write_soil_test(t, dir, false, manifest);
  return dir;
}

}  // namespace

// A cell that localised is an element only up to its last straight velocity profile: by hand,
// windows at gamma 0.1 and 0.2 straight, 0.3 and 0.4 not: rows up to gamma 0.2 (21 of 41) are read.
// A lone bent profile between straight ones is noise; a bent last one is not.
TEST_CASE("a periodic cell that localised is read up to its last homogeneous window",
          "[calibration]") {
  const auto read = [](const std::string& name, const std::vector<double>& r2) {
    return soil_test::read_soil_test(periodic_cell_test(name, r2));
  };
  const auto part = read("periodic-localised", {0.98, 0.93, 0.6, 0.5});
  CHECK(part.element_until == Approx(0.2));
  CHECK(part.rows() == 21);
  CHECK(part.rows_in_file == 41);
  CHECK(part.control.back() == Approx(0.2));
  CHECK(part.e.size() == 21);
  CHECK(read("periodic-bent-last", {0.98, 0.93, 0.91, 0.5}).element_until == Approx(0.3));
  for (const auto& r2 :
       {std::vector<double>{0.98, 0.93, 0.91, 0.95}, std::vector<double>{0.98, 0.6, 0.91, 0.95},
        std::vector<double>{0.89, 0.93, 0.91, 0.95}}) {
    const auto whole = read("periodic-whole", r2);
    CHECK(whole.element_until == 0.0);
    CHECK(whole.rows() == 41);
  }
  // no element to read: a calibration of many tests leaves it out (calibration_run.cpp)
  CHECK_THROWS_AS(read("periodic-never", {0.5, 0.6, 0.91, 0.95}), soil_test::NotAnElement);
  CHECK_THROWS_WITH(read("periodic-never", {0.5, 0.6, 0.91, 0.95}),
                    Catch::Contains("localised from its first profile window"));
}
