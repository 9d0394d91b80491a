#pragma once
// `iwb pile PILE.toml`: the load-transfer analysis into a run directory (README.md here):
// manifest.json, load_settlement.csv, profiles.csv, mesh_convergence.csv (the same pile with half
// and twice the elements), summary.json and figures/.
#include <atomic>
#include <filesystem>
#include <functional>
#include <string>

#include "pile/pile_spec.hpp"

namespace iwb::pile {

struct PileRunOptions {
  std::filesystem::path out;
  bool force = false;
  std::string command_line;
  std::string spec_text;  // the file as given, kept in the directory
  const std::atomic<bool>* interrupt = nullptr;
  std::function<void(long, long)> on_step;  // (done, total) over the three meshes: progress
};

// Exit code: 0 complete, 1 failed or interrupted (manifest.json says why).
int run_pile(const PileSpec& spec, const PileRunOptions& options);

}  // namespace iwb::pile
