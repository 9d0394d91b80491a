#pragma once
// `iwb tradeoff`: speed against accuracy of a DEM scene (issue 7, item 4). The scene is run at its
// own setting with K seeds (the seed scatter is the noise floor), with each knob (knobs.hpp)
// halved and doubled one at a time, with every knob refined at once (the reference) and coarsened
// at once. The runs are jobs of a campaign (src/campaign/pool.hpp): at most N at once, complete
// runs reused and stopped ones resumed when the tradeoff is run again. Each quantity of interest
// (dem/scene/requirements.hpp) is measured against the reference, with its cost in particle-steps
// and wall time: tradeoff.json, tradeoff.csv, tradeoff.md and pareto.svg/.png.
#include <atomic>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "campaign/jobs.hpp"
#include "io/output_directory.hpp"

namespace iwb::tradeoff {

// A tradeoff's directory (issue 60): resumed by a later tradeoff, shared with a plan's plan.json.
inline const io::OutputKind kTradeoffOutput{"tradeoff", "tradeoff.json"};
// a plan writes plan.json into a directory of its own or beside its tradeoff
inline const io::OutputKind kPlanOutput{"plan", "plan.json", {kTradeoffOutput}};

// What the errors are measured against. kRefined: every knob refined at once, one seed (a scene
// not known to be converged). kBase: the scene itself, the mean of its seeds (a scene a
// convergence study has shown converged, data/convergence/: refining it further costs many times
// the scene and says nothing new); then only the coarsening direction of each knob is run.
enum class Reference { kRefined, kBase };
Reference parse_reference(const std::string& text);
const char* to_string(Reference r);

struct TradeoffOptions {
  std::filesystem::path scene_file;
  std::filesystem::path out;  // empty: runs/tradeoff-<scene stem>
  std::vector<std::string> knobs = {"box", "kappa", "dt", "I"};
  int seeds = 3;  // of the base setting
  Reference reference = Reference::kRefined;
  int jobs = 1;
  int processes = 1;
  int stop_after = 0;  // stop cleanly once this many jobs have ended (tests of the resume)
  std::string command_line;
  const std::atomic<bool>* interrupt = nullptr;
  std::function<void(const std::string&)> progress;
};

// One setting of the scene: a campaign job plus what it varies.
struct Variant {
  campaign::Job job;
  std::string kind;  // "base", "knob", "refined" (the reference), "coarsened"
  std::string knob;  // kind "knob": which
  double factor = 1.0;
  int seed = 1;
};

// Every variant, the base seeds first and the reference (most expensive) next, so that the
// longest job starts early. InputError (nothing run) when a variant is not a valid scene.
std::vector<Variant> expand_variants(const TradeoffOptions& options);

// Runs (or reuses) the variants, then analyses what completed. The returned tradeoff.json has
// "status" "complete" when every run completed.
nlohmann::json run_tradeoff(const TradeoffOptions& options);

// Whether a run row or a setting of tradeoff.json completed (its "status").
inline bool completed(const nlohmann::json& row) {
  return row.value("status", "") == "complete";
}

// The analysis over run rows (each {name, kind, knob, factor, seed, status, cost, qoi}): the
// reference, the noise floor, every setting's relative errors and which tolerances it meets, and
// per knob how far each QoI moves. Pure: tested on hand-built rows.
nlohmann::json analyse(const nlohmann::json& rows, Reference reference = Reference::kRefined);

// sha256 of the base scene the tradeoff runs for a scene file of this text and file name (its
// [requirements] left out). Recorded in tradeoff.json beside the scene's content
// (dem/scene/scene_content.hpp), by which `iwb plan` checks that a tradeoff belongs to a scene;
// plan falls back on the hash for a tradeoff.json that predates the content.
std::string dem_scene_sha256(const std::string& scene_text, const std::string& scene_file_name);

std::filesystem::path default_out(const std::filesystem::path& scene_file);

}  // namespace iwb::tradeoff
