// A run directory replaced with --force holds nothing of the earlier run: a YADE smoke run kept a
// snapshot of an earlier run at a step the new one never reached, and its pvd listed it as its own.
#include <catch2/catch.hpp>
#include <filesystem>

#include "common/errors.hpp"
#include "io/run_directory.hpp"

using namespace iwb;
namespace fs = std::filesystem;

TEST_CASE("a forced run directory is emptied, an unforced one is refused, a foreign one is kept",
          "[io]") {
  const fs::path dir = fs::path(IWB_TEST_RUNS_DIR) / "io" / "replaced_run";
  fs::remove_all(dir);
  fs::create_directories(dir / "vtk");
  io::write_atomically(dir / "manifest.json", "{}\n");
  io::write_atomically(dir / "vtk" / "walls_00053207.vtk", "stale\n");
  CHECK_THROWS_AS(io::prepare_run_directory(dir, false), InputError);
  CHECK(fs::exists(dir / "vtk" / "walls_00053207.vtk"));
  io::prepare_run_directory(dir, true);
  CHECK(fs::is_directory(dir));
  CHECK(fs::is_empty(dir));
  // a directory without a manifest is not a run of ours: nothing in it is removed
  const fs::path foreign = fs::path(IWB_TEST_RUNS_DIR) / "io" / "foreign";
  fs::create_directories(foreign);
  io::write_atomically(foreign / "notes.txt", "mine\n");
  io::prepare_run_directory(foreign, true);
  CHECK(fs::exists(foreign / "notes.txt"));
}
