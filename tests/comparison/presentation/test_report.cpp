// `iwb report` writes whole or not at all (issue 15, finding 6): every input is read and checked
// before anything is written, the figures are built beside their directory and put in place at the
// end, a good earlier report survives a refused one, a comparison that did not finish is refused
// and a DEM run that did not complete is flagged where a reader sees it.
#include <catch2/catch.hpp>
#include <filesystem>

#include "io/run_directory.hpp"
#include "support/cli.hpp"
#include "support/replaced.hpp"

using namespace iwb;
namespace fs = std::filesystem;

namespace {

const fs::path kReportWork = fs::path(IWB_TEST_RUNS_DIR) / "report";
const fs::path kRun = "data/reference/reference_rn/runs/sawtooth-2-0.5_cnl_s1";
const fs::path kParams = "data/params/dem_default_grains.toml";

// A fresh comparison of `run` at kReportWork/name (half a second).
fs::path fresh_comparison(const std::string& name, const fs::path& run = kRun,
                          bool allow_partial = false) {
  const fs::path out = kReportWork / name;
  std::vector<std::string> args = {"compare", run.string(), "--params", kParams.string(),
                                   "-o",      out.string(), "--force"};
  if (allow_partial) args.push_back("--allow-partial");
  const auto r = test::run_iwb(args);
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  return out;
}

// `iwb report inputs -o out/report.html` must exit 2 with `message`, and `out` must hold what it
// held before.
void refused(const std::vector<std::string>& inputs, const fs::path& out,
             const std::string& message) {
  const auto before = test::files_under(out);
  std::vector<std::string> args = {"report"};
  args.insert(args.end(), inputs.begin(), inputs.end());
  args.insert(args.end(), {"-o", (out / "report.html").string()});
  const auto r = test::run_iwb(args);
  INFO(r.output);
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.output, Catch::Contains(message));
  CHECK(test::files_under(out) == before);
}

}  // namespace

TEST_CASE("report: bad inputs exit 2 and write nothing, not even the figures directory",
          "[comparison]") {
  const fs::path out = kReportWork / "bad_out";
  fs::remove_all(out);
  fs::create_directories(kReportWork / "empty");
  refused({(kReportWork / "empty").string()}, out, "empty: neither a directory of `iwb compare`");

  const auto truncated = fresh_comparison("truncated");
  const std::string csv = io::read_file(truncated / "compare.csv");
  io::write_atomically(truncated / "compare.csv",
                       csv.substr(0, csv.find('\n', csv.size() / 3) + 1));  // whole rows
  refused({truncated.string()}, out,
          (truncated / "compare.csv").string() + ": changed since `iwb compare` wrote it");
  fs::remove(truncated /
             "manifest.json");  // a comparison of an older iwb, without hashes: the rows tell
  io::write_atomically(truncated / "manifest.json", "{\"status\": \"complete\"}");
  refused({truncated.string()}, out, (truncated / "compare.csv").string() + ": variant 1 has");

  const auto unlisted = fresh_comparison("no_manifest");
  fs::remove(unlisted / "manifest.json");
  refused({unlisted.string()}, out, (unlisted / "manifest.json").string() + ": missing");

  const auto cut = fresh_comparison("cut_manifest");
  io::write_atomically(cut / "manifest.json", io::read_file(cut / "manifest.json").substr(0, 100));
  refused({cut.string()}, out, (cut / "manifest.json").string() + ": not valid JSON");

  // the good comparison first: its figures must not be drawn before the bad one is found
  refused({fresh_comparison("good").string(), (kReportWork / "empty").string()}, out,
          "neither a directory");
  CHECK_FALSE(fs::exists(out));
}

TEST_CASE("report: a comparison whose manifest says failed is refused, naming its status",
          "[comparison]") {
  const auto failed = fresh_comparison("failed");
  test::edit_file(failed / "manifest.json", "\"status\": \"complete\"",
                  "\"status\": \"failed: the replay diverged\"");
  refused({failed.string()}, kReportWork / "failed_out",
          "the comparison's status is 'failed: the replay diverged'; a report shows finished "
          "comparisons only");
}

TEST_CASE("report: -o naming a directory is refused and leaves no temporary file", "[comparison]") {
  const fs::path dir = kReportWork / "o_is_dir";
  fs::remove_all(dir);
  fs::create_directories(dir / "report.html");
  refused({fresh_comparison("for_dir").string()}, dir,
          "--out: " + (dir / "report.html").string() + ": is a directory");
  for (const auto& e : fs::recursive_directory_iterator(kReportWork))
    CHECK(e.path().filename().string().find(".tmp") == std::string::npos);
}

TEST_CASE("report: a new report replaces the old one whole, a refused one leaves it as it was",
          "[comparison]") {
  const fs::path out = kReportWork / "replace";
  fs::remove_all(out);
  const auto earlier = fresh_comparison("replace_earlier");
  const auto good = fresh_comparison("replace_good");
  auto r = test::run_iwb({"report", earlier.string(), "-o", (out / "report.html").string()});
  REQUIRE(r.exit_code == 0);
  REQUIRE(fs::exists(out / "report_files" / "0-replace_earlier" / "tau_ux.svg"));
  io::write_atomically(out / "report_files" / "notes.txt", "mine");  // the user's (issue 60)
  r = test::run_iwb({"report", good.string(), "-o", (out / "report.html").string()});
  REQUIRE(r.exit_code == 0);
  CHECK_FALSE(fs::exists(out / "report_files" / "0-replace_earlier"));  // the earlier figures
  CHECK(io::read_file(out / "report_files" / "notes.txt") == "mine");
  CHECK(fs::exists(out / "report_files" / "0-replace_good" / "tau_ux.svg"));
  refused({(kReportWork / "empty").string()}, out, "neither a directory");  // the good report stays
  CHECK(fs::exists(out / "report_files" / "0-replace_good" / "tau_ux.svg"));
}

TEST_CASE("report: a DEM run that did not complete, compared with --allow-partial, is flagged",
          "[comparison]") {
  const fs::path run = kReportWork / "implausible_run";
  test::fresh_copy(kRun, run);
  test::edit_file(run / "manifest.json", "\"status\": \"complete\"",
                  "\"status\": \"failed: implausible: normal_stress_held = 0.6, must be <= 0.5\"");
  const auto partial = fresh_comparison("partial", run, true);
  const fs::path out = kReportWork / "partial_out";
  const auto r = test::run_iwb({"report", partial.string(), "-o", (out / "report.html").string()});
  REQUIRE(r.exit_code == 0);
  const std::string html = io::read_file(out / "report.html");
  CHECK_THAT(html, Catch::Contains("Warning: the DEM run " + run.string() +
                                   " did not complete (status: failed: implausible"));
  CHECK_THAT(html,
             Catch::Contains(
                 "<td class=\"breaks\">failed: implausible: normal_stress_held"));  // glance table
}

TEST_CASE(
    "report: a DEM run with coarse-grained fields shows its band (maps, profiles, void ratio in "
    "d_s)",
    "[comparison]") {
  // the smoke scene in LIGGGHTS (~10 s), coarse-grained when it completes (issue 21)
  const fs::path run = kReportWork / "smoke-with-fields";
  const auto dem =
      test::run_iwb({"dem", "run", "data/scenes/smoke.toml", "--out", run.string(), "--force"});
  INFO(dem.output);
  REQUIRE(dem.exit_code == 0);
  const fs::path out = fresh_comparison("smoke-with-fields-compare", run);
  const fs::path html = kReportWork / "band-report" / "report.html";
  const auto r = test::run_iwb({"report", out.string(), "-o", html.string()});
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const fs::path figures = html.parent_path() / "report_files" / "0-smoke-with-fields-compare";
  // three snapshots (0, 1, 2 mm): the maps at 1 and 2 mm
  for (const char* f : {"band_map_1", "band_map_2", "band_profiles", "band_void_ratio"})
    CHECK(fs::exists(figures / (std::string(f) + ".svg")));
  const std::string page = io::read_file(html);
  CHECK_THAT(page, Catch::Contains("over x-z at u_x = 1.") &&
                       Catch::Contains("Void ratio change inside the shear zone"));
  // the DEM's void ratio change starts at zero in each zone (columns x0 y0: the predicted d_s)
  // (the figure's CSV pads shorter curves with nan, which read_csv_table refuses: read its first
  // row)
  const std::string csv = io::read_file(figures / "band_void_ratio.csv");
  const auto first = csv.substr(csv.find('\n') + 1);
  CHECK(first.rfind("x0", 0) != 0);
  CHECK(std::stod(first.substr(0, first.find(','))) == 0.0);
  const auto rest = first.substr(first.find(',') + 1);
  CHECK(std::stod(rest.substr(0, rest.find(','))) == 0.0);
}
