// `iwb tradeoff SCENE`: DEM speed against accuracy, knob by knob (tradeoff/tradeoff.hpp).
#include "tradeoff/tradeoff.hpp"

#include <fmt/core.h>

#include <memory>

#include "app/command_list.hpp"
#include "app/commands/commands.hpp"
#include "app/option_checks.hpp"
#include "app/progress.hpp"
#include "io/run_directory.hpp"
#include "tradeoff/knobs.hpp"

namespace iwb::app {

namespace fs = std::filesystem;

namespace {

struct TradeoffCommand {
  std::string scene, out, knobs = "box,kappa,dt,I", reference = "refined";
  int jobs = 1, np = 1, seeds = 3, stop_after = 0;
};

CLI::App* add_tradeoff_options(CLI::App& app, TradeoffCommand& c) {
  auto* tradeoff = app.add_subcommand(
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
  tradeoff->add_option("scene", c.scene, "scene TOML file (data/scenes/)")
      ->required()
      ->check(input_file());
  tradeoff->add_option("--out,-o", c.out, "tradeoff directory (default runs/tradeoff-<scene stem>)")
      ->check(output_directory());
  tradeoff->add_option("--jobs,-j", c.jobs, "runs at once (jobs x np should not exceed the cores)")
      ->check(whole_in(1, kMaxProcesses))
      ->capture_default_str();
  tradeoff->add_option("--np", c.np, "MPI ranks per run")
      ->check(whole_in(1, kMaxProcesses))
      ->capture_default_str();
  tradeoff
      ->add_option("--seeds", c.seeds,
                   "seeds of the base setting (>= 2; 3 or more for a usable noise floor)")
      ->check(whole_in(2, 100))
      ->capture_default_str();
  tradeoff->add_option("--knobs", c.knobs, "comma-separated knobs to vary: box, kappa, dt, I")
      ->capture_default_str();
  tradeoff
      ->add_option(
          "--reference", c.reference,
          "what the errors are measured against: refined (every knob refined at once, one "
          "seed) or base (the scene itself, mean of its seeds: for a scene a convergence "
          "study showed converged, e.g. data/scenes/truth.toml; then only cheaper settings run)")
      ->check(CLI::IsMember({"refined", "base"}))
      ->capture_default_str();
  tradeoff
      ->add_option("--stop-after", c.stop_after,
                   "stop cleanly once N runs have ended; run again to continue")
      ->check(whole_in(1, 1000000));
  return tradeoff;
}

int run_tradeoff_command(const TradeoffCommand& c, const std::string& cl,
                         const std::atomic<bool>* interrupt) {
  tradeoff::TradeoffOptions opt;
  opt.scene_file = c.scene;
  opt.out = c.out.empty() ? tradeoff::default_out(c.scene) : fs::path(c.out);
  opt.knobs = tradeoff::parse_knob_list(c.knobs);
  opt.reference = tradeoff::parse_reference(c.reference);
  opt.seeds = c.seeds, opt.jobs = c.jobs, opt.processes = c.np, opt.stop_after = c.stop_after;
  opt.command_line = cl;
  opt.interrupt = interrupt;
  opt.progress = print_progress_line;
  fmt::print(stderr, "iwb tradeoff: {} ({} variants, {} at once) -> {}\n", c.scene,
             tradeoff::expand_variants(opt).size(), c.jobs, opt.out.string());
  const auto result = tradeoff::run_tradeoff(opt);
  fmt::print("{}\n-> {}\n", io::read_file(opt.out / "tradeoff.md"),
             (opt.out / "tradeoff.md").string());
  return result["status"] == "complete" ? 0 : 1;
}

}  // namespace

void add_tradeoff_command(CLI::App& app, CommandList& commands) {
  auto c = std::make_shared<TradeoffCommand>();
  auto* tradeoff = add_tradeoff_options(app, *c);
  commands.add(tradeoff, [c](const CommandContext& context) {
    return run_tradeoff_command(*c, context.command_line, context.interrupt);
  });
}

}  // namespace iwb::app
