// The plan of seeds (claims/seed_plan.hpp) on runs written here. Two claims, each on two groups of
// runs: "rough-lower" (flat_s1-3 against rough_s1-5, rough_s5 at the plate and left out) and
// "other" (x_s1-3 against y_s1-3). Beside each other neither is resolved after Benjamini-Hochberg
// (tests/claims/test_claims.cpp), and the claims layer gives each the seeds a group would need, n.
// What the plan must make of n, by its stated rules:
//   - a group all of whose runs were kept needs n - (its runs) more; the rough group, 4 of 5 kept,
//     needs ceil((n - 4) 5 / 4): a run at the plate is as likely again;
//   - the new seeds follow the largest a group's manifests record (flat: 4..., rough: 6...);
//   - a run costs its group's mean engine core-hours: every run here 1 (flat: one rank for 1 h;
//     rough: two ranks for 0.5 h; x and y: one rank for 2 h, so "other" costs twice as much a run);
//   - claims are taken cheapest first within the budget, the rest left out saying so.
#include <toml++/toml.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "claims/claims.hpp"
#include "claims/seed_plan.hpp"
#include "support/case_directory.hpp"

using namespace iwb;
namespace fs = std::filesystem;

namespace {

// the running case's own directory (tests/support/case_directory.hpp)
fs::path plan_runs_dir() {
  return test::case_directory(fs::path(IWB_TEST_RUNS_DIR) / "seed_plan");
}

void write_planned_run(const std::string& name, int seed, double value, double hours, int ranks,
                       const std::string& mode = "localised at the wall") {
  fs::create_directories(plan_runs_dir() / name);
  std::ofstream(plan_runs_dir() / name / "summary.json")
      << nlohmann::json{{"peak_friction", value}, {"shear_mode", mode}}.dump();
  std::ofstream(plan_runs_dir() / name / "manifest.json") << nlohmann::json{
      {"seed", seed},
      {"engine", {{"name", "liggghts"}, {"processes", ranks}}},
      {"scene", {{"text", "description = 'the scene of " + name + "'\n"}}},
      {"stages",
       {{"shear",
         {{"status", "done"}, {"wall_seconds", hours * 3600}}}}}}.dump();
}

claims::ClaimsReport two_undecided_claims() {
  fs::remove_all(plan_runs_dir());
  const double a[] = {0.418, 0.392, 0.447}, b[] = {0.343, 0.301, 0.385, 0.37};
  for (int i = 0; i < 3; ++i)
    write_planned_run("flat_s" + std::to_string(i + 1), i + 1, a[i], 1.0, 1);
  for (int i = 0; i < 4; ++i)
    write_planned_run("rough_s" + std::to_string(i + 1), i + 1, b[i], 0.5, 2);
  write_planned_run("rough_s5", 5, 10.0, 0.5, 2, "localised at the plate");
  for (int i = 0; i < 3; ++i) {
    write_planned_run("x_s" + std::to_string(i + 1), i + 1, 0.40 + 0.01 * i, 2.0, 1);
    write_planned_run("y_s" + std::to_string(i + 1), i + 1, 0.41 - 0.02 * i, 2.0, 1);
  }
  std::string body = "q = 0.05\n";
  for (const auto& [id, a_, b_] :
       {std::tuple{"rough-lower", "flat_*", "rough_*"}, std::tuple{"other", "x_*", "y_*"}})
    body += std::string("[[claim]]\nid = \"") + id +
            "\"\nsays = \"s\"\nquantity = " + "\"/peak_friction\"\na = [\"" + a_ + "\"]\nb = [\"" +
            b_ + "\"]\nexpect = \"b != a\"\nflagged = \"exclude\"\n";
  std::ofstream(plan_runs_dir() / "claims.toml") << body;
  return claims::test_claims(claims::read_claims(plan_runs_dir() / "claims.toml"));
}

const claims::GroupPlan* group_of(const claims::SeedPlan& plan, const std::string& pattern) {
  for (const auto& g : plan.groups)
    if (g.patterns.front() == pattern) return &g;
  return nullptr;
}

}  // namespace

TEST_CASE("a seed plan counts the runs a group loses, numbers new seeds and prices them",
          "[claims]") {
  const auto report = two_undecided_claims();
  REQUIRE(report.results[0].status == "not resolved");
  REQUIRE(report.results[0].seeds_needed);
  const int n = *report.results[0].seeds_needed;
  const auto plan = claims::plan_seeds(report, 1000.0);
  const auto* flat = group_of(plan, "flat_*");
  const auto* rough = group_of(plan, "rough_*");
  REQUIRE(flat);
  REQUIRE(rough);
  CHECK(flat->to_run == n - 3);
  CHECK(rough->usable == 4);
  CHECK(rough->read == 5);
  CHECK(rough->to_run == int(std::ceil((n - 4) * 5.0 / 4.0)));
  CHECK(flat->seeds.front() == 4);
  CHECK(rough->seeds.front() == 6);
  CHECK(flat->core_hours_per_run == Approx(1.0));
  CHECK(rough->core_hours_per_run == Approx(1.0));
  CHECK(flat->scene_text == "description = 'the scene of flat_s1'\n");
}

TEST_CASE("a seed plan takes the cheaper claim first and leaves out what the budget cannot buy",
          "[claims]") {
  const auto report = two_undecided_claims();
  const auto all = claims::plan_seeds(report, 1000.0);
  double rough_lower = 0.0, other = 0.0;
  for (const auto& g : all.groups)
    (g.claims.front() == "rough-lower" ? rough_lower : other) += g.to_run * g.core_hours_per_run;
  REQUIRE(rough_lower > 0.0);
  REQUIRE(other > 0.0);
  CHECK(all.planned_core_hours == Approx(rough_lower + other));
  // a budget below the dearer claim but above the cheaper takes the cheaper alone
  const double cheaper = std::min(rough_lower, other), dearer = std::max(rough_lower, other);
  REQUIRE(dearer > cheaper);  // "other" costs 2 a run against 1
  const auto some = claims::plan_seeds(report, 0.5 * (cheaper + dearer));
  CHECK(some.planned_core_hours == Approx(cheaper));
  REQUIRE(some.left_out.size() == 1);
  CHECK(some.left_out[0].second.find("beyond the budget") != std::string::npos);
  const auto none = claims::plan_seeds(report, 0.5 * cheaper);
  CHECK(none.groups.empty());
  CHECK(none.left_out.size() == 2);
}

TEST_CASE("a seed plan writes a sweep per group that sets the new seeds on the group's scene",
          "[claims]") {
  const auto report = two_undecided_claims();
  const auto plan = claims::plan_seeds(report, 1000.0);
  const fs::path out = plan_runs_dir() / "plan";
  claims::write_seed_plan(plan, out);
  for (const auto& g : plan.groups) {
    const auto sweep = toml::parse_file((out / "sweeps" / (g.name + ".toml")).string());
    CHECK(sweep["engines"][0].value<std::string>() == "liggghts");
    const fs::path scene = out / "sweeps" / *sweep["scene"].value<std::string>();
    CHECK(fs::is_regular_file(scene));
    CHECK(sweep["axis"][0]["key"].value<std::string>() == "seed");
    const auto* values = sweep["axis"][0]["values"].as_array();
    REQUIRE(values);
    REQUIRE(values->size() == g.seeds.size());
    for (std::size_t k = 0; k < g.seeds.size(); ++k)
      CHECK((*values)[k].value<int64_t>() == g.seeds[k]);
  }
  CHECK(fs::is_regular_file(out / "plan.md"));
}

TEST_CASE("a seed plan names soil cells' runs by their command, and writes no sweep for them",
          "[claims]") {
  const fs::path dir = plan_runs_dir();
  fs::remove_all(dir);
  // three soil cells (no summary.json: the manifest's cell_summary) against three interface runs
  const double cells[] = {0.22, 0.16, 0.17}, walls[] = {0.22, 0.27, 0.19};
  for (int i = 0; i < 3; ++i) {
    const auto cell = dir / ("cell_s" + std::to_string(i + 1));
    fs::create_directories(cell);
    std::ofstream(cell / "manifest.json") << nlohmann::json{
        {"kind", "soiltest"},
        {"seed", i + 1},
        {"command_line", "iwb dem soiltest truth.toml --test simpleshear"},
        {"engine", {{"name", "liggghts"}, {"processes", 1}}},
        {"scene", {{"text", "description = 'the interface scene'\n"}}},
        {"stages", {{"shear", {{"wall_seconds", 360.0}}}}},
        {"cell_summary", {{"rate", cells[i]}}}}.dump();
    write_planned_run("wall_s" + std::to_string(i + 1), i + 1, walls[i], 1.0, 1);
    std::ofstream(dir / ("wall_s" + std::to_string(i + 1)) / "summary.json")
        << nlohmann::json{{"rate", walls[i]}, {"shear_mode", "localised at the wall"}}.dump();
  }
  std::ofstream(dir / "claims.toml")
      << "q = 0.05\n[[claim]]\nid = \"r\"\nsays = \"s\"\nquantity = \"/rate\"\na = "
         "[\"cell_s*\"]\nb = [\"wall_s*\"]\nexpect = \"b > a\"\nflagged = \"exclude\"\n"
         "[[claim]]\nid = \"other\"\nsays = \"s\"\nquantity = \"/rate\"\na = [\"wall_s*\"]\nb = "
         "[\"cell_s*\"]\nexpect = \"b != a\"\nflagged = \"exclude\"\n";
  const auto report = claims::test_claims(claims::read_claims(dir / "claims.toml"));
  const auto plan = claims::plan_seeds(report, 1000.0);
  const auto* cells_plan = group_of(plan, "cell_s*");
  REQUIRE(cells_plan);
  CHECK(cells_plan->soil_cells);
  CHECK(cells_plan->command_line == "iwb dem soiltest truth.toml --test simpleshear");
  CHECK(cells_plan->core_hours_per_run == Approx(0.1));
  claims::write_seed_plan(plan, dir / "plan");
  CHECK_FALSE(fs::exists(dir / "plan" / "sweeps" / (cells_plan->name + ".toml")));
}

TEST_CASE("a seed plan does not number seeds for a group whose runs do not record theirs",
          "[claims]") {
  auto report = two_undecided_claims();
  // flat_s2's manifest without its seed: a new run could repeat it
  const auto manifest = plan_runs_dir() / "flat_s2" / "manifest.json";
  auto m = nlohmann::json::parse(std::ifstream(manifest));
  m.erase("seed");
  std::ofstream(manifest) << m.dump();
  report = claims::test_claims(claims::read_claims(plan_runs_dir() / "claims.toml"));
  const auto plan = claims::plan_seeds(report, 1000.0);
  CHECK_FALSE(group_of(plan, "flat_*"));
  bool said = false;
  for (const auto& [id, why] : plan.left_out)
    said = said || (id == "rough-lower" && why.find("record their seed") != std::string::npos);
  CHECK(said);
}
