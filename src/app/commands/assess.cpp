// `iwb assess MODEL PARAMS`: the total Sobol indices of an interface model's element test, or its
// parameter uncertainty (issue 17, seed 4.3.1-4.3.2); `iwb assess --reference RUN...`: the league
// of the interface models on a DEM scene (model, parameter and global uncertainty, seed 4.3).
#include <fmt/core.h>
#include <fmt/ranges.h>

#include <map>

#include <filesystem>
#include <memory>

#include "app/command_list.hpp"
#include "app/commands/commands.hpp"
#include "app/option_checks.hpp"
#include "app/progress.hpp"
#include "assessment/distribution_file.hpp"
#include "assessment/element_sensitivity.hpp"
#include "assessment/league_output.hpp"
#include "app/parameter_choice.hpp"
#include "comparison/dem_run.hpp"
#include "dem/scene.hpp"
#include "io/json_file.hpp"
#include "io/parameter_sets.hpp"
#include "common/errors.hpp"
#include "io/parameter_file.hpp"
#include "io/run_directory.hpp"
#include "io/toml_reader.hpp"

namespace iwb::app {

namespace {

struct AssessOptions {
  std::string model, params, out, boundary = "CNL", uncertainty;
  std::vector<std::string> reference, models, params_for;  // the league
  std::string distributions;  // empty: the files built into iwb
  std::string parameter_uncertainty = "seed";
  int sobol_samples = 0, threads = 0;
  bool force = false;
  double cov = 0.1, sigma_n = 100.0, e0 = 0.0, K = 0.0, gamma = 0.1;
  int samples = 1000, increments = 200;
  unsigned seed = 1;
  std::vector<std::string> cov_of;  // KEY=COV
  std::vector<std::string> ties;    // KEY=FACTOR*OTHER
};

// --cov-of KEY=COV, repeated: InputError naming the bad one.
std::map<std::string, double> own_covs(const std::vector<std::string>& given) {
  std::map<std::string, double> out;
  for (const auto& g : given) {
    const auto eq = g.find('=');
    double v = 0.0;
    try {
      if (eq == std::string::npos || eq == 0) throw std::invalid_argument(g);
      v = std::stod(g.substr(eq + 1));
    } catch (const std::exception&) {
      throw InputError(fmt::format("--cov-of {}: give KEY=COV, e.g. alpha_p=0.01", g));
    }
    if (!(v > 0.0 && v <= 1.0)) throw InputError(fmt::format("--cov-of {}: the COV must be in (0, 1]", g));
    out[g.substr(0, eq)] = v;
  }
  return out;
}

// --tie KEY=FACTOR*OTHER, repeated: InputError naming the bad one.
std::map<std::string, std::pair<double, std::string>> tied(const std::vector<std::string>& given) {
  std::map<std::string, std::pair<double, std::string>> out;
  for (const auto& g : given) {
    const auto eq = g.find('='), star = g.find('*');
    double factor = 0.0;
    try {
      if (eq == std::string::npos || eq == 0 || star == std::string::npos || star < eq || star + 1 == g.size())
        throw std::invalid_argument(g);
      factor = std::stod(g.substr(eq + 1, star - eq - 1));
    } catch (const std::exception&) {
      throw InputError(fmt::format("--tie {}: give KEY=FACTOR*OTHER, e.g. ei0=1.2*ec0", g));
    }
    if (!(factor > 0.0)) throw InputError(fmt::format("--tie {}: the factor must be positive", g));
    out[g.substr(0, eq)] = {factor, g.substr(star + 1)};
  }
  return out;
}

std::string markdown(const assessment::SobolResult& r, const AssessOptions& o) {
  std::string md = fmt::format(
      "# Total Sobol indices: {} ({})\n\nEvery material parameter normal about the file's value with COV {}{}; "
      "monotonic simple shear under {} from sigma_n0 = {} kPa to gamma = {} in {} increments. Saltelli's sampling, "
      "Jansen's estimator, N = {} ({} element tests, {} rows dropped for a failed run), 95 % bootstrap intervals.\n\n"
      "| quantity |",
      o.model, o.params, o.cov,
      (o.cov_of.empty() ? "" : fmt::format(" ({} their own)", fmt::join(o.cov_of, ", "))) +
          (o.ties.empty() ? "" : fmt::format("; tied, not varied: {}", fmt::join(o.ties, ", "))),
      o.boundary, o.sigma_n, o.gamma, o.increments, r.base_samples, r.evaluations, r.failed);
  for (const auto& p : r.parameters) md += " " + p + " |";
  md += "\n|---|";
  for (std::size_t i = 0; i < r.parameters.size(); ++i) md += "---|";
  md += "\n";
  for (std::size_t q = 0; q < r.quantities.size(); ++q) {
    md += "| " + r.quantities[q] + " |";
    for (const auto& t : r.total[q]) md += fmt::format(" {:.3f} [{:.3f}, {:.3f}] |", t.value, t.low, t.high);
    md += "\n";
  }
  return md;
}

std::string csv(const assessment::SobolResult& r) {
  std::string out = "quantity,parameter,S_T,S_T_low,S_T_high\n";
  for (std::size_t q = 0; q < r.quantities.size(); ++q)
    for (std::size_t i = 0; i < r.parameters.size(); ++i)
      out += fmt::format("{},{},{:.6g},{:.6g},{:.6g}\n", r.quantities[q], r.parameters[i], r.total[q][i].value,
                         r.total[q][i].low, r.total[q][i].high);
  return out;
}

std::string uncertainty_markdown(const assessment::UncertaintyResult& r, const AssessOptions& o) {
  std::string md = fmt::format(
      "# Parameter uncertainty: {} ({}, distributions {})\n\nLatin hypercube, {} samples ({} failed and left out); "
      "monotonic simple shear under {} from sigma_n0 = {} kPa to gamma = {}.\n\n| quantity | mean | SD | CV_Y |\n"
      "|---|---|---|---|\n",
      o.model, o.params, o.uncertainty, r.samples, r.failed, o.boundary, o.sigma_n, o.gamma);
  for (const auto& q : r.quantities) md += fmt::format("| {} | {:.4g} | {:.4g} | {:.3f} |\n", q.name, q.mean, q.sd, q.cv);
  return md;
}

models::ModelInputs as_inputs(const io::ParameterSet& set) {
  models::ModelInputs in;
  in.tables = set.tables;
  in.source = set.origin;
  return in;
}

// The league's parameter set of `model`: --params-for MODEL=FILE, else the positional set when
// one model is named, else for a model calibrated from soil tests the set of the scene's grains as
// `iwb validate` chooses it, else the model's own example (the seed's table), where its fit starts.
models::ModelInputs league_parameters(const AssessOptions& o, const std::string& model, const comparison::DemRun& dem) {
  for (const auto& g : o.params_for) {
    const auto eq = g.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == g.size())
      throw InputError(fmt::format("--params-for {}: give MODEL=FILE, e.g. hvwe=data/params/truth_grains.toml", g));
    if (g.substr(0, eq) != model) continue;
    return as_inputs(io::read_parameter_set(g.substr(eq + 1)));
  }
  if (!o.params.empty()) return as_inputs(io::read_parameter_set(o.params));
  const auto& spec = models::find_model(model);
  if (spec.declaration.calibration_recipe.empty()) return io::shipped_inputs(spec.declaration.example_parameters);
  std::string why;
  const auto scene = dem::parse_scene(dem.scene_text, (dem.dir / "manifest.json").string() + " /scene/text");
  return as_inputs(parameters_for(io::parameter_sets({}), scene, dem.summary.at("residual_friction").get<double>(), why));
}

// The tables a set lacks for `spec` (the sand set has no [intergranular_strain] for the -igs models)
// from the model's own example set, and the source says so.
models::ModelInputs with_missing_tables(const models::ModelSpec& spec, models::ModelInputs in) {
  for (const auto* t : spec.tables)
    if (!in.tables.count(t->name)) {
      in.tables[t->name] = io::shipped_inputs(spec.declaration.example_parameters).tables.at(t->name);
      in.source += fmt::format(" + [{}] of {}", t->name, spec.declaration.example_parameters);
    }
  return in;
}

std::vector<std::string> league_models(const AssessOptions& o) {
  if (!o.model.empty()) return {o.model};
  if (!o.models.empty()) {
    for (const auto& m : o.models) models::find_model(m);  // an unknown name is refused before anything runs
    return o.models;
  }
  return models::ranked_interface_models(true);
}

// What a model's record was made from: a record of other inputs is not reused.
nlohmann::json record_inputs(const AssessOptions& o, const models::ModelInputs& in,
                             const std::map<std::string, std::string>& distributions) {
  return {{"reference", o.reference}, {"parameters", in.tables}, {"samples", o.samples}, {"sobol_samples", o.sobol_samples},
          {"seed", o.seed}, {"distributions", distributions}, {"parameter_uncertainty", o.parameter_uncertainty}};
}

int run_league(const AssessOptions& o) {
  std::vector<comparison::DemRun> runs;
  for (const auto& r : o.reference) runs.push_back(comparison::load_dem_run(r));
  const auto ref = assessment::scene_reference(runs);  // refuses runs of different scenes
  const auto names = league_models(o);
  const auto texts = assessment::distribution_texts(o.distributions);  // each file's text: a changed COV is a changed input
  std::vector<models::ModelInputs> inputs;
  for (const auto& m : names) {
    inputs.push_back(with_missing_tables(models::find_model(m), league_parameters(o, m, runs.front())));
    inputs.back().source = inputs.back().source.empty() ? "?" : inputs.back().source;
    models::find_model(m).make(inputs.back());  // a set the model refuses is bad input, before anything runs
  }
  const auto dir = o.out.empty() ? std::filesystem::path("runs") / "assess-league" : std::filesystem::path(o.out);
  const nlohmann::json header = {{"scene", runs.front().dir.parent_path().string()}, {"runs", o.reference},
                                 {"boundary", driver::to_string(ref.mean.boundary)},
                                 {"wall", fmt::format("R_n {:g}, d50 {:g} mm", ref.mean.R_n, ref.mean.d50_mm)},
                                 {"normal", ref.mean.boundary == driver::BoundaryKind::kCV ? "sigma_n" : "dilation"},
                                 {"uncertainty_samples", o.samples}, {"sobol_samples", o.sobol_samples}, {"models", names},
                                 {"parameter_uncertainty", o.parameter_uncertainty}};
  // an earlier league continues here: its model records say what they were made from, and only
  // those made from these inputs are reused
  const bool resume = std::filesystem::exists(dir / "manifest.json") &&
                      io::read_json_file(dir / "manifest.json").contains("league");
  if (!resume) io::prepare_run_directory(dir, o.force);
  io::write_manifest(dir, {{"command", "assess"}, {"league", header}, {"status", "running"}});
  std::vector<nlohmann::json> entries;
  for (std::size_t i = 0; i < names.size(); ++i) {
    const auto record = dir / "models" / (names[i] + ".json");
    const auto in = record_inputs(o, inputs[i], texts);
    if (std::filesystem::exists(record)) {
      auto old = io::read_json_file(record);
      if (old.value("inputs", nlohmann::json()) == in) {
        fmt::print(stderr, "model {}/{}: {} (reused {})\n", i + 1, names.size(), names[i], record.string());
        entries.push_back(old);
        continue;
      }
    }
    fmt::print(stderr, "model {}/{}: {} (calibration, {} parameter samples{})\n", i + 1, names.size(), names[i], o.samples,
               o.sobol_samples > 0 ? fmt::format(", Sobol N = {}", o.sobol_samples) : "");
    assessment::LeagueOptions lo;
    lo.spread = o.parameter_uncertainty == "fit" ? assessment::ParameterSpread::kFitSigmas : assessment::ParameterSpread::kSeedCovs;
    lo.distributions = texts, lo.uncertainty_samples = o.samples, lo.sobol_samples = o.sobol_samples;
    lo.seed = o.seed, lo.threads = o.threads, lo.progress = increment_progress("run");
    auto e = assessment::entry_json(assessment::assess_model(ref, names[i], inputs[i], lo));
    e["inputs"] = in;
    std::filesystem::create_directories(record.parent_path());
    io::write_atomically(record, e.dump(1));
    entries.push_back(e);
  }
  const auto table = assessment::ranked(entries);
  assessment::draw_league_figures(table, dir / "figures");
  io::write_atomically(dir / "league.csv", assessment::league_csv(table));
  io::write_atomically(dir / "league.md", assessment::league_markdown(header, table));
  io::write_manifest(dir, {{"command", "assess"}, {"league", header}, {"status", "complete"}});
  const auto md = assessment::league_markdown(header, table);
  fmt::print("{}", md.substr(0, md.find("\n![")));
  fmt::print(stderr, "-> {}\n", (dir / "league.md").string());
  return 0;
}

int run_assess(const AssessOptions& o) {
  if (!o.reference.empty()) return run_league(o);
  if (o.model.empty() || o.params.empty())
    throw InputError("iwb assess: give MODEL and PARAMS (the Sobol indices or --uncertainty of one model), or --reference RUN... (the league)");
  const auto& spec = models::find_model(o.model);
  assessment::ElementSensitivityOptions opt;
  opt.inputs.tables = io::load_parameter_file(o.params);
  opt.inputs.source = o.params;
  spec.make(opt.inputs);  // the means must be a valid set, before anything runs
  opt.boundary = driver::parse_boundary_kind(o.boundary, "--bc");
  opt.cov = o.cov, opt.cov_of = own_covs(o.cov_of), opt.ties = tied(o.ties), opt.sigma_n_kPa = o.sigma_n, opt.e0 = o.e0, opt.K_kPa_per_unit_strain = o.K;
  opt.gamma = o.gamma, opt.increments = o.increments, opt.samples = o.samples, opt.seed = o.seed, opt.threads = o.threads;
  if (opt.boundary == driver::BoundaryKind::kCNS && !(o.K > 0.0))
    throw InputError("--bc CNS needs --K, the spring stiffness in kPa per unit normal strain");
  const auto dir = o.out.empty() ? std::filesystem::path("runs") / ("assess-" + o.model) : std::filesystem::path(o.out);
  const auto tick = increment_progress("run");
  opt.progress = [&](long done, long total) { tick(done, total); };
  if (!o.uncertainty.empty()) {
    const auto r = assessment::element_uncertainty(spec, opt, assessment::read_distributions(o.uncertainty));
    io::prepare_run_directory(dir, true);
    const auto md = uncertainty_markdown(r, o);
    io::write_atomically(dir / "uncertainty.md", md);
    fmt::print("{}", md);
    return 0;
  }
  const auto r = assessment::element_sensitivity(spec, opt);
  io::prepare_run_directory(dir, true);
  io::write_atomically(dir / "sobol.csv", csv(r));
  io::write_atomically(dir / "sobol.md", markdown(r, o));
  fmt::print("{}", markdown(r, o));
  fmt::print(stderr, "-> {}\n", (dir / "sobol.md").string());
  return 0;
}

}  // namespace

void add_assess_command(CLI::App& app, CommandList& commands) {
  auto o = std::make_shared<AssessOptions>();
  auto* cmd = app.add_subcommand(
      "assess",
      "Global sensitivity of an interface model (seed 4.3.1, Tables 4.3-4.7): every material parameter of its "
      "tables normal about the parameter file's value with one coefficient of variation (--cov; the seed takes 0.05 "
      "and 0.1), a monotonic simple-shear element test per sample, and the total Sobol index of each parameter for "
      "the peak and end friction, the end normal strain and the end normal stress (Saltelli's sampling, Jansen's "
      "estimator, 95 % bootstrap intervals; N (k + 2) runs for k parameters). Writes sobol.csv and sobol.md.\n\n"
      "Example: iwb assess mc data/params/table_4_3_mohr_coulomb.toml --cov 0.1 --samples 2000\n\n"
      "With --reference RUN...: the league of the interface models on a DEM scene (seed 4.3): each calibrated to the "
      "runs, its model uncertainty at the seed's objective points (eqs. 4.3, 4.15) in shear and dilation, its "
      "parameter uncertainty (the CV of the peak shear stress over --samples Latin hypercube samples about the "
      "calibrated set, the seed's Table 4.8 COVs), the global uncertainty sqrt(UA_model^2 + UA_par^2) (ERRATA 16), "
      "ranked: league.md (table first), league.csv, models/<model>.json, figures/.\n"
      "Example: iwb assess --reference data/convergence/truth_clamped/runs/s{1,2,3} --samples 500 -o runs/league");
  cmd->add_option("model", o->model, "model name (iwb models); with --reference, the one model of the league");
  cmd->add_option("params", o->params, "parameter file: the distributions' means; with --reference, that model's set")
      ->check(input_file());
  cmd->add_option("--cov", o->cov, "coefficient of variation of every parameter")->check(number_in(positive(1.0)));
  cmd->add_option("--cov-of", o->cov_of,
                  "KEY=COV: this parameter's own coefficient of variation instead of --cov (repeat; the seed takes 0.01 "
                  "for the sensitive parameters it stars, e.g. Mortara's alpha_p, alpha_c, omega)");
  cmd->add_option("--tie", o->ties,
                  "KEY=FACTOR*OTHER: this parameter follows another and is not varied itself (repeat; the seed's "
                  "Table 4.6 samples e_c0 only: --tie ei0=1.2*ec0 --tie ed0=0.379*ec0)");
  cmd->add_option("--bc", o->boundary, "CNL, CNS or CV")->check(CLI::IsMember({"CNL", "CNS", "CV"}));
  cmd->add_option("--sigma-n", o->sigma_n, "initial normal stress, kPa")->check(number_in(positive(1e5), "kPa"));
  cmd->add_option("--e0", o->e0, "initial void ratio, for a model that has one")->check(number_in(positive(10.0)));
  cmd->add_option("--K", o->K, "CNS spring stiffness, kPa per unit normal strain")->check(number_in(positive(1e9)));
  cmd->add_option("--gamma", o->gamma, "shear strain of the test")->check(number_in(positive(10.0)));
  cmd->add_option("--increments", o->increments, "increments of the test")->check(whole_in(10, 100000));
  cmd->add_option("--samples", o->samples, "N, the base sample size")->check(whole_in(10, 1000000));
  cmd->add_option("--seed", o->seed, "random seed of the samples");
  cmd->add_option("--uncertainty", o->uncertainty,
                  "instead of the Sobol indices: the CV of each quantity when the parameters follow the distributions of "
                  "this file ([[parameter]] key, distribution, mean, cov; data/assessment/distributions/, seed Table 4.8), "
                  "from --samples Latin hypercube samples")
      ->check(input_file());
  cmd->add_option("--reference", o->reference,
                  "the league instead: DEM runs of one scene (its seeds; the first is replayed, all make the seed mean and "
                  "scatter). Every interface model (--models) is calibrated to them, judged at the seed's objective points "
                  "(hardening, peak, softening, residual, and the dilation at peak and end), sampled about its calibrated "
                  "set for its parameter uncertainty, and ranked by global uncertainty: league.md, league.csv, "
                  "models/<model>.json, figures/. Run again with the same options to resume.")
      ->check(CLI::ExistingDirectory);
  cmd->add_option("--models", o->models, "with --reference: the models of the league (default: every interface model for "
                                         "granular scenes, simplest first: mc, hyperbolic, hp1d, ah, ahe, lashkari, mortara, "
                                         "hvwe, ahe-igs, hvwe-igs)")
      ->delimiter(',');
  cmd->add_option("--params-for", o->params_for,
                  "with --reference: MODEL=FILE, that model's parameter set (repeat; default: the set calibrated on the "
                  "scene's grains for the hypoplastic models, the seed's table as the fit's start for the others)");
  cmd->add_option("--sobol-samples", o->sobol_samples,
                  "with --reference: N of the total Sobol indices about each calibrated set (N (k + 2) replays; default 0: none)")
      ->check(whole_in(0, 1000000));
  cmd->add_option("--distributions", o->distributions,
                  "with --reference: directory of distribution files, one per parameter table (<table>.toml: the kind "
                  "and COV of each parameter; default: data/assessment/distributions/ as built into iwb, the seed's "
                  "Table 4.8 and Appendix A)");
  cmd->add_option("--parameter-uncertainty", o->parameter_uncertainty,
                  "with --reference: seed (default): the COVs of the seed's Table 4.8 and Appendix A about the "
                  "calibrated values; fit: each calibrated quantity spread by its own sigma from the fit to the runs")
      ->check(CLI::IsMember({"seed", "fit"}));
  cmd->add_option("--threads", o->threads, "runs at once (default 0: every core)")->check(whole_in(0, 1024));
  cmd->add_flag("--force", o->force, "with --reference: replace an earlier league of other options in --out");
  cmd->add_option("--out,-o", o->out, "output directory (default runs/assess-<model>, with --reference runs/assess-league)")
      ->check(output_directory());
  commands.add(cmd, [o](const CommandContext&) { return run_assess(*o); });
}

}  // namespace iwb::app
