#include "tradeoff/plan.hpp"

#include <fmt/core.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "assessment/distribution_file.hpp"
#include "common/errors.hpp"
#include "comparison/compare/compare.hpp"
#include "comparison/replay/fit.hpp"
#include "comparison/replay/metrics.hpp"
#include "comparison/replay/seed_scatter.hpp"
#include "dem/scene/scene.hpp"
#include "dem/scene/scene_content.hpp"
#include "io/json_file.hpp"
#include "io/output_directory.hpp"
#include "io/parameter_file.hpp"
#include "io/run_directory.hpp"
#include "tradeoff/tradeoff.hpp"

namespace iwb::tradeoff {

namespace fs = std::filesystem;
using nlohmann::json;

// intergranular strain matters only where the path reverses
std::vector<std::string> model_ladder(bool cyclic) {
  return models::ranked_interface_models(cyclic);
}

namespace {

bool measured_by_tradeoff(const std::string& key) {
  for (const auto& q : dem::quantities_of_interest())
    if (key == q.key) return true;
  return false;
}

// The stated tolerances a candidate fails: error + noise above the tolerance, or not measured.
// Tolerances of quantities only `iwb compare` judges (dem::compared_only_quantities) are not
// the tradeoff's to meet.
json failures(const std::map<std::string, std::optional<double>>& error,
              const dem::Requirements& req, const json& noise_floor) {
  json out = json::array();
  for (const auto& [q, tol] : req) {
    if (!tol || !measured_by_tradeoff(q)) continue;  // "not needed", or not the tradeoff's
    const auto it = error.find(q);
    const json n = noise_floor.contains(q) ? noise_floor[q].value("relative", json()) : json();
    if (it == error.end() || !it->second || !n.is_number()) {
      out.push_back({{"qoi", q},
                     {"tolerance", *tol},
                     {"error", nullptr},
                     {"why", !n.is_number() ? "no noise floor" : "not measured"}});
      continue;
    }
    const double total = *it->second + n.get<double>();
    if (total > *tol)
      out.push_back({{"qoi", q},
                     {"tolerance", *tol},
                     {"error", *it->second},
                     {"noise", n.get<double>()},
                     {"by", total - *tol}});
  }
  return out;
}

std::map<std::string, std::optional<double>> errors_of(const json& setting) {
  std::map<std::string, std::optional<double>> e;
  const json errors = setting.value("error", json::object());  // named: items() must not outlive it
  for (const auto& [q, v] : errors.items())
    e[q] = v.is_number() ? std::optional<double>(v.get<double>()) : std::nullopt;
  return e;
}

}  // namespace

json choose_dem(const json& tradeoff, const dem::Requirements& req) {
  std::vector<const json*> candidates;
  for (const auto& s : tradeoff.at("settings"))
    if (s.value("status", "") == "complete" && s.contains("error")) candidates.push_back(&s);
  std::stable_sort(candidates.begin(), candidates.end(), [](const json* a, const json* b) {
    return (*a)["particle_steps"].get<double>() < (*b)["particle_steps"].get<double>();
  });
  json out = {{"chosen", nullptr}, {"candidates", json::array()}};
  for (const json* s : candidates) {
    json c = {{"name", (*s)["name"]},
              {"settings", s->value("settings", "")},
              {"particle_steps", (*s)["particle_steps"]},
              {"wall_seconds", (*s)["wall_seconds"]},
              {"error", s->value("error", json::object())},
              {"fails", failures(errors_of(*s), req, tradeoff.at("noise_floor"))}};
    if (out["chosen"].is_null() && c["fails"].empty()) out["chosen"] = c;
    out["candidates"].push_back(c);
  }
  return out;
}

namespace {

// The candidate whose worst failure is the smallest; an unmeasured failure ranks last.
json closest(const json& candidates) {
  json best;
  double best_by = INFINITY;
  for (const auto& c : candidates) {
    double worst = 0.0;
    std::string qoi;
    for (const auto& f : c["fails"]) {
      const double by = f.contains("by") ? f["by"].get<double>() : INFINITY;
      if (by >= worst) worst = by, qoi = f["qoi"].get<std::string>();
    }
    if (worst < best_by) {
      best_by = worst;
      best = {{"name", c["name"]}, {"qoi", qoi}, {"by", worst}};
    }
  }
  return best;
}

}  // namespace

json choose_model(const std::vector<ModelErrors>& models, const dem::Requirements& req,
                  const json& noise_floor) {
  json out = {{"chosen", nullptr}, {"candidates", json::array()}};
  for (const auto& m : models) {
    json c = {{"name", m.model},
              {"note", m.note},
              {"error", json::object()},
              {"fails", failures(m.error, req, noise_floor)}};
    for (const auto& [q, e] : m.error) c["error"][q] = e ? json(*e) : json(nullptr);
    if (out["chosen"].is_null() && c["fails"].empty()) out["chosen"] = c;
    out["candidates"].push_back(c);
  }
  if (out["chosen"].is_null()) out["closest"] = closest(out["candidates"]);
  return out;
}

std::vector<Candidate> plan_candidates(const std::vector<std::string>& ladder,
                                       const std::vector<std::string>& set_names) {
  std::vector<Candidate> out;
  for (const auto& m : ladder) {
    out.push_back({m, m, 0});
    if (models::find_model(m).declaration.calibration_recipe.empty()) continue;
    for (std::size_t k = 1; k < set_names.size(); ++k)
      out.push_back({m + " with " + set_names[k], m, k});
  }
  return out;
}

namespace {

// The parameter samples' CV that goes with a quantity of interest (league_quantities(): peak and
// residual tau, the normal quantity's end and rate); 0 for one the samples do not measure.
double parameter_cv(const assessment::LeagueEntry& e, const std::string& qoi) {
  static const std::map<std::string, std::string> sampled = {
      {"peak_friction", "peak_tau_kPa"},
      {"residual_friction", "residual_tau_kPa"},
      {"total_dilation", "normal_end"},
      {"sigma_n_change", "normal_end"},
      {"dilation_rate", "normal_rate"}};
  const auto s = sampled.find(qoi);
  if (s == sampled.end()) return 0.0;
  for (const auto& q : e.parameter_uncertainty.quantities)
    if (q.name == s->second) return std::isfinite(q.cv) ? q.cv : NAN;
  return 0.0;
}

}  // namespace

ModelErrors evaluate_model(const assessment::SceneReference& reference, const std::string& model,
                           const models::ModelInputs& inputs,
                           const assessment::LeagueOptions& options) {
  ModelErrors r{model, {}, ""};
  try {
    const auto e = assessment::assess_model(reference, model, inputs, options);
    std::string parts;
    for (const auto& v : e.verdicts) {
      if (!v.error) continue;
      // the global uncertainty of this quantity: the calibrated model's miss and the spread its
      // parameters' uncertainty gives it, in quadrature (seed eq. 4.4 with ERRATA 16)
      const double cv = parameter_cv(e, v.key);
      r.error[v.key] = std::sqrt(*v.error * *v.error + cv * cv);
      parts += fmt::format("{}{} {:.1f} % (model {:.1f} %, parameters {:.1f} %)",
                           parts.empty() ? "" : ", ", v.key, 100 * *r.error[v.key],
                           100 * std::abs(*v.error), 100 * cv);
    }
    std::string fitted;
    for (const auto& v : e.fit.values)
      fitted += fmt::format("{}{} = {:.4g}", fitted.empty() ? "" : ", ", v.name, v.value);
    r.note =
        fmt::format("calibrated to the base seeds ({}); global uncertainty per quantity: {}; {}",
                    fitted, parts, e.status);
  } catch (const std::exception& ex) {
    r.note = fmt::format("could not be evaluated: {}", ex.what());
  }
  return r;
}

namespace {

fs::path tradeoff_dir(const PlanOptions& opt) {
  return opt.tradeoff_dir.empty() ? default_out(opt.scene_file) : opt.tradeoff_dir;
}

// The scene against the one the tradeoff ran, by content: its file's name, comments and layout
// do not count, a value that decides the DEM runs does and is named.
void require_same_scene(const json& t, const fs::path& file, const PlanOptions& opt) {
  const std::string text = io::read_file(opt.scene_file), scene = opt.scene_file.string();
  const std::string ran = t.value("scene", "?");
  const auto refuse = [&](const std::string& what) {
    return InputError(
        fmt::format("{}: not the scene the tradeoff {} was run on ({}): {}; run `iwb tradeoff {}` "
                    "for this scene",
                    scene, file.string(), ran, what, scene));
  };
  if (t.contains("dem_scene")) {
    const auto diff = dem::content_differences(dem::scene_content(text, scene), t["dem_scene"]);
    if (!diff.empty()) throw refuse(dem::differences_text(diff));
    return;
  }
  // A tradeoff.json from before the content was recorded: its hash, under the name it ran as.
  if (t.value("dem_scene_sha256", "") != dem_scene_sha256(text, fs::path(ran).filename().string()))
    throw refuse(
        "its DEM settings differ (this tradeoff.json records only their sha256, not which key)");
}

std::vector<std::string> complete_base_seeds(const json& t) {
  std::vector<std::string> names;
  for (const auto& r : t["runs"])
    if (r["kind"] == "base" && r["status"] == "complete")
      names.push_back(r["name"].get<std::string>());
  return names;
}

// The runs the reference stands on: the refined run, or, for a tradeoff measured against its own
// base (`iwb tradeoff --reference base`), the complete base seeds whose mean it is (no run is
// called "base").
std::vector<std::string> reference_run_names(const json& t) {
  if (t.value("reference_mode", "refined") == "base") return complete_base_seeds(t);
  return {t["reference"]["name"].get<std::string>()};
}

// Plan reads the reference's run directory (its summary chooses the default parameters) and
// replays the complete base seeds: each must be there, not only the tables (their compact files
// suffice: data/copy_campaign.sh copies them, and the shipped tradeoffs keep them).
void require_run_directories(const json& t, const fs::path& file, const PlanOptions& opt) {
  std::vector<std::string> names = reference_run_names(t);
  for (const auto& n : complete_base_seeds(t))
    if (std::find(names.begin(), names.end(), n) == names.end()) names.push_back(n);
  std::string missing;
  for (const auto& n : names)
    if (!fs::is_regular_file(file.parent_path() / "runs" / n / "manifest.json"))
      missing += (missing.empty() ? "" : ", ") + (fs::path("runs") / n).string();
  if (!missing.empty())
    throw InputError(fmt::format(
        "{}: the tradeoff's run directories {} are missing (plan replays its base runs: "
        "their manifest, summary and time series are enough, as data/tradeoff/*/runs/ "
        "keep them); run `iwb tradeoff {} -o {}` to make them (complete runs there are "
        "reused)",
        file.string(), missing, opt.scene_file.string(), file.parent_path().string()));
}

json load_tradeoff(const PlanOptions& opt) {
  const fs::path dir = tradeoff_dir(opt);
  const fs::path file = dir / "tradeoff.json";
  if (!fs::is_regular_file(file))
    throw InputError(fmt::format("{}: no tradeoff data for {}; run `iwb tradeoff {} -o {}` first",
                                 file.string(), opt.scene_file.string(), opt.scene_file.string(),
                                 dir.string()));
  const json t = io::read_json_file(file);  // a truncated file is named, not a raw parse error
  require_same_scene(t, file, opt);
  if (t["reference"].is_null())
    throw InputError(
        fmt::format("{}: the reference run has not completed (status {}); run `iwb tradeoff` again "
                    "to continue it",
                    file.string(), t.value("status", "?")));
  require_run_directories(t, file, opt);
  return t;
}

}  // namespace

// The scene's own runs (base seeds): the grains a parameter set calibrated for the scene
// describes. The refined reference has other grains (kappa x2 is a stiffer E), so a continuum
// model is judged against these, with their seed mean.
std::vector<fs::path> base_runs(const PlanOptions& opt, const json& t) {
  const fs::path dir = tradeoff_dir(opt);
  std::vector<fs::path> out;
  for (const auto& r : t["runs"])
    if (r["kind"] == "base" && r["status"] == "complete")
      out.push_back(dir / "runs" / r["name"].get<std::string>());
  return out;
}

namespace {

// A candidate's parameter set: its own (--params-for), else the scene's (opt.params) for a model
// calibrated from soil tests, else the model's own example, where its calibration to the runs
// starts.
models::ModelInputs candidate_inputs(const io::ParameterSet& set, const std::string& model,
                                     const std::map<std::string, io::ParameterSet>& own_sets) {
  const auto& spec = models::find_model(model);
  const auto it = own_sets.find(model);
  const io::ParameterSet* given = it == own_sets.end() ? nullptr : &it->second;
  if (!given && spec.declaration.calibration_recipe.empty())
    return io::shipped_inputs(spec.declaration.example_parameters);
  models::ModelInputs in;
  in.tables = given ? given->tables : set.tables;
  in.source = given ? given->origin : set.origin;
  return in;
}

// One candidate judged, or, where its set lacks a table of the model's (the candidates of issue
// 56 carry parameters no soil test gives), listed with what to give it.
ModelErrors evaluate_candidate(const assessment::SceneReference& reference,
                               const std::string& model, const models::ModelInputs& inputs,
                               const assessment::LeagueOptions& league) {
  for (const auto* table : models::find_model(model).tables)
    if (!inputs.tables.count(table->name))
      return {model,
              {},
              fmt::format("could not be evaluated: {} has no [{}] table; give the model its own "
                          "set with --params-for {}=FILE",
                          inputs.source, table->name, model)};
  return evaluate_model(reference, model, inputs, league);
}

// The sets --params-for gives, by model, read once before anything runs: each model one the
// plan tries, each file a set.
std::map<std::string, io::ParameterSet> models_with_own_sets(
    const PlanOptions& opt, const std::vector<std::string>& ladder) {
  std::map<std::string, io::ParameterSet> sets;
  for (const auto& m : io::models_given_sets(opt.params_for)) {
    if (std::find(ladder.begin(), ladder.end(), m) == ladder.end())
      throw InputError(
          fmt::format("--params-for {}=...: the plan does not try {} on this scene (it tries {})",
                      m, m, fmt::join(ladder, ", ")));
    sets.emplace(m, *io::parameter_set_given_for(opt.params_for, m));
  }
  return sets;
}

}  // namespace

// A base reference's first seed stands for it (load_tradeoff has checked that one completed).
fs::path reference_run(const PlanOptions& opt) {
  const json t = load_tradeoff(opt);
  return tradeoff_dir(opt) / "runs" / reference_run_names(t).front();
}

dem::Scene load_scene_to_plan(const fs::path& scene_file) {
  dem::Scene scene = dem::load_scene(scene_file.string());
  if (scene.requirements.empty())
    throw InputError(fmt::format(
        "{}: the scene states no [requirements] (data/scenes/README.md); nothing to plan",
        scene_file.string()));
  return scene;
}

namespace {
// The further calibrations' files, for the record.
json other_origins(const PlanOptions& opt) {
  json out = json::array();
  for (const auto& p : opt.other_calibrations) out.push_back(p.origin);
  return out;
}
}  // namespace

json run_plan(const PlanOptions& opt) {
  const dem::Scene scene = load_scene_to_plan(opt.scene_file);
  const auto ladder = model_ladder(scene.shear.cyclic());
  const auto own_sets = models_with_own_sets(opt, ladder);
  const json t = load_tradeoff(opt);
  const fs::path ref = reference_run(opt);
  const fs::path out = opt.out.empty() ? ref.parent_path().parent_path() : opt.out;
  // a directory that cannot take plan.json is refused before the models are replayed (seconds)
  io::require_output_directory(out, kPlanOutput, false);
  const auto judged_on = base_runs(opt, t);
  if (judged_on.empty())
    throw InputError(
        fmt::format("{}: no complete base seed in the tradeoff; run `iwb tradeoff` "
                    "again to continue it",
                    ref.parent_path().parent_path().string()));
  std::vector<comparison::DemRun> runs;
  for (const auto& r : judged_on) runs.push_back(comparison::load_dem_run(r));
  const auto reference = assessment::scene_reference(runs);  // the base seeds' mean and scatter
  assessment::LeagueOptions league;
  league.spread = opt.spread;
  league.distributions = assessment::embedded_distributions();
  league.uncertainty_samples = opt.samples;
  std::vector<io::ParameterSet> sets = {opt.params};
  sets.insert(sets.end(), opt.other_calibrations.begin(), opt.other_calibrations.end());
  std::vector<std::string> set_names;
  for (const auto& p : sets) set_names.push_back(fs::path(p.origin).stem().string());
  std::vector<ModelErrors> models;
  for (const auto& c : plan_candidates(ladder, set_names)) {
    if (own_sets.count(c.model) && c.set > 0) continue;  // tried with its own set alone
    models.push_back(evaluate_candidate(reference, c.model,
                                        candidate_inputs(sets[c.set], c.model, own_sets), league));
    models.back().model = c.name;
  }
  json judged = json::array();
  for (const auto& r : judged_on) judged.push_back(r.filename().string());
  json req = json::object();
  for (const auto& [q, tol] : scene.requirements) req[q] = tol ? json(*tol) : json("not needed");
  json plan = {{"kind", "plan"},
               {"scene", opt.scene_file.string()},
               {"requirements", req},
               {"tradeoff", (ref.parent_path().parent_path() / "tradeoff.json").string()},
               {"reference", t["reference"]},
               {"noise_floor", t["noise_floor"]},
               {"dem", choose_dem(t, scene.requirements)},
               {"continuum", choose_model(models, scene.requirements, t["noise_floor"])},
               {"continuum_judged_on", judged},
               {"params", opt.params.origin},
               {"other_calibrations", other_origins(opt)},
               {"params_for", opt.params_for},
               {"parameter_uncertainty",
                opt.spread == assessment::ParameterSpread::kFitSigmas ? "fit" : "seed"},
               {"parameter_samples", opt.samples},
               {"params_why", opt.params_why},
               {"command_line", opt.command_line}};
  io::claim_output_directory(out, kPlanOutput, false);
  io::write_atomically(out / "plan.json", plan.dump(2) + "\n");
  return plan;
}

namespace {

std::string fails_text(const json& fails) {
  std::string s;
  for (const auto& f : fails) {
    s += s.empty() ? "" : "; ";
    if (f["error"].is_null())
      s += fmt::format("{}: {}", f["qoi"].get<std::string>(), f["why"].get<std::string>());
    else
      s += fmt::format("{} {:.1f} % + noise {:.1f} % > {:.0f} % by {:.1f} points",
                       f["qoi"].get<std::string>(), 100 * f["error"].get<double>(),
                       100 * f["noise"].get<double>(), 100 * f["tolerance"].get<double>(),
                       100 * f["by"].get<double>());
  }
  return s;
}

// "residual_friction 0.9 %" for the stated QoIs, so that a pass shows its margin too.
std::string stated_errors(const json& c, const json& requirements) {
  std::string s;
  for (const auto& [q, tol] : requirements.items()) {
    if (!tol.is_number()) continue;
    const json e = c.value("error", json::object()).value(q, json());
    s += fmt::format("{}{} {}", s.empty() ? "" : ", ", q,
                     e.is_number() ? fmt::format("{:.1f} %", 100 * e.get<double>()) : "n/a");
  }
  return s;
}

std::string verdict(const json& c, const json& requirements) {
  return c["fails"].empty() ? "meets every tolerance (" + stated_errors(c, requirements) + ")"
                            : "fails: " + fails_text(c["fails"]);
}

}  // namespace

std::string plan_text(const json& p) {
  std::string s = fmt::format("plan for {}: requirements {}\n", p["scene"].get<std::string>(),
                              p["requirements"].dump());
  s += fmt::format("reference: {} ({})\n\nDEM settings, cheapest first:\n",
                   p["reference"]["name"].get<std::string>(),
                   p["reference"]["settings"].get<std::string>());
  for (const auto& c : p["dem"]["candidates"])
    s += fmt::format("  {:<12} {:>10.3g} particle-steps {:>6.0f} s  {}\n",
                     c["name"].get<std::string>(), c["particle_steps"].get<double>(),
                     c["wall_seconds"].get<double>(), verdict(c, p["requirements"]));
  const auto& d = p["dem"]["chosen"];
  s += d.is_null()
           ? "DEM: no setting of the tradeoff meets every tolerance\n"
           : fmt::format("DEM: {} ({}), {:.3g} particle-steps, {:.0f} s\n",
                         d["name"].get<std::string>(), d["settings"].get<std::string>(),
                         d["particle_steps"].get<double>(), d["wall_seconds"].get<double>());
  std::string judged;
  for (const auto& r : p["continuum_judged_on"])
    judged += (judged.empty() ? "" : ", ") + r.get<std::string>();
  s += fmt::format(
      "\ncontinuum models, simplest first (mean error over the scene's own runs {}, "
      "parameters {}):\n",
      judged, p["params"].get<std::string>());
  for (const auto& c : p["continuum"]["candidates"])
    s += fmt::format("  {:<9} {}\n            ({})\n", c["name"].get<std::string>(),
                     verdict(c, p["requirements"]), c["note"].get<std::string>());
  const auto& m = p["continuum"]["chosen"];
  s += "  (band thickness: a continuum model takes d_s as input, it does not predict it)\n";
  const auto& near = p["continuum"].value("closest", json());
  s += !m.is_null() ? fmt::format("continuum: {}\n", m["name"].get<std::string>())
       : near.is_object() && near["by"].is_number()
           ? fmt::format(
                 "continuum: no model with these calibrations meets every tolerance; the closest, "
                 "{}, misses {} by {:.1f} points\n",
                 near["name"].get<std::string>(), near["qoi"].get<std::string>(),
                 100 * near["by"].get<double>())
           : "continuum: no model with these calibrations meets every tolerance\n";
  return s;
}

}  // namespace iwb::tradeoff
