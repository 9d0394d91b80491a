// `iwb assess --reference RUN...`: the league of the interface models on a DEM scene (issue 17,
// seed 4.3): parameters per model, the runs, resumable records, the tables and figures.
#include <fmt/core.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <filesystem>
#include <map>

#include "assessment/assess.hpp"
#include "assessment/distribution_file.hpp"
#include "assessment/league_output.hpp"
#include "common/errors.hpp"
#include "comparison/replay/dem_run.hpp"
#include "comparison/verdicts/form_limit_causes.hpp"
#include "dem/scene/scene.hpp"
#include "io/json_file.hpp"
#include "io/parameter_sets.hpp"
#include "io/run_directory.hpp"
#include "validation/parameter_choice.hpp"

namespace iwb::assessment {

namespace {

models::ModelInputs as_inputs(const io::ParameterSet& set) {
  models::ModelInputs in;
  in.tables = set.tables;
  in.source = set.origin;
  return in;
}

// The league's parameter set of `model`: --params-for MODEL=FILE, else the positional set when
// one model is named, else for a model calibrated from soil tests the set of the scene's grains as
// `iwb validate` chooses it, else the model's own example (the seed's table), where its fit starts.
models::ModelInputs league_parameters(const AssessOptions& o, const std::string& model,
                                      const comparison::DemRun& dem) {
  if (const auto given = io::parameter_set_given_for(o.params_for, model)) return as_inputs(*given);
  if (!o.params.empty()) return as_inputs(io::read_parameter_set(o.params));
  const auto& spec = models::find_model(model);
  if (spec.declaration.calibration_recipe.empty())
    return io::shipped_inputs(spec.declaration.example_parameters);
  std::string why;
  const auto scene =
      dem::parse_scene(dem.scene_text, (dem.dir / "manifest.json").string() + " /scene/text");
  return as_inputs(validation::parameters_for(
      io::parameter_sets({}), scene, dem.summary.at("residual_friction").get<double>(), why));
}

// The tables a set lacks for `spec` (the sand set has no [intergranular_strain] for the -igs
// models) from the model's own example set, and the source says so.
models::ModelInputs with_missing_tables(const models::ModelSpec& spec, models::ModelInputs in) {
  for (const auto* t : spec.tables)
    if (!in.tables.count(t->name)) {
      in.tables[t->name] =
          io::shipped_inputs(spec.declaration.example_parameters).tables.at(t->name);
      in.source += fmt::format(" + [{}] of {}", t->name, spec.declaration.example_parameters);
    }
  return in;
}

std::vector<std::string> league_models(const AssessOptions& o) {
  std::vector<std::string> names = {o.model};
  if (o.model.empty()) {
    for (const auto& m : o.models)
      models::find_model(m);  // an unknown name is refused before anything runs
    names = o.models.empty() ? models::ranked_interface_models(true) : o.models;
  }
  // a set given for a model the league does not judge is a mistake, not an extra
  for (const auto& m : io::models_given_sets(o.params_for))
    if (std::find(names.begin(), names.end(), m) == names.end())
      throw InputError(fmt::format("--params-for {}=...: {} is not among the league's models ({})",
                                   m, m, fmt::join(names, ", ")));
  return names;
}

// What a model's record was made from: a record of other inputs is not reused.
nlohmann::json record_inputs(const AssessOptions& o, const models::ModelInputs& in,
                             const std::map<std::string, std::string>& distributions) {
  return {{"reference", o.reference},
          {"parameters", in.tables},
          {"samples", o.samples},
          {"sobol_samples", o.sobol_samples},
          {"seed", o.seed},
          {"distributions", distributions},
          {"parameter_uncertainty", o.parameter_uncertainty}};
}

// Each model's parameter set, checked by the model before anything runs.
std::vector<models::ModelInputs> league_inputs(const AssessOptions& o,
                                               const std::vector<std::string>& names,
                                               const comparison::DemRun& first) {
  std::vector<models::ModelInputs> inputs;
  for (const auto& m : names) {
    inputs.push_back(with_missing_tables(models::find_model(m), league_parameters(o, m, first)));
    inputs.back().source = inputs.back().source.empty() ? "?" : inputs.back().source;
    models::find_model(m).make(
        inputs.back());  // a set the model refuses is bad input, before anything runs
  }
  return inputs;
}

nlohmann::json league_header(const AssessOptions& o, const SceneReference& ref,
                             const comparison::DemRun& first,
                             const std::vector<std::string>& names) {
  return {{"scene", first.dir.parent_path().string()},
          {"runs", o.reference},
          {"boundary", driver::to_string(ref.mean.boundary)},
          {"wall", fmt::format("R_n {:g}, d50 {:g} mm", ref.mean.R_n, ref.mean.d50_mm)},
          {"normal", ref.mean.boundary == driver::BoundaryKind::kCV ? "sigma_n" : "dilation"},
          {"uncertainty_samples", o.samples},
          {"sobol_samples", o.sobol_samples},
          {"models", names},
          {"parameter_uncertainty", o.parameter_uncertainty},
          {"form_limits", o.form_limits}};
}

LeagueOptions league_options(const AssessOptions& o,
                             const std::map<std::string, std::string>& distributions) {
  LeagueOptions lo;
  lo.spread =
      o.parameter_uncertainty == "fit" ? ParameterSpread::kFitSigmas : ParameterSpread::kSeedCovs;
  lo.distributions = distributions, lo.uncertainty_samples = o.samples,
  lo.sobol_samples = o.sobol_samples;
  lo.seed = o.seed, lo.threads = o.threads, lo.progress = o.run_counter();
  return lo;
}

// One model's entry: its record in DIR/models/ when made from these inputs, else assessed and
// recorded. `counted` is "k/n", for the note.
nlohmann::json model_entry(const AssessOptions& o, const SceneReference& ref,
                           const std::string& name, const models::ModelInputs& inputs,
                           const std::map<std::string, std::string>& distributions,
                           const std::filesystem::path& dir, const std::string& counted) {
  const auto record = dir / "models" / (name + ".json");
  const auto in = record_inputs(o, inputs, distributions);
  if (std::filesystem::exists(record)) {
    auto old = io::read_json_file(record);
    if (old.value("inputs", nlohmann::json()) == in) {
      o.note(fmt::format("model {}: {} (reused {})", counted, name, record.string()));
      return old;
    }
  }
  o.note(fmt::format("model {}: {} (calibration, {} parameter samples{})", counted, name, o.samples,
                     o.sobol_samples > 0 ? fmt::format(", Sobol N = {}", o.sobol_samples) : ""));
  auto e = entry_json(assess_model(ref, name, inputs, league_options(o, distributions)));
  e["inputs"] = in;
  std::filesystem::create_directories(record.parent_path());
  io::write_atomically(record, e.dump(1));
  return e;
}

// Per model, its cell of the form-limit records under --form-limits (none without it): read before
// anything is written, so that an edited record is refused before the runs (issue 60).
std::vector<nlohmann::json> form_limit_cells(const AssessOptions& o,
                                             const std::vector<std::string>& names,
                                             const nlohmann::json& header) {
  std::vector<nlohmann::json> cells;
  if (o.form_limits.empty()) return cells;
  for (const auto& m : names)
    cells.push_back(comparison::form_limit_cell(o.form_limits, m, header["wall"].get<std::string>(),
                                                header["boundary"].get<std::string>()));
  return cells;
}

}  // namespace

AssessOutcome run_league(const AssessOptions& o) {
  std::vector<comparison::DemRun> runs;
  for (const auto& r : o.reference) runs.push_back(comparison::load_dem_run(r));
  const auto ref = scene_reference(runs);  // refuses runs of different scenes
  const auto names = league_models(o);
  const auto texts =
      distribution_texts(o.distributions);  // each file's text: a changed COV is a changed input
  const auto inputs = league_inputs(o, names, runs.front());
  const auto dir = o.out.empty() ? std::filesystem::path("runs") / "assess-league"
                                 : std::filesystem::path(o.out);
  const auto header = league_header(o, ref, runs.front(), names);
  const auto cells = form_limit_cells(o, names, header);
  // an earlier league continues here: its model records say what they were made from, and only
  // those made from these inputs are reused
  const bool resume = std::filesystem::exists(dir / "manifest.json") &&
                      io::read_json_file(dir / "manifest.json").contains("league");
  const io::OutputKind kind{"assess-league", "league.md"};
  if (resume)
    io::claim_output_directory(dir, kind, false);
  else
    io::prepare_run_directory(dir, kind, o.force);
  io::write_manifest(
      dir, {{"kind", kind.kind}, {"command", "assess"}, {"league", header}, {"status", "running"}});
  std::vector<nlohmann::json> entries;
  for (std::size_t i = 0; i < names.size(); ++i)
    entries.push_back(model_entry(o, ref, names[i], inputs[i], texts, dir,
                                  fmt::format("{}/{}", i + 1, names.size())));
  for (std::size_t i = 0; i < cells.size(); ++i)  // not stored in the model records: reusable
    entries[i]["form_limit"] = cells[i];
  const auto table = ranked(entries);
  draw_league_figures(table, dir / "figures");
  io::write_atomically(dir / "league.csv", league_csv(table));
  const auto md = league_markdown(header, table);
  io::write_atomically(dir / "league.md", md);
  io::write_manifest(
      dir,
      {{"kind", kind.kind}, {"command", "assess"}, {"league", header}, {"status", "complete"}});
  return {md.substr(0, md.find("\n![")), dir / "league.md"};  // the table without its figures
}

}  // namespace iwb::assessment
