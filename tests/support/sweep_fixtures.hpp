#pragma once
// Sweep files written by the tests next to their runs, on the smoke scene of data/scenes.
#include <filesystem>
#include <string>

#include "campaign/sweep.hpp"
#include "io/run_directory.hpp"

namespace iwb::test {

inline std::filesystem::path campaign_dir(const std::string& name) {
  const auto dir = std::filesystem::path(IWB_TEST_RUNS_DIR) / "campaign" / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// A sweep file in `dir` on the smoke scene, with `body` after the scene line.
inline std::filesystem::path write_sweep(const std::filesystem::path& dir,
                                         const std::string& body) {
  const auto file = dir / "sweep.toml";
  io::write_atomically(
      file,
      "scene = \"" + std::filesystem::absolute("data/scenes/smoke.toml").string() + "\"\n" + body);
  return file;
}

inline campaign::SweepOptions sweep_options(const std::filesystem::path& sweep,
                                            const std::filesystem::path& out) {
  campaign::SweepOptions opt;
  opt.sweep_file = sweep;
  opt.out = out;
  opt.command_line = "iwb_tests";
  return opt;
}

}  // namespace iwb::test
