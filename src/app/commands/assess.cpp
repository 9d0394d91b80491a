// `iwb assess MODEL PARAMS`: the total Sobol indices of an interface model's element test, or its
// parameter uncertainty (issue 17, seed 4.3.1-4.3.2); `iwb assess --reference RUN...`: the league
// of the interface models on a DEM scene (model, parameter and global uncertainty, seed 4.3).
#include "assessment/assess.hpp"

#include <fmt/core.h>
#include <fmt/ranges.h>

#include <filesystem>
#include <map>
#include <memory>

#include "app/command_list.hpp"
#include "app/commands/commands.hpp"
#include "app/option_checks.hpp"
#include "app/progress.hpp"
#include "assessment/distribution_file.hpp"
#include "assessment/element_sensitivity.hpp"
#include "common/errors.hpp"
#include "comparison/figure.hpp"
#include "io/parameter_file.hpp"
#include "io/run_directory.hpp"
#include "io/toml_reader.hpp"

namespace iwb::app {

namespace {

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
    if (!(v > 0.0 && v <= 1.0))
      throw InputError(fmt::format("--cov-of {}: the COV must be in (0, 1]", g));
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
      if (eq == std::string::npos || eq == 0 || star == std::string::npos || star < eq ||
          star + 1 == g.size())
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

std::string markdown(const assessment::SobolResult& r, const assessment::AssessOptions& o) {
  std::string md = fmt::format(
      "# Total Sobol indices: {} ({})\n\nEvery material parameter normal about the file's value "
      "with COV {}{}; "
      "monotonic simple shear under {} from sigma_n0 = {} kPa to gamma = {} in {} increments. "
      "Saltelli's sampling, "
      "Jansen's estimator, N = {} ({} element tests, {} rows dropped for a failed run), 95 % "
      "bootstrap intervals.\n\n"
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
    for (const auto& t : r.total[q])
      md += fmt::format(" {:.3f} [{:.3f}, {:.3f}] |", t.value, t.low, t.high);
    md += "\n";
  }
  return md;
}

std::string csv(const assessment::SobolResult& r) {
  std::string out = "quantity,parameter,S_T,S_T_low,S_T_high\n";
  for (std::size_t q = 0; q < r.quantities.size(); ++q)
    for (std::size_t i = 0; i < r.parameters.size(); ++i)
      out += fmt::format("{},{},{:.6g},{:.6g},{:.6g}\n", r.quantities[q], r.parameters[i],
                         r.total[q][i].value, r.total[q][i].low, r.total[q][i].high);
  return out;
}

std::string uncertainty_markdown(const assessment::UncertaintyResult& r,
                                 const assessment::AssessOptions& o) {
  std::string md = fmt::format(
      "# Parameter uncertainty: {} ({}, distributions {})\n\nLatin hypercube, {} samples ({} "
      "failed and left out); "
      "monotonic simple shear under {} from sigma_n0 = {} kPa to gamma = {}.\n\n| quantity | mean "
      "| SD | CV_Y |\n"
      "|---|---|---|---|\n",
      o.model, o.params, o.uncertainty, r.samples, r.failed, o.boundary, o.sigma_n, o.gamma);
  for (const auto& q : r.quantities)
    md += fmt::format("| {} | {:.4g} | {:.4g} | {:.3f} |\n", q.name, q.mean, q.sd, q.cv);
  return md;
}

// The indices at N/16, N/8, N/4, N/2 and N (each its own samples): sobol_convergence.csv and .md,
// and a figure of the first quantity's indices with their intervals against N. Returns N's.
assessment::SobolResult sobol_convergence(const models::ModelSpec& spec,
                                          assessment::ElementSensitivityOptions opt,
                                          const assessment::AssessOptions& o,
                                          const std::filesystem::path& dir) {
  std::string csv_text = "N,quantity,parameter,S_T,S_T_low,S_T_high\n";
  std::string md = fmt::format(
      "# Convergence of the total Sobol indices: {} ({}), COV {}\n\nThe first quantity's indices "
      "and their 95 % bootstrap intervals against the base sample size N (each N its own "
      "samples; every quantity in sobol_convergence.csv):\n\n| N |",
      o.model, o.params, o.cov);
  std::vector<comparison::PlotCurve> curves;
  assessment::SobolResult r;
  for (int k = 4; k >= 0; --k) {
    opt.samples = std::max(10, o.samples >> k);
    r = assessment::element_sensitivity(spec, opt);
    if (k == 4) {
      for (const auto& p : r.parameters) md += " " + p + " |", curves.push_back({p, {}, {}});
      md += "\n|---|";
      for (std::size_t i = 0; i < r.parameters.size(); ++i) md += "---|";
      md += "\n";
    }
    md += fmt::format("| {} |", opt.samples);
    for (std::size_t i = 0; i < r.parameters.size(); ++i) {
      const auto& t = r.total[0][i];
      md += fmt::format(" {:.3f} [{:.3f}, {:.3f}] |", t.value, t.low, t.high);
      curves[i].x.push_back(opt.samples), curves[i].y.push_back(t.value);
      for (std::size_t q = 0; q < r.quantities.size(); ++q)
        csv_text += fmt::format("{},{},{},{:.6g},{:.6g},{:.6g}\n", opt.samples, r.quantities[q],
                                r.parameters[i], r.total[q][i].value, r.total[q][i].low,
                                r.total[q][i].high);
    }
    md += "\n";
  }
  io::prepare_run_directory(dir, true);
  io::write_atomically(dir / "sobol_convergence.csv", csv_text);
  io::write_atomically(dir / "sobol_convergence.md", md);
  auto fig = comparison::curves_figure(
      "sobol_convergence",
      fmt::format("{}: total Sobol indices of {} against N", o.model, r.quantities.front()),
      "N, the base sample size", "S_T", curves);
  fig.extra += "set logscale x\n";
  comparison::draw(fig, dir);
  return r;
}

// The league's table on stdout, its models and runs as they go and its file on stderr.
int run_league_command(assessment::AssessOptions o) {
  o.note = [](const std::string& line) { fmt::print(stderr, "{}\n", line); };
  o.run_counter = [] { return increment_progress("run"); };
  const auto outcome = assessment::run_league(o);
  fmt::print("{}", outcome.table);
  fmt::print(stderr, "-> {}\n", outcome.file.string());
  return 0;
}

int run_assess(const assessment::AssessOptions& o) {
  if (!o.reference.empty()) return run_league_command(o);
  if (o.model.empty() || o.params.empty())
    throw InputError(
        "iwb assess: give MODEL and PARAMS (the Sobol indices or --uncertainty of one model), or "
        "--reference RUN... (the league)");
  const auto& spec = models::find_model(o.model);
  assessment::ElementSensitivityOptions opt;
  opt.inputs.tables = io::load_parameter_file(o.params);
  opt.inputs.source = o.params;
  spec.make(opt.inputs);  // the means must be a valid set, before anything runs
  opt.boundary = driver::parse_boundary_kind(o.boundary, "--bc");
  opt.cov = o.cov, opt.cov_of = own_covs(o.cov_of), opt.ties = tied(o.ties),
  opt.sigma_n_kPa = o.sigma_n, opt.e0 = o.e0, opt.K_kPa_per_unit_strain = o.K;
  opt.gamma = o.gamma, opt.increments = o.increments, opt.samples = o.samples, opt.seed = o.seed,
  opt.threads = o.threads;
  if (opt.boundary == driver::BoundaryKind::kCNS && !(o.K > 0.0))
    throw InputError("--bc CNS needs --K, the spring stiffness in kPa per unit normal strain");
  const auto dir = o.out.empty() ? std::filesystem::path("runs") / ("assess-" + o.model)
                                 : std::filesystem::path(o.out);
  const auto tick = increment_progress("run");
  opt.progress = [&](long done, long total) { tick(done, total); };
  if (!o.uncertainty.empty()) {
    const auto r =
        assessment::element_uncertainty(spec, opt, assessment::read_distributions(o.uncertainty));
    io::prepare_run_directory(dir, true);
    const auto md = uncertainty_markdown(r, o);
    io::write_atomically(dir / "uncertainty.md", md);
    fmt::print("{}", md);
    return 0;
  }
  const auto r = o.convergence ? sobol_convergence(spec, opt, o, dir)
                               : assessment::element_sensitivity(spec, opt);
  if (!o.convergence) io::prepare_run_directory(dir, true);
  io::write_atomically(dir / "sobol.csv", csv(r));
  io::write_atomically(dir / "sobol.md", markdown(r, o));
  fmt::print("{}", markdown(r, o));
  fmt::print(stderr, "-> {}\n", (dir / "sobol.md").string());
  return 0;
}

}  // namespace

void add_assess_command(CLI::App& app, CommandList& commands) {
  auto o = std::make_shared<assessment::AssessOptions>();
  auto* cmd = app.add_subcommand(
      "assess",
      "Global sensitivity of an interface model (seed 4.3.1, Tables 4.3-4.7): every material "
      "parameter of its "
      "tables normal about the parameter file's value with one coefficient of variation (--cov; "
      "the seed takes 0.05 "
      "and 0.1), a monotonic simple-shear element test per sample, and the total Sobol index of "
      "each parameter for "
      "the peak and end friction, the end normal strain and the end normal stress (Saltelli's "
      "sampling, Jansen's "
      "estimator, 95 % bootstrap intervals; N (k + 2) runs for k parameters). Writes sobol.csv and "
      "sobol.md.\n\n"
      "Example: iwb assess mc data/params/table_4_3_mohr_coulomb.toml --cov 0.1 --samples 2000\n\n"
      "With --reference RUN...: the league of the interface models on a DEM scene (seed 4.3): each "
      "calibrated to the "
      "runs, its model uncertainty at the seed's objective points (eqs. 4.3, 4.15) in shear and "
      "dilation, its "
      "parameter uncertainty (the CV of the peak shear stress over --samples Latin hypercube "
      "samples about the "
      "calibrated set, the seed's Table 4.8 COVs), the global uncertainty sqrt(UA_model^2 + "
      "UA_par^2) (ERRATA 16), "
      "ranked: league.md (table first), league.csv, models/<model>.json, figures/.\n"
      "Example: iwb assess --reference data/convergence/truth_clamped/runs/s{1,2,3} --samples 500 "
      "-o runs/league");
  cmd->add_option("model", o->model,
                  "model name (iwb models); with --reference, the one model of the league");
  cmd->add_option("params", o->params,
                  "parameter file: the distributions' means; with --reference, that model's set")
      ->check(input_file());
  cmd->add_option("--cov", o->cov, "coefficient of variation of every parameter")
      ->check(number_in(positive(1.0)));
  cmd->add_option("--cov-of", o->cov_of,
                  "KEY=COV: this parameter's own coefficient of variation instead of --cov "
                  "(repeat; the seed takes 0.01 "
                  "for the sensitive parameters it stars, e.g. Mortara's alpha_p, alpha_c, omega)");
  cmd->add_flag("--convergence", o->convergence,
                "also the indices at N/16, N/8, N/4 and N/2 (each with its own samples): "
                "sobol_convergence.md, .csv "
                "and .svg show how they settle with the sample size");
  cmd->add_option("--tie", o->ties,
                  "KEY=FACTOR*OTHER: this parameter follows another and is not varied itself "
                  "(repeat; the seed's "
                  "Table 4.6 samples e_c0 only: --tie ei0=1.2*ec0 --tie ed0=0.379*ec0)");
  cmd->add_option("--bc", o->boundary, "CNL, CNS or CV")
      ->check(CLI::IsMember({"CNL", "CNS", "CV"}));
  cmd->add_option("--sigma-n", o->sigma_n, "initial normal stress, kPa")
      ->check(number_in(positive(1e5), "kPa"));
  cmd->add_option("--e0", o->e0, "initial void ratio, for a model that has one")
      ->check(number_in(positive(10.0)));
  cmd->add_option("--K", o->K, "CNS spring stiffness, kPa per unit normal strain")
      ->check(number_in(positive(1e9)));
  cmd->add_option("--gamma", o->gamma, "shear strain of the test")
      ->check(number_in(positive(10.0)));
  cmd->add_option("--increments", o->increments, "increments of the test")
      ->check(whole_in(10, 100000));
  cmd->add_option("--samples", o->samples, "N, the base sample size")->check(whole_in(10, 1000000));
  cmd->add_option("--seed", o->seed, "random seed of the samples");
  cmd->add_option("--uncertainty", o->uncertainty,
                  "instead of the Sobol indices: the CV of each quantity when the parameters "
                  "follow the distributions of "
                  "this file ([[parameter]] key, distribution, mean, cov; "
                  "data/assessment/distributions/, seed Table 4.8), "
                  "from --samples Latin hypercube samples")
      ->check(input_file());
  cmd->add_option("--reference", o->reference,
                  "the league instead: DEM runs of one scene (its seeds; the first is replayed, "
                  "all make the seed mean and "
                  "scatter). Every interface model (--models) is calibrated to them, judged at the "
                  "seed's objective points "
                  "(hardening, peak, softening, residual, and the dilation at peak and end), "
                  "sampled about its calibrated "
                  "set for its parameter uncertainty, and ranked by global uncertainty: league.md, "
                  "league.csv, "
                  "models/<model>.json, figures/. Run again with the same options to resume.")
      ->check(CLI::ExistingDirectory);
  cmd->add_option(
         "--models", o->models,
         "with --reference: the models of the league (default: every interface model for "
         "granular scenes, simplest first: mc, hyperbolic, hp1d, ah, ahe, lashkari, mortara, "
         "hvwe, ahe-igs, hvwe-igs)")
      ->delimiter(',');
  cmd->add_option("--params-for", o->params_for,
                  "with --reference: MODEL=FILE, that model's parameter set (repeat; default: the "
                  "set calibrated on the "
                  "scene's grains for the hypoplastic models, the seed's table as the fit's start "
                  "for the others)");
  cmd->add_option("--sobol-samples", o->sobol_samples,
                  "with --reference: N of the total Sobol indices about each calibrated set (N (k "
                  "+ 2) replays; default 0: none)")
      ->check(whole_in(0, 1000000));
  cmd->add_option("--distributions", o->distributions,
                  "with --reference: directory of distribution files, one per parameter table "
                  "(<table>.toml: the kind "
                  "and COV of each parameter; default: data/assessment/distributions/ as built "
                  "into iwb, the seed's "
                  "Table 4.8 and Appendix A)");
  cmd->add_option("--parameter-uncertainty", o->parameter_uncertainty,
                  "with --reference: seed (default): the COVs of the seed's Table 4.8 and Appendix "
                  "A about the "
                  "calibrated values; fit: each calibrated quantity spread by its own sigma from "
                  "the fit to the runs")
      ->check(CLI::IsMember({"seed", "fit"}));
  cmd->add_option("--form-limits", o->form_limits,
                  "with --reference: a directory of form-limit records (iwb form-limit's "
                  "DIR/*/form_limit.json, e.g. data/reference/form_limit): each model's row says "
                  "which quantities its prediction breaks on this wall and boundary, and whether "
                  "its form or its calibration broke them")
      ->check(CLI::ExistingDirectory)
      ->needs("--reference");
  cmd->add_option("--threads", o->threads, "runs at once (default 0: every core)")
      ->check(whole_in(0, 1024));
  cmd->add_flag("--force", o->force,
                "with --reference: replace an earlier league of other options in --out");
  cmd->add_option(
         "--out,-o", o->out,
         "output directory (default runs/assess-<model>, with --reference runs/assess-league)")
      ->check(output_directory());
  commands.add(cmd, [o](const CommandContext&) { return run_assess(*o); });
}

}  // namespace iwb::app
