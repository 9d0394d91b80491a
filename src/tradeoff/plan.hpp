#pragma once
// `iwb plan` (issue 7, item 5): from a scene's [requirements] and its tradeoff (tradeoff.hpp),
// the cheapest DEM setting whose errors plus the seed noise floor meet every stated tolerance,
// and the simplest continuum model (hp1d, ah, hvwe; hvwe-igs as well for cyclic paths) whose
// errors against the tradeoff's reference run, replayed along its own path (comparison/), meet
// them. Writes plan.json; plan_text() is the decision and why, as printed.
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "dem/requirements.hpp"
#include "io/parameter_sets.hpp"

namespace iwb::tradeoff {

// The continuum models in the order plan tries them: simplest first.
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
// every stated tolerance; each model with its failures, as choose_dem.
nlohmann::json choose_model(const std::vector<ModelErrors>& models,
                            const dem::Requirements& requirements,
                            const nlohmann::json& noise_floor);

struct PlanOptions {
  std::filesystem::path scene_file;
  std::filesystem::path tradeoff_dir;  // empty: runs/tradeoff-<scene stem>
  io::ParameterSet params;             // for the continuum models (a file, or built into iwb)
  std::string params_why;              // how it was chosen, for the record
  std::filesystem::path out;           // plan.json goes here; empty: the tradeoff directory
  std::string command_line;
};

// The replay of `model` on the reference run and its errors in each QoI.
ModelErrors evaluate_model(const std::filesystem::path& reference_run, const std::string& model,
                           const io::ParameterSet& params);

// InputError when the scene states no requirements, or the tradeoff is missing, unfinished, of
// another scene (compared by content, dem/scene_content.hpp: the keys that differ are named) or
// without its run directories (a committed tradeoff holds tables only).
nlohmann::json run_plan(const PlanOptions& options);

// The reference run's directory, after checking the tradeoff (for the CLI's default parameters).
std::filesystem::path reference_run(const PlanOptions& options);

std::string plan_text(const nlohmann::json& plan);

}  // namespace iwb::tradeoff
