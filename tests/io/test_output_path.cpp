// Where commands write (issue 15, finding 6): a file destination that cannot be written is refused
// before anything runs, a staged directory appears whole or not at all, and a write that cannot
// land leaves no temporary file.
#include <catch2/catch.hpp>
#include <filesystem>

#include "common/errors.hpp"
#include "io/output_directory.hpp"
#include "io/output_path.hpp"
#include "io/run_directory.hpp"
#include "support/cli.hpp"

using namespace iwb;
namespace fs = std::filesystem;

namespace {
const fs::path kWork = fs::path(IWB_TEST_RUNS_DIR) / "output_path";

bool has_temporary(const fs::path& dir) {
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.path().filename().string().find(".tmp") != std::string::npos) return true;
  return false;
}
}  // namespace

TEST_CASE("output: a file destination that is a directory or lies under a file is refused",
          "[io]") {
  fs::remove_all(kWork);
  fs::create_directories(kWork / "dir");
  io::write_atomically(kWork / "file", "x");
  CHECK_THROWS_WITH(
      io::require_file_destination(kWork / "dir", "-o"),
      "-o " + (kWork / "dir").string() + ": is a directory; give the name of the file to write");
  CHECK_THROWS_WITH(io::require_file_destination(kWork / "file" / "a.toml", "-o"),
                    Catch::Contains((kWork / "file").string() + " is a file, not a directory"));
  CHECK_NOTHROW(io::require_file_destination(kWork / "new" / "a.toml", "-o"));
  CHECK_FALSE(fs::exists(kWork / "new"));  // checking writes nothing
}

TEST_CASE("output: a write onto a directory throws and leaves no temporary file", "[io]") {
  fs::remove_all(kWork);
  fs::create_directories(kWork / "target");
  CHECK_THROWS_AS(io::write_atomically(kWork / "target", "content"), fs::filesystem_error);
  CHECK_FALSE(has_temporary(kWork));
}

TEST_CASE("output: a staged directory appears only when committed and replaces the earlier one",
          "[io]") {
  fs::remove_all(kWork);
  {
    io::StagedDirectory first(kWork / "figures");
    io::write_atomically(first.path() / "old.svg", "old");
    first.commit();
  }
  {
    io::StagedDirectory staged(kWork / "figures");
    io::write_atomically(staged.path() / "new.svg", "new");
    CHECK(fs::exists(kWork / "figures" / "old.svg"));  // not yet
  }                                                    // abandoned: as if a figure had failed
  CHECK(fs::exists(kWork / "figures" / "old.svg"));
  CHECK_FALSE(has_temporary(kWork));
  io::write_atomically(kWork / "figures" / "notes.txt", "mine");  // the user's, kept
  io::StagedDirectory staged(kWork / "figures");
  io::write_atomically(staged.path() / "new.svg", "new");
  staged.commit();
  auto files = test::files_under(kWork / "figures");
  files.erase(io::kLedgerFileName);
  CHECK(files == std::map<std::string, std::string>{{"new.svg", "new"}, {"notes.txt", "mine"}});
  CHECK_FALSE(has_temporary(kWork));
}

TEST_CASE("output: a staged directory never replaces a file the workbench did not write", "[io]") {
  fs::remove_all(kWork);
  io::write_atomically((fs::create_directories(kWork / "figures"), kWork / "figures" / "a.svg"),
                       "the user's");
  io::StagedDirectory staged(kWork / "figures");
  io::write_atomically(staged.path() / "a.svg", "ours");
  CHECK_THROWS_WITH(staged.commit(), Catch::Contains("a.svg"));
  CHECK(io::read_file(kWork / "figures" / "a.svg") == "the user's");
}

TEST_CASE("calibrate -o naming a directory is refused before fitting, leaving no temporary file",
          "[io][calibration]") {
  // its own directory: the other cases of this file empty kWork, and ctest runs them beside it
  const fs::path work = fs::path(IWB_TEST_RUNS_DIR) / "output_path_calibrate";
  fs::remove_all(work);
  fs::create_directories(work / "params");
  const auto r = test::run_iwb({"calibrate", "data/calibration/dem_default_grains/oedometer-dense",
                                "-o", (work / "params").string()});
  CHECK(r.exit_code == 2);
  // refused by the option's check, before anything is fitted
  CHECK_THAT(r.output, Catch::StartsWith("error: iwb calibrate: --out: " +
                                         (work / "params").string() + ": is a directory"));
  CHECK(test::files_under(work).empty());
  CHECK_FALSE(has_temporary(work));
}
