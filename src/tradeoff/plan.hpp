#pragma once
// `iwb plan` (issue 7, item 5; issue 17, item 4): from a scene's [requirements] and its tradeoff
// (tradeoff.hpp), the cheapest DEM setting whose errors plus the seed noise floor meet every
// stated tolerance, and the simplest interface model (the declared candidates, simplest first:
// mc, hyperbolic, hp1d, ah, ahe, lashkari, mortara, hvwe; the -igs ones as well for cyclic paths)
// whose global uncertainty per quantity meets them: calibrated to the scene's base seeds and
// replayed along their path (assessment/league.hpp), its miss of the seed mean and the spread its
// parameters' uncertainty gives, in quadrature. Writes plan.json; plan_text() is the decision and
// why, as printed.
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "assessment/league.hpp"
#include "dem/scene/requirements.hpp"
#include "dem/scene/scene.hpp"
#include "io/parameter_sets.hpp"

namespace iwb::tradeoff {

// The interface models in the order plan tries them: simplest first (ModelDeclaration::plan_rank);
// those with intergranular strain only for cyclic paths.
std::vector<std::string> model_ladder(bool cyclic);

// Pure decision over tradeoff.json: every complete setting from the cheapest up, each with the
// tolerances it fails (QoI, error, noise, tolerance, by how much); "chosen" is the first that
// fails none, or null.
nlohmann::json choose_dem(const nlohmann::json& tradeoff, const dem::Requirements& requirements);

// A model's relative errors in each QoI against the DEM reference (nullopt: not predicted or
// not reached), and why when it could not be evaluated.
struct ModelErrors {
  std::string model;
  std::map<std::string, std::optional<double>> error;
  std::string note;
};

// Pure decision: the first model (in the order given) whose error + the DEM's noise floor meets
// every stated tolerance; each model with its failures, as choose_dem. When none does, "closest"
// names the candidate whose worst failure is the smallest, and by how much (a failure that cannot
// be measured counts as no closer than any measured one).
nlohmann::json choose_model(const std::vector<ModelErrors>& models,
                            const dem::Requirements& requirements,
                            const nlohmann::json& noise_floor);

// What plan tries, in order: each model of the ladder with the first parameter set, and a model
// calibrated from soil tests (a calibration recipe) with each further set too (another
// calibration of the same grains: a point of a Pareto front that weights the dilatancy, say);
// named "model" for the first set and "model with <set's file stem>" for the others.
struct Candidate {
  std::string name, model;
  std::size_t set = 0;  // index into the parameter sets
};
std::vector<Candidate> plan_candidates(const std::vector<std::string>& ladder,
                                       const std::vector<std::string>& set_names);

struct PlanOptions {
  std::filesystem::path scene_file;
  std::filesystem::path tradeoff_dir;  // empty: runs/tradeoff-<scene stem>
  io::ParameterSet params;             // for the continuum models (a file, or built into iwb)
  std::string params_why;              // how it was chosen, for the record
  std::filesystem::path out;           // plan.json goes here; empty: the tradeoff directory
  std::string command_line;
  assessment::ParameterSpread spread = assessment::ParameterSpread::kFitSigmas;
  int samples = 200;  // parameter samples per candidate
  // further calibrations of the models calibrated from soil tests, tried after `params`
  std::vector<io::ParameterSet> other_calibrations = {};
  // MODEL=FILE: a model's own set, tried instead of the sets above (issue 56's candidates, whose
  // parameters are fitted to DEM walls); each MODEL one the plan tries
  std::vector<std::string> params_for = {};
};

// `model` calibrated to the reference (the base seeds' mean) and judged: its global uncertainty
// in each quantity it replays; a model that cannot be evaluated says why in its note.
ModelErrors evaluate_model(const assessment::SceneReference& reference, const std::string& model,
                           const models::ModelInputs& inputs,
                           const assessment::LeagueOptions& options);

// The scene file's scene; InputError when it is not valid or states no [requirements] (nothing to
// plan), checked before any tradeoff is read.
dem::Scene load_scene_to_plan(const std::filesystem::path& scene_file);

// InputError when the scene states no requirements, or the tradeoff is missing, unfinished, of
// another scene (compared by content, dem/scene/scene_content.hpp: the keys that differ are named)
// or without its run directories (a committed tradeoff holds tables only).
nlohmann::json run_plan(const PlanOptions& options);

// The reference run's directory, after checking the tradeoff (for the CLI's default parameters).
std::filesystem::path reference_run(const PlanOptions& options);

std::string plan_text(const nlohmann::json& plan);

}  // namespace iwb::tradeoff
