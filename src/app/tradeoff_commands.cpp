#include "app/tradeoff_commands.hpp"

#include <fmt/core.h>

#include "app/option_checks.hpp"
#include "app/parameter_choice.hpp"
#include "io/json_file.hpp"
#include "io/run_directory.hpp"
#include "tradeoff/knobs.hpp"
#include "tradeoff/plan.hpp"
#include "tradeoff/tradeoff.hpp"

namespace iwb::app {

namespace fs = std::filesystem;

struct TradeoffCommands {
  CLI::App* tradeoff = nullptr;
  CLI::App* plan = nullptr;
  std::string scene, out, knobs = "box,kappa,dt,I", reference = "refined";
  int jobs = 1, np = 1, seeds = 3, stop_after = 0;
  std::string plan_scene, plan_tradeoff, plan_params, plan_out;
};

namespace {

void add_tradeoff(CLI::App& app, TradeoffCommands& c) {
  c.tradeoff = app.add_subcommand(
      "tradeoff",
      "Speed against accuracy of a DEM scene. Runs the scene with K seeds (their scatter is the "
      "noise floor), each "
      "knob halved and doubled one at a time, every knob refined at once (the reference: larger "
      "box, stiffer "
      "grains, smaller step, slower shear) and coarsened at once. Knobs: box (length and height in "
      "d50; the "
      "particle count scales with the volume; where the length cannot shrink, the height alone), "
      "kappa (the "
      "stiffness level, through Young's modulus), dt (numerics.dt_fraction of the Rayleigh time), "
      "I (the inertial "
      "number). Measures peak and residual friction, dilation rate and band thickness against the "
      "reference, with "
      "cost in particle-steps and wall time: DIR/tradeoff.md, .csv, .json and pareto.svg/.png. The "
      "runs are a "
      "campaign (as iwb sweep): N at once, complete runs reused and stopped ones resumed when run "
      "again; Ctrl-C "
      "stops cleanly.\n"
      "Example: iwb tradeoff data/scenes/default.toml -o runs/tradeoff-default --jobs 2\n"
      "then:    iwb plan data/scenes/default.toml --tradeoff runs/tradeoff-default");
  c.tradeoff->add_option("scene", c.scene, "scene TOML file (data/scenes/)")
      ->required()
      ->check(input_file());
  c.tradeoff->add_option("--out,-o", c.out,
                         "tradeoff directory (default runs/tradeoff-<scene stem>)")
      ->check(output_directory());
  c.tradeoff
      ->add_option("--jobs,-j", c.jobs, "runs at once (jobs x np should not exceed the cores)")
      ->check(whole_in(1, kMaxProcesses))
      ->capture_default_str();
  c.tradeoff->add_option("--np", c.np, "MPI ranks per run")
      ->check(whole_in(1, kMaxProcesses))
      ->capture_default_str();
  c.tradeoff
      ->add_option("--seeds", c.seeds,
                   "seeds of the base setting (>= 2; 3 or more for a usable noise floor)")
      ->check(whole_in(2, 100))
      ->capture_default_str();
  c.tradeoff->add_option("--knobs", c.knobs, "comma-separated knobs to vary: box, kappa, dt, I")
      ->capture_default_str();
  c.tradeoff
      ->add_option("--reference", c.reference,
                   "what the errors are measured against: refined (every knob refined at once, one "
                   "seed) or base (the scene itself, mean of its seeds: for a scene a convergence "
                   "study showed converged, e.g. data/scenes/truth.toml; then only cheaper settings run)")
      ->check(CLI::IsMember({"refined", "base"}))
      ->capture_default_str();
  c.tradeoff
      ->add_option("--stop-after", c.stop_after,
                   "stop cleanly once N runs have ended; run again to continue")
      ->check(whole_in(1, 1000000));
}

void add_plan(CLI::App& app, TradeoffCommands& c) {
  c.plan = app.add_subcommand(
      "plan",
      "Choose from a scene's [requirements] (data/scenes/README.md: a relative tolerance per "
      "quantity of "
      "interest, or \"not needed\") and its tradeoff (run `iwb tradeoff` first): the cheapest DEM "
      "setting whose "
      "errors plus the seed noise floor meet every tolerance, and the simplest continuum model "
      "(hp1d, ah, hvwe; "
      "hvwe-igs too for cyclic paths) whose errors, averaged over the scene's own runs (the base "
      "seeds) replayed along their own "
      "paths with kappa_r and d_s fitted, meet them. Prints the decision and which setting or model "
      "failed which "
      "tolerance by how much; writes plan.json.\n"
      "It needs the tradeoff's run directories (the base runs are replayed), not only its "
      "tables.\n"
      "Example: iwb plan data/scenes/default.toml --tradeoff runs/tradeoff-default");
  c.plan->add_option("scene", c.plan_scene, "scene TOML file with a [requirements] table")
      ->required()
      ->check(input_file());
  c.plan->add_option("--tradeoff", c.plan_tradeoff,
                     "tradeoff directory (default runs/tradeoff-<scene stem>)");  // run_plan says what to run
  c.plan->add_option(
      "--params", c.plan_params,
      "parameter file of the continuum models (default: the set iwb validate chooses from those "
      "built into iwb: dem_default_grains.toml for the default scene's grains, else phi_c closest "
      "to the reference's residual friction)")
      ->check(input_file());
  c.plan->add_option("--out,-o", c.plan_out,
                     "where plan.json goes (default: the tradeoff directory)")
      ->check(output_directory());
}

int run_tradeoff_command(const TradeoffCommands& c, const std::string& cl,
                         const std::atomic<bool>* interrupt) {
  tradeoff::TradeoffOptions opt;
  opt.scene_file = c.scene;
  opt.out = c.out.empty() ? tradeoff::default_out(c.scene) : fs::path(c.out);
  opt.knobs = tradeoff::parse_knob_list(c.knobs);
  opt.reference = tradeoff::parse_reference(c.reference);
  opt.seeds = c.seeds, opt.jobs = c.jobs, opt.processes = c.np, opt.stop_after = c.stop_after;
  opt.command_line = cl;
  opt.interrupt = interrupt;
  opt.progress = [](const std::string& line) { fmt::print(stderr, "  {}\n", line); };
  fmt::print(stderr, "iwb tradeoff: {} ({} variants, {} at once) -> {}\n", c.scene,
             tradeoff::expand_variants(opt).size(), c.jobs, opt.out.string());
  const auto result = tradeoff::run_tradeoff(opt);
  fmt::print("{}\n-> {}\n", io::read_file(opt.out / "tradeoff.md"),
             (opt.out / "tradeoff.md").string());
  return result["status"] == "complete" ? 0 : 1;
}

// --params, else the set `iwb validate` would choose for the tradeoff's reference run from the
// sets built into iwb (app/parameter_choice.hpp).
io::ParameterSet plan_parameters(const tradeoff::PlanOptions& opt, const std::string& params, std::string& why) {
  if (!params.empty()) {
    why = "given with --params";
    return io::read_parameter_set(params);
  }
  const auto summary =
      io::read_json_file(tradeoff::reference_run(opt) / "summary.json");
  const auto scene = dem::parse_scene(io::read_file(opt.scene_file), opt.scene_file.string());
  const auto sets = io::parameter_sets({});
  return parameters_for(sets, scene, summary["residual_friction"].get<double>(), why);
}

int run_plan_command(const TradeoffCommands& c, const std::string& cl) {
  dem::load_scene(c.plan_scene);  // every value checked before the tradeoff is read
  tradeoff::PlanOptions opt{c.plan_scene, c.plan_tradeoff, {}, "", c.plan_out, cl};
  opt.params = plan_parameters(opt, c.plan_params, opt.params_why);
  const auto plan = tradeoff::run_plan(opt);
  const fs::path written =
      opt.out.empty() ? fs::path(plan["tradeoff"].get<std::string>()).parent_path() : opt.out;
  fmt::print("{}parameters: {} ({})\n-> {}\n", tradeoff::plan_text(plan), opt.params.origin,
             opt.params_why, (written / "plan.json").string());
  return 0;
}

}  // namespace

std::shared_ptr<TradeoffCommands> add_tradeoff_commands(CLI::App& app) {
  auto c = std::make_shared<TradeoffCommands>();
  add_tradeoff(app, *c);
  add_plan(app, *c);
  return c;
}

std::optional<int> run_tradeoff_commands(const TradeoffCommands& c, const std::string& cl,
                                         const std::atomic<bool>* interrupt) {
  if (*c.tradeoff) return run_tradeoff_command(c, cl, interrupt);
  if (*c.plan) return run_plan_command(c, cl);
  return std::nullopt;
}

}  // namespace iwb::app
