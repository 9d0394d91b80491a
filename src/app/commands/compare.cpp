// `iwb compare RUN_DIR` and `iwb compare --runs RUN_DIR...`: a continuum model judged against DEM
// runs (comparison/compare/compare.hpp, comparison/compare/run_set.hpp).
#include "comparison/compare/compare.hpp"

#include <fmt/core.h>

#include <filesystem>
#include <memory>

#include "app/command_list.hpp"
#include "app/commands/commands.hpp"
#include "app/option_checks.hpp"
#include "common/errors.hpp"
#include "comparison/compare/compare_models.hpp"
#include "comparison/compare/run_set.hpp"
#include "comparison/presentation/verdict_table.hpp"
#include "comparison/replay/quantities.hpp"
#include "comparison/verdicts/cyclic_verdicts.hpp"
#include "models/registry.hpp"

namespace iwb::app {

namespace fs = std::filesystem;

void print_hypothesis_checks(const nlohmann::json& hypotheses) {
  for (const auto& check : hypotheses["checks"])
    fmt::print("\n{}\n  {}\n", check["title"].get<std::string>(),
               check["verdict"].get<std::string>());
}

namespace {

struct CompareCommand {
  comparison::CompareOptions options;
  std::vector<std::string> models = {::iwb::models::kDefaultInterfaceModel};
  std::string dem_dir, out;
  std::vector<std::string> set_runs, seed_runs;
  bool own_scatter = false;
};

// `iwb compare --runs`: the set's comparisons, then the hypothesis verdicts.
int compare_set(const CompareCommand& o, const CommandContext& context) {
  if (o.models.size() > 1)
    throw InputError("--model: a set (--runs) is compared with one model; give one");
  auto c = o.options;
  c.model = o.models.front();
  comparison::RunSetOptions opt;
  opt.dem_dirs = {o.set_runs.begin(), o.set_runs.end()};
  opt.model = c.model, opt.params = c.params, opt.out = o.out.empty() ? "runs/hypotheses" : o.out;
  opt.allow_partial = c.allow_partial, opt.force = c.force, opt.command_line = context.command_line;
  opt.predicted_ds_d50 = c.predicted_ds_d50;
  opt.form_limit = c.form_limit;
  opt.roughness_scheme = c.roughness_scheme, opt.f_c = c.f_c;
  opt.pool_scatter = !o.own_scatter;
  const auto outcome = comparison::run_hypothesis_set(opt);
  fmt::print("{} run(s) compared ({} reused) -> {}\n", outcome.compare_dirs.size(),
             outcome.reused.size(), opt.out.string());
  print_hypothesis_checks(outcome.hypotheses);
  fmt::print("\n-> {}\n", (opt.out / "hypotheses.md").string());
  return 0;
}

void print_verdicts(const nlohmann::json& result, bool with_cycles) {
  const auto cyclic = comparison::cyclic_verdict_table(result);
  if (with_cycles && !cyclic.rows.empty())
    fmt::print("Cycles (issue 34):\n{}\nMonotonic quantities over the whole path:\n",
               comparison::to_text(cyclic));
  fmt::print("{}", comparison::to_text(comparison::verdict_table(result)));
  for (const auto& f : comparison::verdict_findings(result)) fmt::print("{}\n", f);
}

// One model into OUT, several each into OUT/<model> (comparison/compare/compare_models.hpp).
int compare_run(const CompareCommand& o, const CommandContext& context) {
  if (o.dem_dir.empty()) throw InputError("compare: give a DEM run directory or --runs DIR...");
  auto opt = o.options;
  opt.dem_dir = o.dem_dir;
  opt.out = o.out.empty()
                ? fs::path("runs") / ("compare-" + fs::path(o.dem_dir).filename().string())
                : fs::path(o.out);
  opt.command_line = context.command_line;
  opt.seed_dirs.assign(o.seed_runs.begin(), o.seed_runs.end());
  const auto c = comparison::compare_models(opt, o.models);
  if (c.results.size() == 1) {
    print_verdicts(c.results.front(), true);
  } else {
    const auto beside = comparison::cyclic_models_table(c.results);
    if (!beside.rows.empty())
      fmt::print("Cycles, model beside model (issue 34):\n{}", comparison::to_text(beside));
    for (std::size_t k = 0; k < c.results.size(); ++k) {
      fmt::print("\n{} ({}):\n", o.models[k], c.dirs[k].string());
      print_verdicts(c.results[k], false);
    }
  }
  std::string dirs;
  for (const auto& d : c.dirs) dirs += " " + d.string();
  fmt::print("->{} (iwb report{})\n", dirs, dirs);
  return 0;
}

}  // namespace

void add_compare_command(CLI::App& app, CommandList& commands) {
  auto o = std::make_shared<CompareCommand>();
  auto* compare = app.add_subcommand(
      "compare",
      "Judge a continuum model against a DEM run. The model is replayed along the DEM's own path "
      "(measured u_x(t); CNL with the measured sigma_n(t), CNS with the scene's K, CV) from the "
      "DEM's first state, in variants of kappa_r and d_s: predicted without fitting (kappa_r from "
      "eq. 5.35 with the wall's R_n, d_s = --predict-ds-d50 x d50; also 5 and 10 d50 and the "
      "measured wall band), fitted to tau alone, and fitted to tau and u_n (CNL) or tau and "
      "sigma_n "
      "(CNS, CV) together, each weighted by the DEM's seed scatter (--seeds; without seeds, by its "
      "range). Per quantity (peak and residual friction, u_x at the peak, total dilation, dilation "
      "rate, sigma_n change at the end and the lowest sigma_n on the way (CNS, CV: what a "
      "contractive interface loses before it dilates again), and the dilation of the wall zone "
      "alone, from its void ratio: a loose specimen may move the plate from elsewhere) the DEM "
      "(its seed mean +- the 95 % "
      "Student's t-interval; seeds that sheared at the plate left out), the model, the error, the "
      "tolerance (the scene's [requirements], else the default: " +
          comparison::default_tolerances_text() +
          "), the detection "
          "limit and a verdict: holds, "
          "breaks (beyond the tolerance by more than the interval), or within DEM scatter. A "
          "cyclic "
          "run is judged per cycle first (cycles 1, 2, 5 and the last: peaks each way, sigma_n "
          "degradation, accumulated u_n, reversal stiffness; each as a change from cycle 1 to the "
          "last; then the post-cyclic peak and u_n; tolerances the scene's [requirements], else " +
          comparison::tolerances_text({comparison::cyclic_default_tolerances().begin(),
                                       comparison::cyclic_default_tolerances().end()}) +
          "). "
          "A scan of the (kappa_r, d_s) box says whether any pair makes every quantity hold. "
          "Writes compare.json, compare.csv (curves) and seed_band.csv.\n"
          "Example: iwb compare data/reference/reference_rn/runs/sawtooth-2-0.5_cnl_s1 --seeds "
          "data/reference/reference_rn/runs/sawtooth-2-0.5_cnl_s{2,3} --params "
          "data/params/dem_default_grains.toml -o runs/cmp");
  auto& copt = o->options;
  auto* single_run = compare->add_option("dem_run", o->dem_dir, "a run directory of `iwb dem run`")
                         ->check(input_directory());
  compare
      ->add_option("--runs", o->set_runs,
                   "a set of DEM run directories: each is compared (or its complete comparison "
                   "in OUT/<run> reused), with the set's runs of its scene and other seeds as "
                   "its seeds, then the hypothesis checks of DEM.md over the set "
                   "into OUT/hypotheses.json and .md")
      ->check(input_directory())
      ->excludes(single_run);
  compare
      ->add_option("--seeds", o->seed_runs,
                   "runs of the same scene with other seeds: their scatter weighs the joint "
                   "fit and the verdicts")
      ->check(input_directory())
      ->excludes("--runs");
  compare
      ->add_option("--predict-ds-d50", copt.predicted_ds_d50,
                   "d_s of the predicted variant, in d50")
      ->capture_default_str()
      ->check(number_in(closed(0.5, 100.0), "d50"));
  compare
      ->add_option("--model", o->models,
                   "continuum model (iwb models); several, comma-separated (an -igs model and its "
                   "plain counterpart: hvwe-igs,hvwe), are each judged along the same run into "
                   "OUT/<model>, their cyclic verdicts printed side by side")
      ->delimiter(',')
      ->capture_default_str();
  compare->add_option("--params", copt.params, "parameter file (data/params/)")
      ->required()
      ->check(input_file());
  compare->add_option("--out,-o", o->out, "output directory (default runs/compare-<dem run>)")
      ->check(output_directory());
  compare->add_option(
      "--roughness-scheme", copt.roughness_scheme,
      "the wall's roughness scheme for every variant instead of the model's default "
      "(one the model "
      "declares: iwb models)");
  compare
      ->add_option("--f-c", copt.f_c,
                   "Arnold & Herle's rate factor: 1/kappa_r (eq. 5.40 as printed, default) or "
                   "kappa_r (ERRATA 9); with --roughness-scheme arnold-herle")
      ->check(CLI::IsMember({"1/kappa_r", "kappa_r"}));
  compare->add_flag("--own-scatter", o->own_scatter,
                    "with --runs: each cell's own seed scatter, not the set's pooled one (pooled "
                    "per quantity where Levene's test about the median does not reject equal "
                    "relative scatter across cells of 3 or more runs; pooled_scatter.json)");
  compare
      ->add_option("--form-limit", copt.form_limit,
                   "a form-limit record of the model (iwb form-limit's form_limit.json): each "
                   "breaking quantity then says whether the model's form or its calibration broke")
      ->check(input_file());
  compare->add_flag("--allow-partial", copt.allow_partial,
                    "compare a failed or interrupted DEM run");
  compare->add_flag("--force", copt.force, "replace an earlier comparison in the same directory");
  commands.add(compare, [o](const CommandContext& c) {
    return o->set_runs.empty() ? compare_run(*o, c) : compare_set(*o, c);
  });
}

}  // namespace iwb::app
