// The list of `iwb` commands, in the order `iwb --help` shows them. Groups (`dem`, `bench`,
// `soiltest`) are created here; every command's options and run live in its own file.
#include "app/command_list.hpp"
#include "app/commands/commands.hpp"

namespace iwb::app {

namespace {
CLI::App& add_group(CLI::App& app, const std::string& name, const std::string& description) {
  auto* group = app.add_subcommand(name, description);
  group->require_subcommand(1);
  return *group;
}
}  // namespace

void add_all_commands(CLI::App& app, CommandList& commands) {
  add_element_command(app, commands);
  add_models_command(app, commands);
  add_run_command(app, commands);
  auto& dem =
      add_group(app, "dem", "DEM interface-shear scenes (scene schema: data/scenes/README.md).");
  add_dem_run_command(dem, commands);
  add_dem_soiltest_command(dem, commands);
  add_dem_crosscheck_command(dem, commands);
  add_dem_summary_command(dem, commands);
  add_dem_fields_command(dem, commands);
  add_dem_keys_command(dem, commands);
  add_dem_roughness_command(dem, commands);
  add_compare_command(app, commands);
  add_sweep_command(app, commands);
  add_report_command(app, commands);
  add_validate_command(app, commands);
  add_stability_command(app, commands);
  add_assess_command(app, commands);
  auto& bench = add_group(app, "bench", "Benchmarks that print figures.");
  add_bench_element_command(bench, commands);
  add_bench_integrators_command(bench, commands);
  add_bench_assess_command(bench, commands);
  add_bench_dem_command(bench, commands);
  add_bench_calibration_command(bench, commands);
  auto& soiltest = add_group(
      app, "soiltest", "Soil element tests in the soil-test contract (src/calibration/README.md).");
  add_soiltest_synthetic_command(soiltest, commands);
  add_calibrate_command(app, commands);
  add_form_limit_command(app, commands);
  add_claims_command(app, commands);
  add_tradeoff_command(app, commands);
  add_plan_command(app, commands);
  add_pile_command(app, commands);
  add_column_command(app, commands);
}

}  // namespace iwb::app
