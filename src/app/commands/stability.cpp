// `iwb stability MODEL PARAMS`: where a model runs and where it stops (analysis/stability_map.hpp).
#include <fmt/core.h>

#include <memory>

#include "analysis/stability_map.hpp"
#include "analysis/stability_output.hpp"
#include "app/command_list.hpp"
#include "app/commands/commands.hpp"
#include "app/option_checks.hpp"

namespace iwb::app {

namespace {
// What is swept on stderr as it starts; the points per outcome and where the map is on stdout.
int run_stability_command(analysis::StabilityMapOptions opt) {
  opt.starting = [](const std::string& line) { fmt::print(stderr, "iwb stability: {}\n", line); };
  const auto map = analysis::run_stability_map(opt);
  for (const auto& [o, n] : analysis::count_outcomes(map.results))
    fmt::print("{:<20} {}\n", analysis::to_string(o), n);
  fmt::print("{} points in {:.1f} s -> {}\n", map.results.size(), map.seconds,
             (map.dir / "stability.md").string());
  return 0;
}
}  // namespace

void add_stability_command(CLI::App& app, CommandList& commands) {
  auto o = std::make_shared<analysis::StabilityMapOptions>();
  auto* stability = app.add_subcommand(
      "stability",
      "Stability map of a model: sweeps sigma_n0 (1 kPa to 10 MPa), e0 (just above e_d to just "
      "below e_i at "
      "sigma_n0; for clay models the overconsolidation ratio, 1 to 10), kappa_r (0.05 to 1), shear "
      "strain per increment (1e-6 to 1e-2) and cyclic runs, under CNL, "
      "CNS and CV, and writes stability.csv (one row per point: outcome, reason, message, counts "
      "of rejected "
      "substeps), stability.md (counts per outcome, why points stopped) and "
      "stability_<BC>.svg/.png (sigma_n0 x "
      "density index or OCR, coloured by the worst outcome). Outcomes: complete, domain error, no "
      "convergence, budget "
      "exceeded, inadmissible start, non-finite value, other error. The reduced form takes "
      "seconds, --full "
      "(1000-cycle runs) minutes.\n\nExample: iwb stability hvwe "
      "data/params/table_5_1_evaluation.toml --full");
  stability->add_option("model", o->model, "model name (iwb models)")->required();
  stability
      ->add_option("params", o->params,
                   "parameter file, e.g. data/params/table_5_1_evaluation.toml; "
                   "-igs models need an [intergranular_strain] table (table_5_3_*)")
      ->required()
      ->check(input_file());
  stability->add_flag("--full", o->full,
                      "the full sweep (5 values per axis, 1000 cycles) instead of the reduced one");
  stability->add_option("--out,-o", o->out, "output directory (default runs/stability-<model>)")
      ->check(output_directory());
  stability
      ->add_option("--budget", o->budget_seconds,
                   "wall-clock seconds per point before it is stopped as "
                   "'budget exceeded' (default 5 reduced, 10 full)")
      ->check(number_in(positive(kMaxBudgetSeconds), "s"));
  commands.add(stability, [o](const CommandContext&) { return run_stability_command(*o); });
}

}  // namespace iwb::app
