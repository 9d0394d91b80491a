#pragma once
// Evidence where it decides (issue 59 item 4): the runs a campaign should add so that the claims
// its seeds leave undecided can be resolved, within a stated budget of engine core-hours.
//
// For each claim not resolved, the claims layer gives the seeds a group would need at the
// measured effect and scatter for its p to reach q / m (claims.hpp). Per group:
//   - usable: the runs kept; read: kept and excluded (split, at the plate, residual not steady).
//     A new run is usable with the share usable / read, so (needed - usable) usable runs take
//     ceil((needed - usable) read / usable) runs; a group none of whose runs was kept cannot be
//     planned (its scene needs changing, not more seeds), and is named so;
//   - each run costs the group's mean engine core-hours (engine_core_hours: a lower bound);
//   - the new seeds are the next above every seed the group's runs have (manifest.json "seed"),
//     and the scene the text a kept run ran (manifest.json scene.text), the seed set by the sweep;
//     a group some of whose runs record no seed is not planned (a new seed could repeat one).
// A group shared by claims is planned once, for the most runs any of them needs. Claims are taken
// cheapest first (the runs their groups still need, priced) while the total stays within the
// budget; the rest are listed with why they were left out.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "claims/claims.hpp"

namespace iwb::claims {

struct GroupPlan {
  std::string name;                   // for its files: from the group's first pattern
  std::vector<std::string> patterns;  // as the claims file names them
  std::string scene_text, engine;
  // a group of soil cells (`iwb dem soiltest`): no sweep runs them; the command a kept run was
  // made with is given instead, to be run with the new seeds
  bool soil_cells = false;
  std::string command_line;
  int usable = 0, read = 0, needed = 0, to_run = 0;
  std::vector<int> seeds;  // the new runs' seeds
  double core_hours_per_run = 0.0;
  std::vector<std::string> claims;  // the claims it serves
};

struct SeedPlan {
  double budget_core_hours = 0.0;
  double planned_core_hours = 0.0;
  std::vector<GroupPlan> groups;                              // groups with runs to add
  std::vector<std::pair<std::string, std::string>> left_out;  // claim, why
};

SeedPlan plan_seeds(const ClaimsReport& report, double budget_core_hours);

// DIR/plan.md and plan.json, and per group of interface runs DIR/scenes/<name>.toml and
// DIR/sweeps/<name>.toml (an `iwb sweep` file over the seed alone). The caller has claimed DIR.
void write_seed_plan(const SeedPlan& plan, const std::filesystem::path& dir);
std::string markdown(const SeedPlan& plan);
nlohmann::json to_json(const SeedPlan& plan);

}  // namespace iwb::claims
