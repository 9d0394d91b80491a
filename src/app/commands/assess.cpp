// `iwb assess MODEL PARAMS`: the total Sobol indices of an interface model's element test, or its
// parameter uncertainty (issue 17, seed 4.3.1-4.3.2); `iwb assess --reference RUN...`: the league
// of the interface models on a DEM scene (model, parameter and global uncertainty, seed 4.3). The
// work is assessment/assess.hpp's.
#include "assessment/assess.hpp"

#include <fmt/core.h>

#include <memory>

#include "app/command_list.hpp"
#include "app/commands/commands.hpp"
#include "app/option_checks.hpp"
#include "app/progress.hpp"

namespace iwb::app {

namespace {

// The table on stdout; the league's models, the runs as they go and the file written on stderr.
int run_assess_command(assessment::AssessOptions o) {
  o.note = [](const std::string& line) { fmt::print(stderr, "{}\n", line); };
  o.run_counter = [] { return increment_progress("run"); };
  const auto outcome = assessment::run_assess(o);
  fmt::print("{}", outcome.table);
  if (!outcome.file.empty()) fmt::print(stderr, "-> {}\n", outcome.file.string());
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
  cmd->add_option("--models", o->models,
                  "with --reference: the models of the league (default: every interface model for "
                  "granular scenes, simplest first: " +
                      std::string(kInterfaceModelLadder) + ")")
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
  commands.add(cmd, [o](const CommandContext&) { return run_assess_command(*o); });
}

}  // namespace iwb::app
