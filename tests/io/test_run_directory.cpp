// Output directories are the workbench's alone (issue 60): a command writes only into a new or
// empty directory or an earlier output of its own kind, and --force removes exactly the files the
// ledger says the workbench wrote. (Before: --force emptied any directory holding a manifest, so a
// user's thesis.txt beside a run was deleted; and a YADE smoke run kept a snapshot of an earlier
// run at a step the new one never reached, which --force must still remove.)
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <thread>

#include "common/errors.hpp"
#include "io/run_directory.hpp"

using namespace iwb;
namespace fs = std::filesystem;

namespace {

const io::OutputKind kRun{"element-test"};

fs::path fresh(const std::string& name) {
  const fs::path dir = fs::path(IWB_TEST_RUNS_DIR) / "io" / "output_directory" / name;
  fs::remove_all(dir);
  return dir;
}

void write(const fs::path& file, const std::string& text) {
  fs::create_directories(file.parent_path());
  std::ofstream(file) << text;
}

std::set<std::string> ledger_of(const fs::path& dir) {
  const auto j = nlohmann::json::parse(io::read_file(dir / io::kLedgerFileName));
  return j.at("written").get<std::set<std::string>>();
}

}  // namespace

TEST_CASE("output directory: --force removes the earlier run's files and keeps the user's",
          "[io]") {
  const fs::path dir = fresh("replaced_run");
  io::prepare_run_directory(dir, kRun, false);
  write(dir / "vtk" / "walls_00053207.vtk", "stale\n");  // a snapshot the next run never reaches
  io::write_manifest(dir, {{"kind", "element-test"}, {"status", "complete"}});
  CHECK(ledger_of(dir) == std::set<std::string>{"manifest.json", "vtk/walls_00053207.vtk"});
  io::release_claimed_directories();    // the command ends
  write(dir / "thesis.txt", "mine\n");  // put there after the run
  CHECK_THROWS_AS(io::prepare_run_directory(dir, kRun, false), InputError);  // no --force
  const auto kept = io::prepare_run_directory(dir, kRun, true);
  CHECK(kept == std::vector<std::string>{"thesis.txt"});
  CHECK_FALSE(fs::exists(dir / "vtk"));  // emptied by the removal, so removed
  CHECK_FALSE(fs::exists(dir / "manifest.json"));
  CHECK(io::read_file(dir / "thesis.txt") == "mine\n");
  // the new run's files are its own, the user's file stays the user's through another --force
  io::write_manifest(dir, {{"kind", "element-test"}, {"status", "complete"}});
  CHECK(ledger_of(dir) == std::set<std::string>{"manifest.json"});
  io::prepare_run_directory(dir, kRun, true);
  CHECK(io::read_file(dir / "thesis.txt") == "mine\n");
}

TEST_CASE("output directory: a directory of the user's or of another kind is refused untouched",
          "[io]") {
  const fs::path user = fresh("users");
  write(user / "thesis.txt", "mine\n");
  const auto before = fs::last_write_time(user);
  for (bool force : {false, true}) {
    REQUIRE_THROWS_AS(io::prepare_run_directory(user, kRun, force), InputError);
    try {
      io::prepare_run_directory(user, kRun, force);
    } catch (const InputError& e) {  // names the directory and a file in it that is not ours
      CHECK_THAT(e.what(), Catch::Contains(user.string()) && Catch::Contains("thesis.txt"));
    }
  }
  CHECK(fs::last_write_time(user) == before);
  CHECK(std::distance(fs::directory_iterator(user), fs::directory_iterator()) == 1);

  const fs::path other = fresh("other_kind");
  io::prepare_run_directory(other, {"pile"}, false);
  CHECK_THROWS_WITH(io::prepare_run_directory(other, kRun, true),
                    Catch::Contains("'pile'") && Catch::Contains("'element-test'"));
  CHECK(fs::exists(other / io::kLedgerFileName));
}

TEST_CASE("output directory: a run from before the ledger is reused, never replaced", "[io]") {
  const fs::path dir = fresh("legacy");
  write(dir / "manifest.json", R"({"kind": "element-test", "status": "complete"})");
  write(dir / "history.csv", "u\n0\n");
  CHECK_NOTHROW(io::require_output_directory(dir, kRun, false));  // resumed, reused
  CHECK_THROWS_WITH(io::require_output_directory(dir, kRun, true),
                    Catch::Contains(io::kLedgerFileName));
  CHECK_THROWS_AS(io::require_output_directory(dir, {"pile"}, false), InputError);  // not a pile
}

TEST_CASE("output directory: a killed run's file written again by its successor is its own",
          "[io]") {
  const fs::path dir = fresh("killed");
  io::claim_output_directory(dir, kRun, false);
  write(dir / "history.csv", "killed before it was entered in the ledger\n");
  write(dir / "dumps" / "left.dump", "never written again\n");
  // a second process: what it finds unlisted is not known to be ours
  const fs::path second = fresh("killed_second");
  fs::rename(dir, second);
  io::claim_output_directory(second, kRun, false);
  std::this_thread::sleep_for(std::chrono::milliseconds(20));  // a later mtime, on any clock
  write(second / "history.csv", "written again\n");
  io::record_written_files(second);
  CHECK(ledger_of(second) == std::set<std::string>{"history.csv"});
  io::claim_output_directory(second, kRun, true);
  CHECK_FALSE(fs::exists(second / "history.csv"));
  CHECK(fs::exists(second / "dumps" / "left.dump"));  // kept: nothing says it is ours
}

TEST_CASE("output directory: a ledger that names a file outside its directory is refused", "[io]") {
  const fs::path root = fresh("escape");
  const fs::path dir = root / "run";
  write(root / "thesis.txt", "mine\n");
  write(dir / io::kLedgerFileName,
        R"({"kind": "element-test", "written": ["../thesis.txt", "history.csv"]})");
  CHECK_THROWS_WITH(io::prepare_run_directory(dir, kRun, true),
                    Catch::Contains("\"../thesis.txt\" lies outside"));
  CHECK(io::read_file(root / "thesis.txt") == "mine\n");
}
