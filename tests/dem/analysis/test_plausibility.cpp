// Plausibility of a DEM run (issue 15, finding 1): each check on synthetic series that pass or
// break exactly it, every committed run of data/reference and data/convergence passing, and the
// garbage run of the issue (the smoke scene at inertial number 1e6) failed with its reason.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <functional>

#include "dem/analysis/plausibility.hpp"
#include "dem/engines/engines.hpp"
#include "dem/run/run.hpp"
#include "io/run_directory.hpp"
#include "support/smoke_specimens.hpp"

using namespace iwb;
namespace fs = std::filesystem;

namespace {

// The smoke scene's request: 2 mm of shear, a row every 0.02 mm, 50 kPa, d50 2 mm.
dem::Asked asked(driver::BoundaryKind kind = driver::BoundaryKind::kCNL, double K = 0.0) {
  return {2.0, 0.02, 0, kind, 50.0, K, 2.0};
}

// A run that did what was asked: 101 rows from 0 to 2 mm (one row: at 2 mm), dilating to 0.2 mm,
// sigma_n on target (CNS: sigma_n0 + K u_n), friction 0.6. `edit(row, u_x, u_n, sigma_n)` spoils
// it.
using Edit = std::function<void(int, double&, double&, double&)>;
io::CsvTable series(const dem::Asked& a, const Edit& edit = nullptr, int rows = 101) {
  io::CsvTable t;
  t.columns = {"t_s", "u_x_mm", "u_n_mm", "sigma_n_kPa", "tau_kPa"};
  for (int i = 0; i < rows; ++i) {
    double ux = rows > 1 ? a.travel_mm * i / (rows - 1) : a.travel_mm,
           un = a.boundary == driver::BoundaryKind::kCV ? 0.0 : 0.1 * ux;
    double sigma = a.sigma_n0_kPa + a.K_kPa_per_mm * un;
    if (edit) edit(i, ux, un, sigma);
    t.rows.push_back({0.01 * i, ux, un, sigma, 0.6 * sigma});
  }
  return t;
}

// The names of the failed checks.
std::vector<std::string> failed(const dem::Asked& a, const io::CsvTable& t) {
  std::vector<std::string> out;
  for (const auto& c : dem::plausibility_checks(a, t))
    if (!c.passed) out.push_back(c.name);
  return out;
}
using Names = std::vector<std::string>;

}  // namespace

TEST_CASE("plausibility: a run that did what was asked passes every check, under CNL, CNS and CV",
          "[dem]") {
  for (const auto& a :
       {asked(), asked(driver::BoundaryKind::kCNS, 100.0), asked(driver::BoundaryKind::kCV)}) {
    const auto checks = dem::plausibility_checks(a, series(a));
    CHECK(checks.size() == 6);
    CHECK(failed(a, series(a)).empty());
    CHECK_FALSE(dem::failure_reason(checks));
    CHECK(dem::plausibility_warnings(checks).empty());
  }
}

TEST_CASE("plausibility: the displacement must be reached within two rows and not overshot",
          "[dem]") {
  const auto a = asked();
  // the last row one row short of the end (as the engine's cadence leaves it): passes
  CHECK(failed(a, series(a, [](int, double& ux, double&, double&) { ux *= 0.99; })).empty());
  // stopped at 90 %: short by 0.2 mm, ten rows
  CHECK(failed(a, series(a, [](int, double& ux, double&, double&) { ux *= 0.9; })) ==
        Names{"displacement_reached"});
  // the garbage: one step took the wall 66 mm
  CHECK(failed(a, series(a, [](int i, double& ux, double&, double&) {
                 ux = i == 100 ? 66.2 : ux;
               })) == Names{"displacement_not_overshot"});
  // cyclic travel counts every reversal: 0 -> 0.5 -> -0.5 -> 0 is 2 mm; rows that cut each of the
  // two turning points short by 0.015 mm lose 0.06 mm: more than the two rows' slack (0.04 mm),
  // within the slack with a row per reversal (0.08 mm)
  auto cyclic = a;
  cyclic.reversals = 2;
  const auto cycle = [](double cut) {
    return [cut](int i, double& ux, double&, double&) {
      ux = i <= 25 ? 0.02 * i : i <= 75 ? 0.5 - 0.02 * (i - 25) : -0.5 + 0.02 * (i - 75);
      ux = std::clamp(ux, -0.5 + cut, 0.5 - cut);
    };
  };
  CHECK(failed(cyclic, series(cyclic, cycle(0.0))).empty());
  CHECK(failed(cyclic, series(cyclic, cycle(0.015))).empty());
  CHECK(failed(a, series(a, cycle(0.015))) ==
        Names{"displacement_reached"});  // without the reversals' slack
  CHECK(failed(cyclic, series(cyclic, cycle(0.05))) == Names{"displacement_reached"});
}

TEST_CASE("plausibility: a time series with fewer rows than the cadence promises fails", "[dem]") {
  const auto a = asked();
  CHECK(failed(a, series(a, nullptr, 92)).empty());           // 91 intervals: 0.9 x 100 rows + 1
  CHECK(failed(a, series(a, nullptr, 89)) == Names{"rows"});  // 89 of 100
  // a single row, at the end: 1.8 rows promised at a row per mm, but 2 at least
  CHECK(failed({2.0, 1.0, 0, driver::BoundaryKind::kCNL, 50, 0, 2}, series(a, nullptr, 1)) ==
        Names{"rows"});
  const auto none = failed(a, series(a, nullptr, 0));  // a header only: nothing can be measured
  CHECK(none == Names{"rows", "displacement_reached", "displacement_not_overshot",
                      "contact_stress_positive", "normal_stress_held"});
}

TEST_CASE("plausibility: a non-finite value or a lost contact fails", "[dem]") {
  const auto a = asked();
  CHECK(failed(a, series(a, [](int i, double&, double& un, double&) {
                 un = i == 50 ? NAN : un;
               })) == Names{"finite_values"});
  CHECK(failed(a, series(a, [](int i, double&, double&, double& s) { s = i == 99 ? 0.0 : s; })) ==
        Names{"contact_stress_positive"});
}

TEST_CASE(
    "plausibility: CNL holds sigma_n on average within a fifth of sigma_n0 and warns beyond a "
    "twentieth",
    "[dem]") {
  const auto a = asked();
  const auto loose = series(a, [](int, double&, double&, double& s) { s *= 1.15; });
  CHECK(failed(a, loose).empty());
  const auto warnings = dem::plausibility_warnings(dem::plausibility_checks(a, loose));
  REQUIRE(warnings.size() == 1);
  CHECK_THAT(warnings[0],
             Catch::Contains("normal_stress_held = 0.15") && Catch::Contains("held only loosely"));
  // swings of +-90 % around the target are the servo at work, a mean 30 % high is not CNL (as the
  // stiffest runs with the fixed servo gain, data/convergence/README.md)
  CHECK(failed(a, series(a, [](int i, double&, double&, double& s) { s *= i % 2 ? 1.9 : 0.1; }))
            .empty());
  const auto off = series(a, [](int, double&, double&, double& s) { s *= 1.3; });
  CHECK(failed(a, off) == Names{"normal_stress_held"});
  CHECK_THAT(
      *dem::failure_reason(dem::plausibility_checks(a, off)),
      Catch::StartsWith("normal_stress_held = 0.3, must be <= 0.2 (|mean of sigma_n - sigma_n0|"));
}

TEST_CASE("plausibility: CNS holds the sigma_n-u_n relation, not a constant sigma_n", "[dem]") {
  const auto a = asked(driver::BoundaryKind::kCNS, 400.0);  // u_n 0.2 mm: sigma_n 50 -> 130 kPa
  CHECK(failed(a, series(a)).empty());
  const auto constant =
      series(a, [](int, double&, double&, double& s) { s = 50.0; });  // CNL, not CNS
  CHECK(failed(a, constant) == Names{"normal_stress_held"});
  CHECK_THAT(*dem::failure_reason(dem::plausibility_checks(a, constant)),
             Catch::Contains("sigma_n0 + K u_n"));
}

TEST_CASE("plausibility: CV holds u_n within a hundredth of d50", "[dem]") {
  const auto a = asked(driver::BoundaryKind::kCV);
  CHECK(
      failed(a, series(a, [](int i, double&, double& un, double&) { un = i == 40 ? 0.019 : 0.0; }))
          .empty());
  CHECK(failed(a, series(a, [](int i, double&, double& un, double&) {
                 un = i == 40 ? -0.021 : 0.0;
               })) == Names{"normal_displacement_held"});
}

TEST_CASE("plausibility: every check is recorded with its value, limit and verdict", "[dem]") {
  const auto a = asked();
  const auto j = dem::to_json(dem::plausibility_checks(a, series(a, nullptr, 50)));
  REQUIRE(j.size() == 6);
  CHECK(j[1]["name"] == "rows");
  CHECK(j[1]["value"] == 50.0);
  CHECK(j[1]["comparison"] == ">=");
  CHECK(j[1]["limit"].get<double>() == Approx(90.0));
  CHECK(j[1]["passed"] == false);
  CHECK(j[5]["warning_limit"] == dem::kNormalStressWarning);
}

TEST_CASE("plausibility: every committed DEM run of data/reference and data/convergence passes",
          "[dem]") {
  int runs = 0;
  for (const char* root : {"data/reference", "data/convergence"})
    for (const auto& e : fs::recursive_directory_iterator(root)) {
      if (e.path().filename() != "manifest.json" ||
          !fs::exists(e.path().parent_path() / "timeseries.csv"))
        continue;
      const auto m = nlohmann::json::parse(io::read_file(e.path()));
      if (m.value("kind", "") != "dem-run") continue;
      const auto scene = dem::parse_scene(m["scene"]["text"].get<std::string>(),
                                          m["scene"]["source"].get<std::string>());
      const auto checks = dem::plausibility_checks(
          dem::asked_by(scene), io::read_csv_table(e.path().parent_path() / "timeseries.csv"));
      INFO(e.path().parent_path().string());
      CHECK(dem::failure_reason(checks).value_or("all pass") == "all pass");
      ++runs;
    }
  CHECK(runs >= 48);  // 48 when this was written; campaigns add runs
}

namespace {
// The garbage run: the smoke scene at I = 1e6 (one timestep moves the wall 66 mm). A scene
// file asking for it is refused since (the inertial number is at most 1: tests/app/bad_inputs), so
// the scene is parsed valid and the speed set afterwards: the gate before `complete` must catch a
// garbage run whatever made it.
void garbage_run(const std::string& engine_name) {
  const std::string text = io::read_file("data/scenes/smoke.toml");
  auto scene = dem::parse_scene(text, "garbage.toml");
  scene.shear.velocity_m_s *= 1e9;
  scene.shear.inertial_number *= 1e9;
  const auto dir = fs::path(IWB_TEST_RUNS_DIR) / "dem" / engine_name / "garbage";
  const auto engine = dem::make_engine(engine_name);
  const auto outcome =
      dem::run_scene(scene, text, *engine,
                     {dir, 1, false, true, "tests", nullptr, nullptr, test::smoke_specimens()});
  CHECK_THAT(outcome.status, Catch::StartsWith("failed: implausible: ") &&
                                 Catch::Contains("displacement_not_overshot = ") &&
                                 Catch::Contains("rows = "));
  const auto m = nlohmann::json::parse(io::read_file(dir / "manifest.json"));
  CHECK(m["status"] == outcome.status);
  REQUIRE(m["plausibility"].size() == 6);
  int failures = 0;
  for (const auto& c : m["plausibility"]) failures += c["passed"] ? 0 : 1;
  CHECK(failures >= 2);  // at least the rows and the overshoot
  for (const auto& c : m["plausibility"])
    if (c["name"] == "displacement_not_overshot" || c["name"] == "rows")
      CHECK(c["passed"] == false);
  REQUIRE(m["files"].size() == 6);  // kept for a look at why, and listed
  for (const auto& f : m["files"]) CHECK(fs::exists(dir / f.get<std::string>()));
}
}  // namespace

TEST_CASE("LIGGGHTS: the smoke scene at inertial number 1e6 is failed as implausible, not complete",
          "[dem][liggghts]") {
  garbage_run("liggghts");
}
TEST_CASE("YADE: the smoke scene at inertial number 1e6 is failed as implausible, not complete",
          "[dem][yade][heavy]") {
  garbage_run("yade");
}
