#include "comparison/compare/compare.hpp"

#include <fmt/core.h>

#include "common/errors.hpp"
#include "comparison/replay/metrics.hpp"
#include "comparison/verdicts/cyclic_verdicts.hpp"
#include "comparison/verdicts/feasibility.hpp"
#include "comparison/verdicts/form_limit_causes.hpp"
#include "comparison/verdicts/verdicts.hpp"
#include "io/parameter_file.hpp"
#include "io/run_directory.hpp"

namespace iwb::comparison {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// kappa_r from the wall's R_n by eq. 5.35; a flat wall (R_n = 0) gets the floor.
// kappa_r of the variants that need no fit: the model's declared prediction from the wall (sand:
// eq. 5.35 from R_n), else the parameter file's value (1, fully rough, when it gives none).
// kappa_r in [floor, 1] for a model that reads wall roughness; fixed at 1 for one that does not (a
// 3D continuum model, the reference models of seed 3.3, a user's model): d_s is then fitted alone,
// and the model's own parameters stay as given (fitting them is `iwb assess`'s, issue 17).

std::pair<double, std::string> predicted_kappa(const models::ModelSpec& spec, const DemRun& dem,
                                               const models::ModelInputs& parameters) {
  if (!spec.uses_roughness)
    return {1.0, fmt::format("no kappa_r ({} reads no wall roughness)", spec.name)};
  for (const auto& f : spec.declaration.fit)
    if (f.target == models::FitParameter::Target::kRoughness && f.predict)
      return f.predict({dem.R_n, dem.d50_mm});
  const double k = parameters.roughness.kappa_r;
  return {k, fmt::format("kappa_r = {:g} ({} predicts none from the wall)", k, spec.name)};
}

std::string curves_csv(const DemRun& dem, const std::vector<Replay>& replays) {
  std::string s =
      "variant,u_x_mm,tau_dem_kPa,tau_model_kPa,sigma_n_dem_kPa,sigma_n_model_kPa,u_n_dem_mm,u_n_"
      "model_mm\n";
  for (std::size_t v = 0; v < replays.size(); ++v) {
    const auto& r = replays[v];
    for (std::size_t i = 0; i < r.u_x_mm.size(); ++i)
      s += fmt::format("{},{:.8g},{:.8g},{:.8g},{:.8g},{:.8g},{:.8g},{:.8g}\n", v, r.u_x_mm[i],
                       dem.tau_kPa[i], r.tau_kPa[i], dem.sigma_n_kPa[i], r.sigma_n_kPa[i],
                       dem.u_n_mm[i], r.u_n_mm[i]);
  }
  return s;
}

// The DEM's seed band per row (mean and SD over the seeds, on the compared run's rows every seed
// covers), for the report's figures.
std::string seed_band_csv(const DemRun& dem, const SeedScatter& s) {
  std::string out =
      "u_x_mm,tau_mean_kPa,tau_sd_kPa,sigma_n_mean_kPa,sigma_n_sd_kPa,u_n_mean_mm,u_n_sd_mm\n";
  for (std::size_t i = 0; i < s.rows; ++i)
    out += fmt::format("{:.8g},{:.8g},{:.8g},{:.8g},{:.8g},{:.8g},{:.8g}\n", dem.u_x_mm[i],
                       s.tau.mean[i], s.tau.sd[i], s.sigma_n.mean[i], s.sigma_n.sd[i],
                       s.u_n.mean[i], s.u_n.sd[i]);
  return out;
}

Variant fitted_variant(const Variant& start, const FitResult& fit, const std::string& what,
                       double d50) {
  Variant v = start;
  v.inputs.roughness.kappa_r = fit.kappa_r;
  v.d_s_mm = fit.d_s_mm;
  const std::string kappa =
      fit.kappa_fitted ? fmt::format("kappa_r = {:.3f} +- {:.3f}", fit.kappa_r, fit.sigma_kappa_r)
                       : fmt::format("kappa_r fixed at {:g} (no roughness)", fit.kappa_r);
  v.label = fmt::format("fitted to {}: {}, d_s = {:.2f} +- {:.2f} mm ({:.1f} d50)", what, kappa,
                        fit.d_s_mm, fit.sigma_d_s_mm, fit.d_s_mm / d50);
  return v;
}

json fit_json(const FitResult& fit, const DemRun& dem, const Metrics& at_optimum) {
  return {{"kappa_r", fit.kappa_r},
          {"sigma_kappa_r", fit.sigma_kappa_r},
          {"d_s_mm", fit.d_s_mm},
          {"sigma_d_s_mm", fit.sigma_d_s_mm},
          {"d_s_over_d50", fit.d_s_mm / dem.d50_mm},
          {"rmse_tau_kPa", at_optimum.rmse_tau_kPa},
          {"rms_scaled_residual", fit.rms_scaled},
          {"evaluations", fit.evaluations},
          {"at_bound", fit.at_bound},
          {"algorithm", fit.algorithm},
          {"stop", fit.stop_reason}};
}

std::vector<DemRun> load_seeds(const CompareOptions& opt) {
  std::vector<DemRun> seeds;
  for (const auto& d : opt.seed_dirs) seeds.push_back(load_dem_run(d, opt.allow_partial));
  return seeds;
}

json manifest_of(const CompareOptions& opt) {
  json seeds = json::array();
  for (const auto& d : opt.seed_dirs) seeds.push_back(d.string());
  return {
      {"kind", "comparison"},
      {"workbench", {{"name", "iwb"}, {"version", IWB_VERSION}}},
      {"command_line", opt.command_line},
      {"inputs",
       {{"dem_run", opt.dem_dir.string()},
        {"dem_manifest_sha256", io::sha256_hex(io::read_file(opt.dem_dir / "manifest.json"))},
        {"seed_runs", seeds},
        {"parameters", opt.params},
        {"parameters_sha256", io::sha256_hex(io::read_file(opt.params))},
        {"predicted_d_s_over_d50", opt.predicted_ds_d50},
        {"form_limit", opt.form_limit.empty() ? json() : json(opt.form_limit.string())},
        {"pooled_scatter", opt.pooled ? to_json(*opt.pooled) : json()},
        {"form_limit_sha256",
         opt.form_limit.empty() ? json() : json(io::sha256_hex(io::read_file(opt.form_limit)))}}},
      {"started", io::utc_timestamp()},
      {"status", "running"}};
}

// The headline: which quantities the predicted and the jointly fitted model hold, and the scan.
json headline(const json& predicted, const json& fitted, const Feasibility& scan) {
  auto summary = [](const json& verdicts) {
    json s = {{"holds", json::array()}, {"fails", json::array()}};
    for (const auto& v : verdicts)
      s[v["verdict"] == "holds" ? "holds" : "fails"].push_back(v["quantity"]);
    return s;
  };
  return {{"predicted", summary(predicted)}, {"fitted", summary(fitted)}, {"scan", to_json(scan)}};
}

}  // namespace

FitBounds fit_bounds(const std::string& model) {
  FitBounds b;
  if (!models::find_model(model).uses_roughness) b.kappa_min = b.kappa_max = 1.0;
  return b;
}

double gutjahr_kappa_r(double R_n, double log_base) {
  if (!(R_n > 0.0)) return models::kKappaRFloor;
  return models::kappa_r_from_normalized_roughness(R_n, log_base).value;
}

std::vector<Variant> standard_variants(const DemRun& dem, const std::string& model,
                                       const models::ModelInputs& parameters,
                                       double predicted_ds_d50) {
  const auto& spec = models::find_model(model);
  const auto [kappa, kappa_label] = predicted_kappa(spec, dem, parameters);
  std::vector<std::pair<double, std::string>> thicknesses = {
      {predicted_ds_d50 * dem.d50_mm, fmt::format("d_s = {:g} d50", predicted_ds_d50)}};
  for (double k : {5.0, 10.0})
    if (k != predicted_ds_d50)
      thicknesses.push_back({k * dem.d50_mm, fmt::format("d_s = {:g} d50", k)});
  if (const auto band = dem.band_d50())
    thicknesses.push_back(
        {*band * dem.d50_mm, fmt::format("d_s = measured wall band ({:.2g} d50)", *band)});
  std::vector<Variant> out;
  for (const auto& [d_s, label] : thicknesses) {
    Variant v{fmt::format("{}, {}", kappa_label, label), model, parameters, d_s};
    v.inputs.roughness = {spec.declaration.roughness.default_scheme, kappa};
    // for a model that reads the wall beside kappa_r, or a length in grains
    v.inputs.roughness.R_n = dem.R_n;
    v.inputs.roughness.mean_abs_slope = dem.wall_mean_abs_slope;
    v.inputs.d50_mm = dem.d50_mm;
    out.push_back(v);
  }
  out.front().label = "predicted: " + out.front().label;
  return out;
}

void chosen_roughness(const CompareOptions& opt, models::Roughness& r) {
  const auto& support = models::find_model(opt.model).declaration.roughness;
  if (!opt.roughness_scheme.empty()) {
    const auto named = support.scheme_named(opt.roughness_scheme);
    if (!named)
      throw InputError(
          fmt::format("--roughness-scheme {}: {} takes {}", opt.roughness_scheme, opt.model,
                      support.schemes.empty() ? "no wall roughness" : support.scheme_names(", ")));
    r.scheme = *named;
  }
  if (!opt.f_c.empty()) {
    if (!support.reads_arnold_herle_factor(r.scheme))
      throw InputError(fmt::format(
          "--f-c {}: the rate factor of Arnold & Herle's sand scheme; give --roughness-scheme "
          "arnold-herle with a sand model",
          opt.f_c));
    r.f_c = models::parse_arnold_herle_factor(opt.f_c, "--f-c");
  }
}

// The cyclic quantities of the runs the seed statistics rest on (seed_scatter's: the compared run
// first unless it was left out), as the monotonic verdicts'.
std::vector<cycles::CyclicQuantities> cycles_of_seeds(const DemRun& dem,
                                                      const std::vector<DemRun>& seeds,
                                                      const SeedScatter& scatter,
                                                      const cycles::Program& program) {
  const auto admitted = [&](const DemRun& r) {
    return std::find(scatter.runs.begin(), scatter.runs.end(), r.dir.string()) !=
           scatter.runs.end();
  };
  std::vector<cycles::CyclicQuantities> out;
  if (admitted(dem)) out.push_back(dem_cycles(dem, program));
  for (const auto& s : seeds)
    if (admitted(s)) out.push_back(dem_cycles(s, program));
  return out;
}

namespace {
// Each "breaks" of every variant labelled with its cause from the form-limit record (issue 38).
void label_causes(json& variants, const json& record, const fs::path& dem_dir, const DemRun& dem) {
  const auto limit =
      form_limit_causes(record, dem_dir, dem.R_n, dem.d50_mm, driver::to_string(dem.boundary));
  for (auto& v : variants)
    for (auto& verdict : v["verdicts"]) {
      const auto it = limit.find(verdict["quantity"].get<std::string>());
      if (it == limit.end()) continue;
      if (const auto c = cause_of(verdict["verdict"], it->second); !c.empty()) verdict["cause"] = c;
    }
}
}  // namespace

models::ModelInputs validated_parameters(const std::string& model, const std::string& params) {
  models::ModelInputs in;
  in.tables = io::load_parameter_file(params);
  in.source = params;
  models::find_model(model).make(in);
  return in;
}

void require_startable(const DemRun& dem, const Variant& predicted, const std::string& params) {
  const std::string why = inadmissible_start(dem, predicted);
  if (why.empty()) return;
  // a wall may shrink a model's domain (a clay's critical state cone, eq. 6.22), and a fit may
  // leave such a wall: the set is refused only where the unreduced material cannot start either
  Variant unreduced = predicted;
  unreduced.inputs.roughness.kappa_r = 1.0;
  if (inadmissible_start(dem, unreduced).empty()) return;
  throw InputError(fmt::format(
      "{}: {} cannot start from this run's first state (its sigma_n and wall band's void ratio) "
      "with {}, neither at the predicted kappa_r nor at 1: {}. The set does not describe these "
      "grains in this state: give a set calibrated on them (iwb calibrate on their soil tests)",
      dem.dir.string(), predicted.model, params, why));
}

// A model that builds only its monotonic part would replay a cyclic run's reversals with a law
// that was never meant for them, and its verdicts would judge that, not the model.
void require_reversible(const DemRun& dem, const std::string& model) {
  if (!cyclic_program(dem) || !models::find_model(model).declaration.monotonic_only) return;
  throw InputError(fmt::format(
      "--model {}: {} is a cyclic run, and {} builds only its monotonic part (src/models/{}/"
      "README.md): its path reverses where the model has no law; compare it with a model that "
      "unloads (an -igs model and its plain counterpart: --model hvwe-igs,hvwe)",
      model, dem.dir.string(), model, model));
}

ComparisonInputs read_comparison_inputs(const CompareOptions& opt) {
  ComparisonInputs in;
  in.options = opt;
  in.dem = load_dem_run(opt.dem_dir, opt.allow_partial);
  in.seeds = load_seeds(opt);
  require_reversible(in.dem, opt.model);
  in.scatter = seed_scatter(in.dem, in.seeds);  // InputError for a seed of another scene
  if (opt.pooled) apply_pooling(in.scatter, *opt.pooled);
  in.tolerances = tolerances_for(in.dem);
  in.form_limit = opt.form_limit.empty() ? json() : read_form_limit(opt.form_limit, opt.model);
  in.candidates = standard_variants(in.dem, opt.model, validated_parameters(opt.model, opt.params),
                                    opt.predicted_ds_d50);
  if (!opt.roughness_scheme.empty() || !opt.f_c.empty())
    for (auto& v : in.candidates) chosen_roughness(opt, v.inputs.roughness);
  require_startable(in.dem, in.candidates.front(), opt.params);
  return in;
}

nlohmann::json run_comparison(const CompareOptions& options) {
  return run_comparison(read_comparison_inputs(options));
}

namespace {

// Each candidate replayed along the run and judged: its metrics, verdicts and, on a cyclic run,
// its cycles (issue 34); `replays` gets the replays in the candidates' order.
json judged_variants(const ComparisonInputs& in, const std::vector<Variant>& candidates,
                     const std::optional<cycles::Program>& program,
                     const std::optional<cycles::CyclicQuantities>& dem_cyclic,
                     std::vector<Replay>& replays) {
  const auto& [opt, dem, seeds, scatter, tolerances, form_limit, given] = in;
  const auto seed_cycles = program ? cycles_of_seeds(dem, seeds, scatter, *program)
                                   : std::vector<cycles::CyclicQuantities>{};
  json variants = json::array();
  for (const auto& v : candidates) {
    replays.push_back(replay(dem, v));
    variants.push_back({{"index", replays.size() - 1},
                        {"label", v.label},
                        {"kappa_r", v.inputs.roughness.kappa_r},
                        {"d_s_mm", v.d_s_mm},
                        {"status", replays.back().status},
                        {"metrics", to_json(compare(dem, replays.back()))},
                        {"verdicts", to_json(judge(dem, scatter, replays.back(), tolerances))}});
    if (dem_cyclic) {  // issue 34: the cycles judged on the quantities of src/cycles/
      const auto model_cyclic = replay_cycles(dem, replays.back(), *program);
      variants.back()["cyclic"] = {
          {"model", cycles::to_json(model_cyclic)},
          {"verdicts", to_json(judge_cycles(dem, seed_cycles, model_cyclic))}};
    }
  }
  if (!form_limit.is_null()) label_causes(variants, form_limit, opt.dem_dir, dem);
  return variants;
}

// What compare.json says of the run, its seeds and tolerances, besides the variants.
json run_record(const ComparisonInputs& in, const std::optional<cycles::CyclicQuantities>& cyc) {
  const auto& [opt, dem, seeds, scatter, tolerances, form_limit, given] = in;
  json tol = json::object();
  for (const auto& [k, t] : tolerances) tol[k] = t;
  return {{"dem",
           {{"dir", opt.dem_dir.string()},
            {"engine", dem.engine},
            {"status", dem.status},
            {"boundary", driver::to_string(dem.boundary)},
            {"R_n", dem.R_n},
            {"d50_mm", dem.d50_mm},
            {"sigma_n0_kPa", dem.sigma_n_kPa.front()},
            {"e0_band", dem.e_band.front()}}},
          {"model", opt.model},
          {"cyclic", cyc ? cycles::to_json(*cyc) : json(nullptr)},
          {"seeds",
           {{"runs", scatter.runs},
            {"rows", scatter.rows},
            {"tau_rms_sd_kPa", scatter.tau.rms_sd},
            {"u_n_rms_sd_mm", scatter.u_n.rms_sd},
            {"sigma_n_rms_sd_kPa", scatter.sigma_n.rms_sd}}},
          {"tolerances", tol}};
}

// compare.json, compare.csv and (with seeds) seed_band.csv, each atomically and hashed in the
// manifest (`iwb report` refuses a file that changed since), then the manifest says complete.
void write_comparison(const ComparisonInputs& in, json manifest, const json& result,
                      const std::vector<Replay>& replays) {
  const auto& [opt, dem, seeds, scatter, tolerances, form_limit, given] = in;
  std::vector<std::pair<std::string, std::string>> files = {
      {"compare.json", result.dump(2) + "\n"}, {"compare.csv", curves_csv(dem, replays)}};
  if (scatter.from_seeds()) files.push_back({"seed_band.csv", seed_band_csv(dem, scatter)});
  manifest["files"] = json::array();
  for (const auto& [name, content] : files) {
    io::write_atomically(opt.out / name, content);
    manifest["files"].push_back(name);
    manifest["sha256"][name] = io::sha256_hex(content);
  }
  manifest["finished"] = io::utc_timestamp();
  manifest["status"] = "complete";
  io::write_manifest(opt.out, manifest);
}

}  // namespace

nlohmann::json run_comparison(const ComparisonInputs& in) {
  const auto& [opt, dem, seeds, scatter, tolerances, form_limit, given] = in;
  auto candidates = given;
  io::prepare_run_directory(opt.out, {"comparison"}, opt.force);
  json manifest = manifest_of(opt);
  if (!opt.roughness_scheme.empty()) manifest["inputs"]["roughness_scheme"] = opt.roughness_scheme;
  if (!opt.f_c.empty()) manifest["inputs"]["f_c"] = opt.f_c;
  io::write_manifest(opt.out, manifest);

  const Variant predicted = candidates.front();
  const FitBounds bounds = fit_bounds(opt.model);
  const FitResult tau_fit = fit_kappa_and_ds(dem, predicted, tau_only_targets(), bounds);
  const FitResult fit = fit_kappa_and_ds(dem, predicted, joint_targets(dem, scatter), bounds);
  candidates.push_back(fitted_variant(predicted, tau_fit, "tau alone", dem.d50_mm));
  candidates.push_back(fitted_variant(
      predicted, fit,
      dem.boundary == driver::BoundaryKind::kCNL ? "tau and u_n" : "tau and sigma_n", dem.d50_mm));
  const std::size_t fitted_index = candidates.size() - 1;

  std::vector<Replay> replays;
  const auto program = cyclic_program(dem);
  const auto dem_cyclic = program ? std::optional(dem_cycles(dem, *program)) : std::nullopt;
  const json variants = judged_variants(in, candidates, program, dem_cyclic, replays);
  const Feasibility scan =
      scan_feasibility(dem, scatter, predicted, tolerances, kScanPoints, bounds);
  json result = run_record(in, dem_cyclic);
  result["verdicts"] = {
      {"predicted_variant", 0},
      {"tau_only_variant", fitted_index - 1},
      {"fitted_variant", fitted_index},
      {"summary", headline(variants[0]["verdicts"], variants[fitted_index]["verdicts"], scan)}};
  result["variants"] = variants;
  result["fit"] = fit_json(fit, dem, compare(dem, replays[fitted_index]));
  result["fit_tau_only"] = fit_json(tau_fit, dem, compare(dem, replays[fitted_index - 1]));
  result["replay"] = {
      {"normal_control",
       "the DEM's boundary condition: CNL with its measured sigma_n(t), CNS with its K, CV"},
      {"initial_state", "DEM sigma_n and band void ratio of the first row; K0 = 1 - sin(phi_c)"},
      {"strain_increment", kReplayStrainIncrement}};
  write_comparison(in, manifest, result, replays);
  return result;
}

}  // namespace iwb::comparison
