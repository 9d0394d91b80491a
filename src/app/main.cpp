// iwb, the interface workbench: command line. Thin: parses, validates, calls the library.
// Exit codes: 0 done, 1 the run failed or was interrupted (its manifest says why), 2 bad input.
#include <CLI/CLI.hpp>
#include <atomic>
#include <chrono>
#include <csignal>
#include <fmt/core.h>
#include <iostream>
#include <unistd.h>

#include "app/calibration_commands.hpp"
#include "app/dem_soiltest.hpp"
#include "app/option_checks.hpp"
#include "app/default_job.hpp"
#include "app/stability.hpp"
#include "app/validate.hpp"
#include "app/tradeoff_commands.hpp"
#include "campaign/sweep.hpp"
#include "comparison/report.hpp"
#include "dem/consolidation_cache.hpp"
#include "dem/crosscheck.hpp"
#include "dem/engines.hpp"
#include "dem/run.hpp"
#include "bench/dem_bench.hpp"
#include "bench/element_bench.hpp"
#include "bench/integrator_bench.hpp"
#include "common/errors.hpp"
#include "comparison/compare.hpp"
#include "comparison/verdict_table.hpp"
#include "comparison/run_set.hpp"
#include "io/element_run.hpp"
#include "io/run_directory.hpp"
#include "models/hypoplastic/parameters.hpp"
#include "models/registry.hpp"

namespace {

using iwb::app::input_directory, iwb::app::input_file, iwb::app::input_path, iwb::app::number_in,
    iwb::app::output_directory, iwb::app::output_file, iwb::app::whole_in, iwb::app::kMaxProcesses,
    iwb::app::kMaxBudgetSeconds;

std::atomic<bool> g_interrupt{false};
void on_signal(int) { g_interrupt.store(true); }

std::string joined(int argc, char** argv) {
  std::string s;
  for (int i = 0; i < argc; ++i) s += (i ? " " : "") + std::string(argv[i]);
  return s;
}

// Progress on stderr, at most once a second, only for runs longer than a second.
std::function<void(long, long)> progress_printer() {
  auto start = std::make_shared<std::chrono::steady_clock::time_point>(std::chrono::steady_clock::now());
  auto last = std::make_shared<double>(1.0);
  return [start, last](long done, long total) {
    const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - *start).count();
    if (t < *last && done < total) return;
    *last = t + 1.0;
    if (t < 1.0) return;
    const double eta = done > 0 ? t * double(total - done) / double(done) : 0.0;
    fmt::print(stderr, "  increment {}/{} ({:.0f} %), {:.0f} s elapsed, ETA {:.0f} s\n", done, total,
               100.0 * double(done) / double(total), t, eta);
  };
}

int cmd_element(const std::string& file, const std::string& out, bool force, const std::string& cl) {
  const auto spec = iwb::io::load_element_test(file);
  for (const auto& w : spec.warnings) fmt::print(stderr, "warning: {}\n", w);
  const auto dir = out.empty() ? std::filesystem::path("runs") / std::filesystem::path(file).stem()
                               : std::filesystem::path(out);
  iwb::io::ElementRunOptions opt{dir, force, cl, iwb::io::read_file(file), &g_interrupt};
  auto spec_with_progress = spec;
  spec_with_progress.settings.on_increment = progress_printer();
  const auto outcome = iwb::io::run_element_to_directory(spec_with_progress, opt);
  const auto& r = outcome.result;
  // A failed or interrupted run is an error message: on stderr, with exit 1 (README).
  fmt::print(r.complete() ? stdout : stderr,
             "{}: {} ({} increments, {} rate evaluations, {} rejected substeps) -> {}\n", file,
             r.status, r.increments, r.counters.rate_evaluations, r.counters.rejected_substeps,
             dir.string());
  return r.complete() ? 0 : 1;
}

// Engine progress on stderr: at most one line every two seconds, and every change of stage.
std::function<void(const std::string&)> engine_progress() {
  auto last = std::make_shared<std::chrono::steady_clock::time_point>();
  auto kind = std::make_shared<std::string>();
  return [last, kind](const std::string& line) {
    const auto now = std::chrono::steady_clock::now();
    const std::string k = line.substr(0, line.find(':'));
    if (k == *kind && now - *last < std::chrono::seconds(2)) return;
    *last = now;
    *kind = k;
    fmt::print(stderr, "  {}\n", line);
  };
}

int cmd_dem_run(const std::string& scene_file, const std::string& engine_name, int np,
                const std::string& out, bool resume, bool force, const std::string& consolidated,
                const std::string& cl) {
  const auto scene = iwb::dem::load_scene(scene_file);  // refused here, before any engine starts
  for (const auto& w : scene.warnings) fmt::print(stderr, "warning: {}\n", w);
  const auto engine = iwb::dem::make_engine(engine_name);
  const auto dir = out.empty() ? std::filesystem::path("runs") / fmt::format("{}-{}", scene.name, engine_name)
                               : std::filesystem::path(out);
  iwb::dem::RunOptions opt{dir, np, resume, force, cl, &g_interrupt, engine_progress(),
                           iwb::dem::consolidation_cache_dir(consolidated)};
  fmt::print(stderr, "iwb dem run: {} with {} ({} particles requested, {} rank(s)) -> {}\n", scene_file,
             engine_name, scene.particle_count, np, dir.string());
  const auto outcome = iwb::dem::run_scene(scene, iwb::io::read_file(scene_file), *engine, opt);
  fmt::print(outcome.complete() ? stdout : stderr, "{}: {} -> {}\n", scene_file, outcome.status, dir.string());
  return outcome.complete() ? 0 : 1;
}

std::vector<std::string> split_list(const std::string& csv) {
  std::vector<std::string> out;
  std::string item;
  for (char c : csv + ",") {
    if (c != ',') {
      item += c;
    } else if (!item.empty()) {
      out.push_back(item);
      item.clear();
    }
  }
  return out;
}

int cmd_models(bool json) {
  nlohmann::json all = nlohmann::json::array();
  for (const auto& spec : iwb::models::model_registry()) {
    nlohmann::json m = {{"name", spec.name}, {"summary", spec.summary}, {"equations", spec.equations},
                        {"roughness", spec.uses_roughness}};
    if (!json) fmt::print("{:<11} {}\n{:<11} equations: {}; wall roughness: {}\n", spec.name,
                          spec.summary, "", spec.equations, spec.uses_roughness ? "yes" : "no");
    for (const auto* table : spec.tables) {
      if (!json) fmt::print("{:<11} [{}]\n", "", table->name);
      for (const auto& p : table->entries) {
        m["parameters"][table->name].push_back(
            {{"key", p.key}, {"unit", p.unit}, {"range", p.range()}, {"doc", p.doc}});
        if (!json) fmt::print("{:<13} {:<10} {:<5} {:<16} {}\n", "", p.key, p.unit, p.range(), p.doc);
      }
    }
    if (!json) fmt::print("\n");
    all.push_back(m);
  }
  if (json) fmt::print("{}\n", all.dump(2));
  else fmt::print("Roughness (interface models): [roughness] scheme = the model's own (sand: \"gutjahr\" | "
                  "\"arnold-herle\"; hcc: \"arnold-herle\"; hce: \"stutz-masin\"), and one of kappa_r, R_n "
                  "(sand, + log_base), delta_deg. See data/tests/README.md.\n");
  return 0;
}

// `iwb compare --runs`: the set's comparisons, then the hypothesis verdicts.
int cmd_compare_set(const std::vector<std::string>& runs, const iwb::comparison::CompareOptions& c,
                    const std::string& out, const std::string& cl) {
  iwb::comparison::RunSetOptions opt{{runs.begin(), runs.end()}, c.model, c.params,
                                     out.empty() ? "runs/hypotheses" : out, c.allow_partial, c.force, cl};
  opt.predicted_ds_d50 = c.predicted_ds_d50;
  const auto outcome = iwb::comparison::run_hypothesis_set(opt);
  fmt::print("{} run(s) compared ({} reused) -> {}\n", outcome.compare_dirs.size(), outcome.reused.size(),
             opt.out.string());
  for (const auto& check : outcome.hypotheses["checks"])
    fmt::print("\n{}\n  {}\n", check["title"].get<std::string>(), check["verdict"].get<std::string>());
  fmt::print("\n-> {}\n", (opt.out / "hypotheses.md").string());
  return 0;
}

// `iwb sweep`: the campaign, then its verdicts when it names a comparison.
int cmd_sweep(iwb::campaign::SweepOptions opt) {
  opt.interrupt = &g_interrupt;
  opt.progress = [](const std::string& line) { fmt::print(stderr, "  {}\n", line); };
  const auto outcome = iwb::campaign::run_sweep(opt);
  if (opt.emit_slurm) {
    fmt::print("{} -> submit from {}: sbatch sweep.slurm\n", (outcome.out / "sweep.slurm").string(), outcome.out.string());
    return 0;
  }
  fmt::print("sweep: {} -> {}\n", outcome.record["status"].get<std::string>(), (outcome.out / "sweep.json").string());
  if (outcome.comparison)
    for (const auto& check : outcome.comparison->hypotheses["checks"])
      fmt::print("\n{}\n  {}\n", check["title"].get<std::string>(), check["verdict"].get<std::string>());
  if (outcome.comparison) fmt::print("\n-> {} (iwb report {})\n", (outcome.out / "compare" / "hypotheses.md").string(),
                                     (outcome.out / "compare").string());
  return outcome.complete() ? 0 : 1;
}

// The deepest subcommand the parser had reached ("dem run" in `iwb dem run ...`), and its path.
const CLI::App& reached(const CLI::App& app, std::string& path) {
  path = "iwb";
  const CLI::App* sub = &app;
  while (!sub->get_subcommands().empty()) {
    sub = sub->get_subcommands().front();
    path += " " + sub->get_name();
  }
  return *sub;
}

// What was wrong with the command line. CLI11 reports `iwb` and `iwb bogus` alike as "A subcommand
// is required"; say instead which word is not a command, and what the commands are.
std::string parse_error_message(const CLI::App& sub, const CLI::ParseError& e) {
  // Option groups are unnamed subcommands in CLI11: not commands.
  const auto commands =
      sub.get_subcommands([](const CLI::App* c) { return !c->get_name().empty(); });
  if (e.get_name() != "RequiredError" || sub.get_require_subcommand_min() == 0) return e.what();
  std::string known;
  for (const auto* c : commands) known += (known.empty() ? "" : ", ") + c->get_name();
  const auto extra = sub.remaining();
  if (extra.empty()) return fmt::format("give a command: {}", known);
  return fmt::format("unknown command '{}'; the commands are {}", extra.front(), known);
}

// CLI11 ends a bad command line with its own codes (105 validator, 106 required, 109 extras, ...);
// the README promises 2 for every bad input, so all parse errors but --help map to 2.
int parse_error_exit(const CLI::App& app, const CLI::ParseError& e) {
  if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return app.exit(e);
  std::string path;
  const auto& sub = reached(app, path);
  fmt::print(stderr, "error: {}: {}\nRun `{} --help` for the options.\n", path,
             parse_error_message(sub, e), path);
  return 2;
}

// The message and exit code of an exception that ended a command: 2 for bad input (the README's
// promise: the message names the file, key or value), 1 for a run that failed.
int exit_for(const std::exception_ptr& error) {
  const auto fail = [](const std::string& message, int code) {
    fmt::print(stderr, "error: {}\n", message);
    return code;
  };
  try {
    std::rethrow_exception(error);
  } catch (const iwb::InputError& e) {
    return fail(e.what(), 2);
  } catch (const std::filesystem::filesystem_error& e) {
    // A path given to the command (--out under a file, an unreadable directory); what() names it.
    return fail(e.what(), 2);
  } catch (const nlohmann::json::parse_error& e) {
    // Every JSON file iwb parses is in a run or comparison directory given to the command.
    return fail(fmt::format("a JSON file in the given directories is not JSON: {}", e.what()), 2);
  } catch (const std::exception& e) {
    return fail(e.what(), 1);
  } catch (...) {
    return fail("unknown exception", 1);
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "iwb, the interface workbench: DEM interface-shear scenes (LIGGGHTS, YADE) and continuum\n"
      "hypoplastic interface models run side by side on the same path.\n\n"
      "Examples:\n"
      "  iwb models                                  list models, parameters, units, bounds\n"
      "  iwb element data/tests/hvwe_cnl_dense.toml  run one element test into runs/<name>/\n"
      "  iwb run                                     the main job on the embedded default\n"
      "  iwb dem run data/scenes/smoke.toml          a DEM interface-shear scene in LIGGGHTS\n"
      "  iwb sweep data/sweeps/example.toml -j 2     a campaign of scenes (R_n x d50 x CNL/CNS/CV x seed)\n"
      "  iwb tradeoff data/scenes/default.toml -j 2  DEM speed against accuracy, knob by knob\n"
      "  iwb bench element                           cost of the continuum core\n"
      "  iwb stability hvwe data/params/table_5_1_evaluation.toml   where a model runs and where it stops\n"};
  app.require_subcommand(1);
  const std::string cl = joined(argc, argv);

  auto* element = app.add_subcommand(
      "element",
      "Run an element test described in a TOML file (schema: data/tests/README.md) and write a "
      "run directory with manifest.json and history.csv (compression positive, kPa, mm).");
  std::string test_file, out;
  bool force = false;
  element->add_option("test", test_file, "element-test TOML file")->required()->check(input_file());
  element->add_option("--out,-o", out, "run directory (default runs/<test file stem>)")->check(output_directory());
  element->add_flag("--force", force, "replace an earlier run in the same directory");

  auto* models = app.add_subcommand("models", "List the constitutive models, their parameters "
                                              "(keys, units, bounds, meaning) and equations.");
  bool as_json = false;
  models->add_flag("--json", as_json, "machine-readable output");

  auto* run = app.add_subcommand(
      "run", "The main job on the embedded default: hvwe against its 3D reference vw3d in simple "
             "shear under CNL, CNS and CV (seed Table 5.1), with a table of their differences.");
  std::string run_out = "runs/default";
  run->add_option("--out,-o", run_out, "output directory")->check(output_directory())->capture_default_str();
  run->add_flag("--force", force, "replace earlier runs in the output directory");

  auto* dem = app.add_subcommand("dem", "DEM interface-shear scenes (scene schema: data/scenes/README.md).");
  dem->require_subcommand(1);
  auto* dem_run = dem->add_subcommand(
      "run",
      "Run a scene in a DEM engine and write the run directory of the contract (DEM.md): "
      "manifest.json, timeseries.csv, profiles.csv, vtk/ with .pvd indexes, summary.json. Stages "
      "(consolidate, shear) are recorded as they finish; --resume continues an interrupted run.");
  std::string scene_file, engine_name = "liggghts";
  int np = 1;
  bool resume = false;
  dem_run->add_option("scene", scene_file, "scene TOML file")->required()->check(input_file());
  dem_run->add_option("--engine", engine_name, "DEM engine: liggghts or yade")->capture_default_str();
  dem_run->add_option("--np,--threads", np, "parallel processes: MPI ranks (LIGGGHTS) or OpenMP threads (YADE)")->check(whole_in(1, kMaxProcesses))->capture_default_str();
  dem_run->add_option("--out,-o", out, "run directory (default runs/<scene>-<engine>)")->check(output_directory());
  dem_run->add_flag("--resume", resume, "continue an interrupted run of the same scene from its last finished stage");
  dem_run->add_flag("--force", force, "replace an earlier run in the same directory");
  std::string consolidated;
  dem_run->add_option("--consolidated", consolidated,
                      "start from a consolidated specimen of the same consolidation key kept in DIR, or keep this "
                      "run's there (default $IWB_CONSOLIDATED_DIR, else none; src/dem/consolidation_cache.hpp)");

  const auto dem_soiltest = iwb::app::add_dem_soiltest(*dem);

  auto* dem_cross = dem->add_subcommand(
      "crosscheck",
      "Run one scene in both engines with K seeds each (seed = 1..K) and put peak and residual "
      "tau/sigma_n, dilation rate and wall band thickness side by side with their seed scatter and "
      "each engine's wall-clock cost; verdicts: residual friction within 10 %, dilation of the same "
      "sign and order. Writes crosscheck.json and crosscheck.md; complete runs in the output "
      "directory are reused, so a stopped crosscheck continues when run again.");
  iwb::dem::CrosscheckOptions xopt;
  std::string cross_scene, cross_out, cross_engines = "liggghts,yade";
  dem_cross->add_option("scene", cross_scene, "scene TOML file")->required()->check(input_file());
  dem_cross->add_option("--seeds", xopt.seeds, "seeds per engine")->check(whole_in(1, 100))->capture_default_str();
  dem_cross->add_option("--engines", cross_engines, "comma-separated engines")->capture_default_str();
  dem_cross->add_option("--np,--threads", xopt.processes, "MPI ranks / OpenMP threads per run")->check(whole_in(1, kMaxProcesses))->capture_default_str();
  dem_cross->add_option("--out,-o", cross_out, "output directory (default runs/crosscheck-<scene>)")->check(output_directory());

  auto* dem_summary = dem->add_subcommand(
      "summary", "Recompute summary.json of a complete run directory from its contract files (peak and "
                 "residual friction, dilation, shear mode and band, wall slip, band void ratio).");
  std::string run_dir;
  dem_summary->add_option("run_dir", run_dir, "a run directory of `iwb dem run`")->required()->check(input_directory());

  auto* compare = app.add_subcommand(
      "compare",
      "Judge a continuum model against a DEM run. The model is replayed along the DEM's own path "
      "(measured u_x(t); CNL with the measured sigma_n(t), CNS with the scene's K, CV) from the "
      "DEM's first state, in variants of kappa_r and d_s: predicted without fitting (kappa_r from "
      "eq. 5.35 with the wall's R_n, d_s = --predict-ds-d50 x d50; also 5 and 10 d50 and the "
      "measured wall band), fitted to tau alone, and fitted to tau and u_n (CNL) or tau and sigma_n "
      "(CNS, CV) together, each weighted by the DEM's seed scatter (--seeds; without seeds, by its "
      "range). Per quantity (peak and residual friction, u_x at the peak, total dilation, dilation "
      "rate, sigma_n change) the DEM +- seed SD, the model, the error, the tolerance (the scene's "
      "[requirements], else 10, 5, 30, 20, 20, 20 %) and a verdict: holds, breaks, or within DEM "
      "scatter. A scan of the (kappa_r, d_s) box says whether any pair makes every quantity hold. "
      "Writes compare.json, compare.csv (curves) and seed_band.csv.\n"
      "Example: iwb compare data/reference/reference_rn/runs/sawtooth-2-0.5_cnl_s1 --seeds "
      "data/reference/reference_rn/runs/sawtooth-2-0.5_cnl_s{2,3} --params "
      "data/params/dem_default_grains.toml -o runs/cmp");
  iwb::comparison::CompareOptions copt;
  std::string dem_dir, compare_out;
  std::vector<std::string> set_runs, seed_runs;
  auto* single_run = compare->add_option("dem_run", dem_dir, "a run directory of `iwb dem run`")->check(input_directory());
  compare->add_option("--runs", set_runs, "a set of DEM run directories: each is compared (or its complete comparison "
                                          "in OUT/<run> reused), with the set's runs of its scene and other seeds as "
                                          "its seeds, then the hypothesis checks of DEM.md over the set "
                                          "into OUT/hypotheses.json and .md")
      ->check(input_directory())->excludes(single_run);
  compare->add_option("--seeds", seed_runs, "runs of the same scene with other seeds: their scatter weighs the joint "
                                            "fit and the verdicts")
      ->check(input_directory())->excludes("--runs");
  compare->add_option("--predict-ds-d50", copt.predicted_ds_d50, "d_s of the predicted variant, in d50")
      ->capture_default_str()->check(number_in(iwb::closed(0.5, 100.0), "d50"));
  compare->add_option("--model", copt.model, "continuum model (iwb models)")->capture_default_str();
  compare->add_option("--params", copt.params, "parameter file (data/params/)")->required()->check(input_file());
  compare->add_option("--out,-o", compare_out, "output directory (default runs/compare-<dem run>)")->check(output_directory());
  compare->add_flag("--allow-partial", copt.allow_partial, "compare a failed or interrupted DEM run");
  compare->add_flag("--force", copt.force, "replace an earlier comparison in the same directory");

  auto* sweep = app.add_subcommand(
      "sweep",
      "Run a campaign: the cartesian product of the axes of a sweep file (schema and example: "
      "data/sweeps/README.md) over a base scene, each job a `dem run` in DIR/runs/<job> with a readable "
      "name (rn0.5_d2_cnl_s1). Every job's scene is validated first; a bad value refuses the whole sweep. "
      "At most --jobs run at once with --np ranks each; run it again to continue: complete runs of the same "
      "scene are reused, stopped ones resumed. DIR/sweep.json tracks every job; Ctrl-C stops cleanly. When the "
      "sweep names a comparison, the hypothesis checks of `compare --runs` follow into DIR/compare "
      "(then: iwb report DIR/compare). --emit slurm writes DIR/sweep.slurm (a job array) instead of running.");
  iwb::campaign::SweepOptions sweep_opt;
  std::string sweep_file, sweep_out, sweep_emit;
  sweep->add_option("sweep", sweep_file, "sweep TOML file")->required()->check(input_file());
  sweep->add_option("--jobs,-j", sweep_opt.jobs, "jobs at once on this machine (jobs x np should not exceed the cores)")->check(whole_in(1, kMaxProcesses))->capture_default_str();
  sweep->add_option("--np,--threads", sweep_opt.processes, "MPI ranks (LIGGGHTS) or threads (YADE) per job")->check(whole_in(1, kMaxProcesses))->capture_default_str();
  sweep->add_option("--emit", sweep_emit, "write a batch script instead of running: slurm")->check(CLI::IsMember({"slurm"}));
  sweep->add_option("--out,-o", sweep_out, "campaign directory (default runs/sweep-<sweep file stem>)")->check(output_directory());
  sweep->add_option("--stop-after", sweep_opt.stop_after, "stop cleanly once N jobs have ended (running ones are interrupted); run again to continue")->check(whole_in(1, 1000000));

  auto* report = app.add_subcommand(
      "report", "Write one self-contained HTML report (inline SVG figures, opens offline) from comparison "
                "directories of `iwb compare`; figures also as SVG and PNG with their data and gnuplot scripts.");
  std::vector<std::string> compare_dirs;
  std::string report_out = "report.html";
  report->add_option("compare_dirs", compare_dirs, "directories of `iwb compare`, or the OUT of `iwb compare --runs` "
                                                   "(its verdicts come first)")->required()->check(input_path());
  report->add_option("-o,--out", report_out, "HTML file")->check(output_file())->capture_default_str();

  auto* validate = app.add_subcommand(
      "validate", "The main job: run a DEM scene (the embedded default unless --scene), replay it through hvwe "
                  "with the set calibrated on the scene's grains (data/calibration/) or else the shipped set "
                  "closest to the DEM's residual friction angle, and write "
                  "report.html (a few minutes on 2 cores). Runs from any directory: the scenes (data/scenes/"
                  "default.toml, smoke.toml) and parameter sets (data/params/) are built into iwb. Everything is "
                  "checked before the engine starts. Run again with the same scene and --out, it reuses the "
                  "complete DEM run there (a stopped one is resumed) and redoes only the replay and the report, "
                  "also with another --params-dir; --force runs the DEM again.");
  iwb::app::ValidateOptions vopt;
  std::string vout = "runs/validate";
  validate->add_option("--scene", vopt.scene, "embedded scene name (default, smoke) or a scene file")->capture_default_str();
  std::string validate_engines = "liggghts";
  validate->add_option("--engines", validate_engines, "comma-separated DEM engines (liggghts, yade); each runs the scene and is replayed, one report")->capture_default_str();
  validate->add_option("--np,--threads", vopt.processes, "MPI ranks (LIGGGHTS) or threads (YADE) per run")->check(whole_in(1, kMaxProcesses))->capture_default_str();
  validate->add_option("--out,-o", vout, "output directory")->check(output_directory())->capture_default_str();
  validate->add_option("--params-dir", vopt.params_dir, "a directory of parameter sets (*.toml) to choose from "
                                                         "instead of those built into iwb (data/params/ at build time)")->check(input_directory());
  validate->add_flag("--force", vopt.force, "replace earlier runs in the output directory");

  auto* stability = app.add_subcommand(
      "stability",
      "Stability map of a model: sweeps sigma_n0 (1 kPa to 10 MPa), e0 (just above e_d to just below e_i at "
      "sigma_n0), kappa_r (0.05 to 1), shear strain per increment (1e-6 to 1e-2) and cyclic runs, under CNL, "
      "CNS and CV, and writes stability.csv (one row per point: outcome, reason, message, counts of rejected "
      "substeps), stability.md (counts per outcome, why points stopped) and stability_<BC>.svg/.png (sigma_n0 x "
      "density index coloured by the worst outcome). Outcomes: complete, domain error, no convergence, budget "
      "exceeded, inadmissible start, non-finite value, other error. The reduced form takes seconds, --full "
      "(1000-cycle runs) minutes.\n\nExample: iwb stability hvwe data/params/table_5_1_evaluation.toml --full");
  iwb::app::StabilityOptions stability_opt;
  stability->add_option("model", stability_opt.model, "model name (iwb models)")->required();
  stability->add_option("params", stability_opt.params, "parameter file, e.g. data/params/table_5_1_evaluation.toml; "
                                               "-igs models need an [intergranular_strain] table (table_5_3_*)")->required()->check(input_file());
  stability->add_flag("--full", stability_opt.full, "the full sweep (5 values per axis, 1000 cycles) instead of the reduced one");
  stability->add_option("--out,-o", stability_opt.out, "output directory (default runs/stability-<model>)")->check(output_directory());
  stability->add_option("--budget", stability_opt.budget_seconds, "wall-clock seconds per point before it is stopped as "
                                                          "'budget exceeded' (default 5 reduced, 10 full)")->check(number_in(iwb::positive(kMaxBudgetSeconds), "s"));

  auto* bench = app.add_subcommand("bench", "Benchmarks that print figures.");
  bench->require_subcommand(1);
  auto* bench_element = bench->add_subcommand(
      "element", "Rate evaluations per second and the time of a 2000-increment CNL simple shear "
                 "at rtol 1e-6, for each model.");
  iwb::bench::ElementBenchOptions bopt;
  bench_element->add_option("--repeats", bopt.repeats, "runs per model; the best is reported")
      ->check(whole_in(1, 1000))->capture_default_str();
  bench_element
      ->add_option("--igs-params", bopt.igs_params,
                   "parameter set of the -igs models (Table 5.1 has no [intergranular_strain]); "
                   "they are skipped when it is not there")
      ->capture_default_str();

  auto* bench_integrators = bench->add_subcommand(
      "integrators", "Integration error against cost (rate evaluations, wall time) of explicit Euler with "
                     "1..256 substeps and adaptive rk32/rk54 at rtol 1e-2..1e-8, against rk54 at 1e-10, for "
                     "vw3d, hvwe, ahe, ah, hp1d, hvwe-exact, hvwe-igs under CNL, CNS and CV; writes "
                     "integrators.csv, integrators.md and pareto_<model>.svg/.png (a few seconds). Error: max over the path of |x - x_ref| / max |x_ref| for tau and sigma_n, the larger of the two.");
  iwb::bench::IntegratorBenchOptions iopt;
  std::string iout = iopt.out.string();
  bench_integrators->add_option("--out,-o", iout, "output directory")->check(output_directory())->capture_default_str();

  auto* bench_dem = bench->add_subcommand(
      "dem", "Particle-steps per second of a DEM engine on a scene with 1 and 2 ranks, and the "
             "workbench's own overhead as a share of the run (a few minutes on the default scene).");
  iwb::bench::DemBenchOptions dopt;
  bench_dem->add_option("--engine", dopt.engine, "DEM engine: liggghts (ranks = MPI ranks) or yade (ranks = OpenMP threads)")->check(CLI::IsMember({"liggghts", "yade"}))->capture_default_str();
  bench_dem->add_option("--scene", dopt.scene, "scene file")->check(input_file())->capture_default_str();
  bench_dem->add_option("--ranks", dopt.ranks, "rank counts to measure")->check(whole_in(1, kMaxProcesses))->capture_default_str();

  const auto calibration_commands = iwb::app::add_calibration_commands(app);
  const auto tradeoff_commands = iwb::app::add_tradeoff_commands(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return parse_error_exit(app, e);
  }
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  try {
    if (*element) return cmd_element(test_file, out, force, cl);
    if (const auto code = iwb::app::run_calibration_commands(*calibration_commands, cl)) return *code;
    if (const auto code = iwb::app::run_tradeoff_commands(*tradeoff_commands, cl, &g_interrupt)) return *code;
    if (*models) return cmd_models(as_json);
    if (*run) return iwb::app::run_default_job(run_out, force, cl);
    if (*dem_run) return cmd_dem_run(scene_file, engine_name, np, out, resume, force, consolidated, cl);
    if (const auto code = iwb::app::run_dem_soiltest(*dem_soiltest, cl, &g_interrupt, engine_progress())) return *code;
    if (*report) {
      std::vector<std::filesystem::path> dirs(compare_dirs.begin(), compare_dirs.end());
      const auto figures = iwb::comparison::write_report(dirs, report_out);
      fmt::print("report: {} ({} figures)\n", std::filesystem::absolute(report_out).string(), figures.size());
      return 0;
    }
    if (*validate) {
      vopt.out = vout;
      vopt.engines = split_list(validate_engines);
      vopt.command_line = cl;
      return iwb::app::run_validate(vopt);
    }
    if (*sweep) {
      sweep_opt.sweep_file = sweep_file;
      sweep_opt.out = sweep_out;
      sweep_opt.emit_slurm = sweep_emit == "slurm";
      sweep_opt.command_line = cl;
      return cmd_sweep(sweep_opt);
    }
    if (*compare && !set_runs.empty()) return cmd_compare_set(set_runs, copt, compare_out, cl);
    if (*compare) {
      if (dem_dir.empty()) throw iwb::InputError("compare: give a DEM run directory or --runs DIR...");
      copt.dem_dir = dem_dir;
      copt.out = compare_out.empty()
                     ? std::filesystem::path("runs") / ("compare-" + std::filesystem::path(dem_dir).filename().string())
                     : std::filesystem::path(compare_out);
      copt.command_line = cl;
      copt.seed_dirs.assign(seed_runs.begin(), seed_runs.end());
      const auto result = iwb::comparison::run_comparison(copt);
      fmt::print("{}", iwb::comparison::to_text(iwb::comparison::verdict_table(result)));
      for (const auto& f : iwb::comparison::verdict_findings(result)) fmt::print("{}\n", f);
      fmt::print("-> {} (iwb report {})\n", copt.out.string(), copt.out.string());
      return 0;
    }
    if (*dem_cross) {
      xopt.scene_file = cross_scene;
      xopt.engines = split_list(cross_engines);
      xopt.out = cross_out.empty() ? std::filesystem::path("runs") /
                                         ("crosscheck-" + std::filesystem::path(cross_scene).stem().string())
                                   : std::filesystem::path(cross_out);
      xopt.command_line = cl;
      xopt.interrupt = &g_interrupt;
      xopt.progress = engine_progress();
      const auto result = iwb::dem::run_crosscheck(xopt);
      fmt::print("{}", iwb::io::read_file(xopt.out / "crosscheck.md"));
      fmt::print("-> {}\n", xopt.out.string());
      return 0;
    }
    if (*dem_summary) {
      fmt::print("{}\n", iwb::dem::resummarize(run_dir).dump(2));
      return 0;
    }
    if (*bench_dem) {
      iwb::bench::run_dem_bench(dopt);
      return 0;
    }
    if (*stability) return iwb::app::run_stability(stability_opt);
    if (*bench_integrators) {
      iopt.out = iout;
      iwb::bench::run_integrator_bench(iopt);
      return 0;
    }
    if (*bench_element) {
      iwb::bench::run_element_bench(bopt);
      return 0;
    }
  } catch (...) {
    return exit_for(std::current_exception());
  }
  return 0;
}
