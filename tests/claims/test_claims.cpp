// The claims layer (claims/claims.hpp) on runs written here with known values: Welch's p for the
// groups below is 0.0361 (SciPy 1.10, scipy.stats.ttest_ind with equal_var=False; the statistics
// themselves are held in tests/statistics/test_group_tests.cpp), so alone the claim is supported at
// q 0.05; beside a second claim of p 0.8, Benjamini-Hochberg adjusts it to 2 x 0.0361 = 0.072 and
// it is not resolved. A run that formed its band at the plate, with a value far off, changes
// nothing where the claim excludes such runs.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "claims/claims.hpp"
#include "common/errors.hpp"
#include "support/case_directory.hpp"

using namespace iwb;
namespace fs = std::filesystem;

namespace {

// the running case's own directory (tests/support/case_directory.hpp)
fs::path runs_dir() {
  return test::case_directory(fs::path(IWB_TEST_RUNS_DIR) / "claims");
}

void write_summary(const std::string& name, double value,
                   const std::string& mode = "localised at the wall") {
  fs::create_directories(runs_dir() / name);
  std::ofstream(runs_dir() / name / "summary.json")
      << nlohmann::json{{"peak_friction", value}, {"shear_mode", mode}}.dump();
}

std::string claim(const std::string& id, const std::string& a, const std::string& b,
                  const std::string& flagged = "exclude") {
  return "[[claim]]\nid = \"" + id + "\"\nsays = \"s\"\nquantity = \"/peak_friction\"\na = [\"" +
         a + "\"]\nb = [\"" + b + "\"]\nexpect = \"b < a\"\nflagged = \"" + flagged + "\"\n";
}

claims::ClaimsReport test_file(const std::string& body) {
  std::ofstream(runs_dir() / "claims.toml") << "q = 0.05\n" << body;
  return claims::test_claims(claims::read_claims(runs_dir() / "claims.toml"));
}

void write_runs() {
  fs::remove_all(runs_dir());
  const double a[] = {0.418, 0.392, 0.447}, b[] = {0.343, 0.301, 0.385, 0.37};
  for (int i = 0; i < 3; ++i) write_summary("flat_s" + std::to_string(i + 1), a[i]);
  for (int i = 0; i < 4; ++i) write_summary("rough_s" + std::to_string(i + 1), b[i]);
  write_summary("rough_s5", 10.0, "localised at the plate");
  for (int i = 0; i < 3; ++i) write_summary("x_s" + std::to_string(i + 1), 0.40 + 0.01 * i);
  for (int i = 0; i < 3; ++i) write_summary("y_s" + std::to_string(i + 1), 0.41 - 0.02 * i);
}

}  // namespace

TEST_CASE("a claim alone is supported where Welch's test is significant in its direction",
          "[claims]") {
  write_runs();
  const auto r = test_file(claim("rough-lower", "flat_*", "rough_*"));
  REQUIRE(r.results.size() == 1);
  const auto& c = r.results[0];
  CHECK(c.b.sample.n == 4);  // rough_s5 formed its band at the plate: left out
  REQUIRE(c.b.excluded.size() == 1);
  CHECK(c.b.excluded[0].second == "localised at the plate");
  CHECK(c.difference->p_value == Approx(0.03609332062368329).epsilon(1e-6));
  CHECK(c.p_adjusted == Approx(c.difference->p_value));
  CHECK(c.status == "supported");
}

TEST_CASE("beside a second claim the same test is not resolved after Benjamini-Hochberg",
          "[claims]") {
  write_runs();
  const auto r =
      test_file(claim("rough-lower", "flat_*", "rough_*") + claim("other", "x_*", "y_*"));
  REQUIRE(r.results.size() == 2);
  CHECK(r.results[0].p_adjusted == Approx(2.0 * 0.03609332062368329).epsilon(1e-6));
  CHECK(r.results[0].status == "not resolved");
  CHECK(r.results[0].seeds_needed.has_value());
  // a run at the plate kept where the claim says so: its 10.0 reverses the sign
  const auto kept = test_file(claim("rough-lower", "flat_*", "rough_*", "include"));
  CHECK(kept.results[0].b.flagged_included == 1);
  CHECK(kept.results[0].difference->effect > 0.0);
  CHECK(kept.results[0].status != "supported");
}

TEST_CASE("a claim on the residual leaves out runs whose friction has not settled", "[claims]") {
  // the same values as the supported claim above, as residuals; one rough run's residual is not
  // steady and far off (10.0): excluded it changes nothing, included it reverses the sign
  write_runs();
  const auto residual = [](const std::string& name, double value, const std::string& is) {
    std::ofstream(runs_dir() / name / "summary.json") << nlohmann::json{
        {"residual_friction", value},
        {"residual_is", is},
        {"shear_mode", "localised at the wall"}}.dump();
  };
  const double a[] = {0.418, 0.392, 0.447}, b[] = {0.343, 0.301, 0.385, 0.37};
  for (int i = 0; i < 3; ++i) residual("flat_s" + std::to_string(i + 1), a[i], "steady");
  for (int i = 0; i < 4; ++i) residual("rough_s" + std::to_string(i + 1), b[i], "steady");
  residual("rough_s5", 10.0, "not steady");
  auto on_residual = [](std::string text) {
    return text.replace(text.find("/peak_friction"), 14, "/residual_friction");
  };
  const auto r = test_file(on_residual(claim("rough-lower", "flat_*", "rough_*")));
  REQUIRE(r.results[0].b.excluded.size() == 1);
  CHECK(r.results[0].b.excluded[0].second == "residual not steady");
  CHECK(r.results[0].difference->p_value == Approx(0.03609332062368329).epsilon(1e-6));
  // flagged = "include" is about runs off the wall; the unsettled run stays out
  const auto off_wall =
      test_file(on_residual(claim("rough-lower", "flat_*", "rough_*", "include")));
  CHECK(off_wall.results[0].b.excluded.size() == 1);
  // unsteady = "include": the claim is on the friction at the stated travel, the run counts
  const auto kept = test_file(on_residual(claim("rough-lower", "flat_*", "rough_*")) +
                              "unsteady = \"include\"\n");
  CHECK(kept.results[0].b.excluded.empty());
  CHECK(kept.results[0].difference->effect > 0.0);
}

TEST_CASE("group b reads its own pointer where its runs are of another kind", "[claims]") {
  // a post-cyclic peak against a virgin one: the rough runs carry the values of the supported
  // claim above under /cyclic/post_cyclic/peak_friction and a decoy 10.0 at /peak_friction; read
  // at their own pointer they give the same p, read at group a's the decoy
  write_runs();
  const double b[] = {0.343, 0.301, 0.385, 0.37};
  for (int i = 0; i < 4; ++i) {
    nlohmann::json s = {{"peak_friction", 10.0}, {"shear_mode", "localised at the wall"}};
    s["cyclic"]["post_cyclic"]["peak_friction"] = b[i];
    std::ofstream(runs_dir() / ("rough_s" + std::to_string(i + 1)) / "summary.json") << s.dump();
  }
  const auto own = test_file(claim("rough-lower", "flat_*", "rough_*") +
                             "quantity_b = \"/cyclic/post_cyclic/peak_friction\"\n");
  CHECK(own.results[0].difference->p_value == Approx(0.03609332062368329).epsilon(1e-6));
  CHECK(own.results[0].status == "supported");
  const auto shared = test_file(claim("rough-lower", "flat_*", "rough_*"));
  CHECK(shared.results[0].difference->effect > 9.0);
  // a relative change on one side only compares a ratio with a value: refused
  CHECK_THROWS_WITH(
      test_file(claim("rough-lower", "flat_*", "rough_*") + "relative_to_b = \"/peak_friction\"\n"),
      Catch::Contains("both groups are relative changes or neither"));
}

TEST_CASE("a claim of equality is shown only by two one-sided tests within its margin",
          "[claims]") {
  // x = 0.40, 0.41, 0.42 and y = 0.41, 0.39, 0.37 (write_runs): SciPy 1.10's one-sided Welch tests
  // of y shifted by the margin give 0.00449 at +-0.1 and 0.752 at +-0.01
  write_runs();
  const auto equal = [](double margin) {
    auto text = claim("same", "x_*", "y_*");
    text.replace(text.find("b < a"), 5, "b = a");
    return text + "margin = " + std::to_string(margin) + "\n";
  };
  const auto wide = test_file(equal(0.1));
  CHECK(wide.results[0].p == Approx(0.004485343250761535).epsilon(1e-6));
  CHECK(wide.results[0].status == "supported");
  const auto narrow = test_file(equal(0.01));
  CHECK(narrow.results[0].p == Approx(0.7519723127707378).epsilon(1e-6));
  CHECK(narrow.results[0].status == "not resolved");
  CHECK(claims::markdown(narrow).find("equal within ±0.01") != std::string::npos);
  // an equality without its margin is refused, naming the key
  auto bare = claim("same", "x_*", "y_*");
  bare.replace(bare.find("b < a"), 5, "b = a");
  CHECK_THROWS_WITH(test_file(bare), Catch::Contains("margin"));
}

TEST_CASE("a claims file with a repeated id or a pattern naming no run is refused", "[claims]") {
  write_runs();
  CHECK_THROWS_WITH(test_file(claim("a", "flat_*", "rough_*") + claim("a", "x_*", "y_*")),
                    Catch::Contains("another claim has this id"));
  CHECK_THROWS_AS(test_file(claim("a", "none_*", "rough_*")), InputError);
}

// Core-hours per resolved claim (issue 59 item 4): flat_s1-3 ran one rank for an hour each (a
// consolidation of 600 s and a shear of 3000 s), rough_s1-5 two ranks for half an hour each, the
// run at the plate included (it cost as much though its value is left out): 3 x 1 + 5 x 2 x 0.5 =
// 8 core-hours over 8 runs; the claim above is then the only one resolved.
TEST_CASE("a claims family states what its runs cost per resolved claim", "[claims]") {
  write_runs();
  const auto manifest = [](const std::string& run, double consolidate_s, double shear_s, int np) {
    std::ofstream(runs_dir() / run / "manifest.json")
        << nlohmann::json{{"engine", {{"name", "liggghts"}, {"processes", np}}},
                          {"stages",
                           {{"consolidate", {{"status", "done"}, {"wall_seconds", consolidate_s}}},
                            {"shear", {{"status", "done"}, {"wall_seconds", shear_s}}}}}}
               .dump();
  };
  for (int i = 1; i <= 3; ++i) manifest("flat_s" + std::to_string(i), 600.0, 3000.0, 1);
  for (int i = 1; i <= 5; ++i) manifest("rough_s" + std::to_string(i), 300.0, 1500.0, 2);
  CHECK(claims::engine_core_hours(runs_dir() / "flat_s1") == Approx(1.0));
  CHECK_FALSE(claims::engine_core_hours(runs_dir() / "x_s1"));  // no manifest
  const auto r = test_file(claim("rough-lower", "flat_*", "rough_*"));
  CHECK(r.cost.runs == 8);
  CHECK(r.cost.runs_without_record == 0);
  CHECK(r.cost.core_hours == Approx(8.0));
  CHECK_THAT(claims::markdown(r),
             Catch::Contains("8.0 core-hours per resolved claim (1 resolved)"));
  // the same runs in a second claim are counted once; runs without a manifest are counted apart
  const auto two = test_file(claim("rough-lower", "flat_*", "rough_*") +
                             claim("again", "rough_*", "flat_*") + claim("other", "x_*", "y_*"));
  CHECK(two.cost.runs == 14);
  CHECK(two.cost.runs_without_record == 6);
  CHECK(two.cost.core_hours == Approx(8.0));
}
