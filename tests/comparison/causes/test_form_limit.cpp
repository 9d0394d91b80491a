// The form limit (issue 38 item 4) on "DEM" runs that hvwe itself wrote (Table 5.1): a
// miscalibrated soil set's breaks could be the calibration's, since a set inside the declared
// boxes (Table 5.1's own) reproduces the runs; on runs whose tau is three times the model's, no
// set inside the boxes reaches the peak, and the break is the form's. Whether it is the
// calibration's is for the soil tests to say (issue 59). They are stood in for by what they
// measure: every material parameter, each to 2 % (a residual (value - measured) / (0.02
// measured) per parameter, and a misfit of one scatter unit no set removes, the form's own miss
// on soil tests); the form limit knows soil tests only through the residuals it is given.
//   - soil tests that measured Table 5.1 (the runs' own set) accept the set that mends the
//     miscalibrated peak: the break is the calibration's;
//   - on runs 1.25 times stronger than Table 5.1, soil tests that measured Table 5.1 refuse every
//     set that could reach them (kappa_r <= 1 only lowers the friction), while without them a
//     larger phi_c does: the break is the form's, with the soil tests.
#include <fmt/core.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>

#include "common/errors.hpp"
#include "comparison/causes/form_limit.hpp"
#include "comparison/compare/compare.hpp"
#include "comparison/verdicts/form_limit_causes.hpp"
#include "io/run_directory.hpp"
#include "support/synthetic_dem.hpp"

using namespace iwb;
namespace fs = std::filesystem;

namespace {

// Table 5.1 with phi_c 33 degrees instead of 28: the "soil-test set" of a miscalibration.
fs::path miscalibrated_table_5_1() {
  const fs::path file = fs::path(IWB_TEST_RUNS_DIR) / "comparison" / "form_limit_phi33.toml";
  fs::create_directories(file.parent_path());
  io::write_atomically(file,
                       "[hypoplastic]\nphi_c_deg = 33\nhs_kPa = 2e6\nn = 0.29\ned0 = 0.61\n"
                       "ec0 = 0.96\nei0 = 1.09\nalpha = 0.13\nbeta = 2\n");
  return file;
}

comparison::FormLimitOptions form_limit_of(const std::string& name, double tau_scale) {
  comparison::FormLimitOptions o;
  o.model = "hvwe";
  o.params = miscalibrated_table_5_1().string();
  for (int seed : {1, 2, 3}) {
    test::SyntheticDem s;
    s.name = fmt::format("{}_s{}", name, seed);
    s.seed = seed, s.tau_noise_kPa = 0.5, s.u_n_noise_mm = 2e-4, s.tau_scale = tau_scale;
    (seed < 3 ? o.fit_runs : o.held_out).push_back(test::write_synthetic_dem(s));
  }
  o.out = fs::path(IWB_TEST_RUNS_DIR) / "comparison" / (name + "_out");
  o.force = true;
  // a short budget: the runs are short and the answer is far from the start or at the start
  o.max_evaluations = 300, o.polish_iterations = 15;
  return o;
}

std::vector<std::string> causes(const nlohmann::json& j, const std::string& quantity) {
  std::vector<std::string> out;
  for (const auto& r : j["runs"])
    out.push_back(r["quantities"][quantity].value("cause", std::string("none")));
  return out;
}

}  // namespace

TEST_CASE("a form limit on runs the model wrote holds everywhere and blames the calibration",
          "[comparison]") {
  const auto j = comparison::run_form_limit(form_limit_of("form_limit_own", 1.0));
  INFO(j["rms_scaled"] << " scatter units, " << j["evaluations"] << " evaluations, " << j["stop"]);
  CHECK(j["rms_scaled"].get<double>() < 3.0);  // the runs' own noise: ~1
  for (const auto& r : j["runs"])
    for (const auto& [key, q] : r["quantities"].items()) {
      INFO(r["dir"] << " " << key << ": " << q.dump());
      CHECK(q["form_limit"]["verdict"] != "breaks");
    }
  // phi_c 33 against 28 degrees: the predicted peak misses by ~20 % and breaks; a set mends it,
  // but no soil test judged that set
  for (const auto& c : causes(j, "peak_friction")) CHECK(c == "calibration (unchecked)");
  CHECK_FALSE(j.contains("joint"));
  CHECK(fs::exists(fs::path(j["fit_runs"][0].get<std::string>())));
  for (const char* f : {"form_limit.json", "form_limit.md", "form_limit.toml", "manifest.json"})
    CHECK(fs::exists(form_limit_of("form_limit_own", 1.0).out / f));
}

namespace {
const fs::path kTable51 = "data/params/table_5_1_evaluation.toml";  // tests run from the root

// Soil tests that measured Table 5.1's every parameter to 2 %, with a unit misfit beside.
comparison::FormLimitOptions::SoilTests soil_tests_measuring_table_5_1() {
  const std::map<std::string, double> measured = {
      {"phi_c_deg", 28.0}, {"hs_kPa", 2e6}, {"n", 0.29},     {"ed0", 0.61},
      {"ec0", 0.96},       {"ei0", 1.09},   {"alpha", 0.13}, {"beta", 2.0}};
  return [measured](const comparison::FormLimitOptions::Tables& t) {
    std::vector<double> r = {1.0};
    for (const auto& [key, m] : measured)
      r.push_back((t.at("hypoplastic").at(key) - m) / (0.02 * m));
    double squares = 0.0;
    for (const double x : r) squares += x * x;
    return std::vector<comparison::FormLimitOptions::SoilGroup>{
        {"shear", r, std::sqrt(squares / double(r.size())), 0}};
  };
}
}  // namespace

TEST_CASE("a break is the calibration's only when a set the soil tests accept mends it",
          "[comparison]") {
  // phi_c 33 against the measured 28 is 8.9 units: the soil-test set's RMS is sqrt((1 + 8.9^2) /
  // 9) = 3.0, and they accept up to 1.25 x 3.0, which Table 5.1 itself (RMS 1/3) meets
  auto agree = form_limit_of("form_limit_soil_agree", 1.0);
  agree.soil_tests = soil_tests_measuring_table_5_1();
  agree.joint_evaluations = 300;
  const auto a = comparison::run_form_limit(agree);
  INFO(a["joint"].dump());
  CHECK(a["joint"]["accepted"].get<bool>());
  for (const auto& c : causes(a, "peak_friction")) CHECK(c == "calibration");
  CHECK(fs::exists(agree.out / "form_limit_joint.toml"));
  // Table 5.1 as the soil-test set (RMS 1/3, accepted up to 0.42: every parameter within ~0.75 of
  // its 2 %) on runs 1.25 times stronger: the prediction's peak misses by -20 %
  auto strong = form_limit_of("form_limit_soil_refuse", 1.25);
  strong.params = kTable51.string();
  strong.soil_tests = soil_tests_measuring_table_5_1();
  strong.joint_evaluations = 300;
  const auto s = comparison::run_form_limit(strong);
  INFO(s["joint"].dump());
  CHECK(s["joint"]["accepted"].get<bool>());  // COBYLA stays inside: it started there
  for (const auto& run : s["runs"]) {
    const auto& q = run["quantities"]["peak_friction"];
    INFO(q.dump());
    REQUIRE(q["soil_test_predicted"]["verdict"] == "breaks");
    CHECK(q["form_limit"]["verdict"] != "breaks");  // without the soil tests a set mends it
    CHECK(q["joint"]["verdict"] == "breaks");
    CHECK(q["cause"] == "form");
  }
}

TEST_CASE("a form limit on runs three times stronger than the model blames the form",
          "[comparison]") {
  const auto j = comparison::run_form_limit(form_limit_of("form_limit_strong", 3.0));
  INFO(j["rms_scaled"] << " scatter units, " << j["evaluations"] << " evaluations");
  // tau/sigma_n about 3 x 0.7: beyond every phi_c of the box [15, 50] degrees
  for (const auto& c : causes(j, "peak_friction")) CHECK(c == "form");
  bool phi_c_on_bound = false;
  for (const auto& p : j["parameters"])
    if (p["name"] == "phi_c_deg") phi_c_on_bound = p["at_bound"].get<bool>();
  CHECK(phi_c_on_bound);
}

TEST_CASE(
    "a fit of one parameter with the walls held recovers the runs' own value, keeps the rest and "
    "gives a break no cause",
    "[comparison]") {
  // the runs were written with phi_c 28 degrees at kappa_r 1 and d_s 5 d50, which is what the
  // wall's R_n 1 and the held prediction give (eq. 5.35: min(1, 1.05)); only phi_c is free
  auto o = form_limit_of("form_limit_free_phi", 1.0);
  o.free = {"hypoplastic.phi_c_deg"};
  o.hold_walls = true;
  const auto j = comparison::run_form_limit(o);
  REQUIRE(j["parameters"].size() == 1);
  CHECK(j["parameters"][0]["value"].get<double>() == Approx(28.0).margin(0.5));
  CHECK(j["restricted"].get<bool>());
  for (const auto& c : causes(j, "peak_friction")) CHECK((c == "none" || c == "not judged"));
  for (const auto& r : j["runs"])
    CHECK(r["quantities"]["peak_friction"]["cause_if_breaks"] == "not judged");
  // the held parameters are written as given, so the file is a whole set
  const auto toml = io::read_file(o.out / "form_limit.toml");
  CHECK(toml.find("hs_kPa = 2000000") != std::string::npos);
  CHECK(toml.find("ec0 = 0.96") != std::string::npos);
  // with the walls fitted, a held-out run on a wall no fit run has gets no unknowns of its own
  // (nothing fitted would move them): it keeps the wall's prediction
  test::SyntheticDem other;
  other.name = "form_limit_free_phi_other_wall", other.R_n = 0.25;
  o.held_out.push_back(test::write_synthetic_dem(other));
  o.hold_walls = false;
  const auto walls = comparison::run_form_limit(o);
  for (const auto& p : walls["parameters"])
    CHECK(p["name"].get<std::string>().find("R_n 0.25") == std::string::npos);
  CHECK(walls["parameters"].size() == 3);  // phi_c, kappa_r and d_s of R_n 1
  o.free = {"chi"};
  CHECK_THROWS_WITH(comparison::run_form_limit(o),
                    Catch::Contains("--free chi: not a parameter of hvwe"));
}

TEST_CASE("a form limit refuses a run given both to fit and to hold out", "[comparison]") {
  auto o = form_limit_of("form_limit_twice", 1.0);
  o.held_out.push_back(o.fit_runs.front());
  CHECK_THROWS_WITH(comparison::run_form_limit(o),
                    Catch::Contains("is given both to fit (--runs) and to hold out"));
}

TEST_CASE("compare with a form-limit record says which broke, and refuses another model's record",
          "[comparison]") {
  const auto o = form_limit_of("form_limit_label", 1.0);
  comparison::run_form_limit(o);
  comparison::CompareOptions c;
  c.dem_dir = o.held_out.front();
  c.seed_dirs = o.fit_runs;
  c.model = "hvwe";
  c.params = o.params;
  c.out = fs::path(IWB_TEST_RUNS_DIR) / "comparison" / "form_limit_label_compare";
  c.force = true;
  c.form_limit = o.out / "form_limit.json";
  const auto result = comparison::run_comparison(c);
  const auto& predicted =
      result["variants"][result["verdicts"]["predicted_variant"].get<std::size_t>()]["verdicts"];
  bool peak_labelled = false;
  for (const auto& v : predicted) {
    INFO(v.dump());
    // a cause on every break and on nothing else
    CHECK(v.contains("cause") == (v["verdict"] == "breaks"));
    if (v["quantity"] == "peak_friction" && v["verdict"] == "breaks")
      peak_labelled = v["cause"] == "calibration (unchecked)";
  }
  CHECK(peak_labelled);  // phi_c 33 against 28: the peak breaks, and a set (unjudged) meets it
  c.model = "ahe";
  CHECK_THROWS_WITH(comparison::run_comparison(c),
                    Catch::Contains("a form limit of hvwe, not of ahe"));
}
