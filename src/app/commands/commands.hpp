#pragma once
// Every `iwb` command, one file each in this folder: each adds its subcommand and options to a
// parent and registers what runs when it is given (app/command_list.hpp). all.cpp lists them in
// the order `iwb --help` shows.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "app/command_list.hpp"

namespace iwb::app {

// The plan's and the league's ladder for their help. Written here, not asked of the registry at
// start-up: building the registry cost every `iwb` command 2.6 million instructions (7 % of
// `iwb --help`); a test holds it to models::ranked_interface_models_text().
inline constexpr const char* kInterfaceModelLadder =
    "mc, hyperbolic, hp1d, ah, ahe, lashkari, mortara, hvwe, hvwe-rd, hvwe-pg; ahe-igs and "
    "hvwe-igs for reversing paths";

void add_element_command(CLI::App& app, CommandList& commands);
void add_models_command(CLI::App& app, CommandList& commands);
void add_run_command(CLI::App& app, CommandList& commands);
void add_dem_run_command(CLI::App& dem, CommandList& commands);
void add_dem_soiltest_command(CLI::App& dem, CommandList& commands);
void add_dem_crosscheck_command(CLI::App& dem, CommandList& commands);
void add_dem_summary_command(CLI::App& dem, CommandList& commands);
void add_dem_keys_command(CLI::App& dem, CommandList& commands);
void add_dem_roughness_command(CLI::App& dem, CommandList& commands);
void add_dem_fields_command(CLI::App& dem, CommandList& commands);
void add_compare_command(CLI::App& app, CommandList& commands);
void add_form_limit_command(CLI::App& app, CommandList& commands);
void add_claims_command(CLI::App& app, CommandList& commands);
void add_sweep_command(CLI::App& app, CommandList& commands);
void add_report_command(CLI::App& app, CommandList& commands);
void add_validate_command(CLI::App& app, CommandList& commands);
void add_stability_command(CLI::App& app, CommandList& commands);
void add_assess_command(CLI::App& app, CommandList& commands);
void add_bench_element_command(CLI::App& bench, CommandList& commands);
void add_bench_integrators_command(CLI::App& bench, CommandList& commands);
void add_bench_calibration_command(CLI::App& bench, CommandList& commands);
void add_bench_assess_command(CLI::App& bench, CommandList& commands);
void add_bench_dem_command(CLI::App& bench, CommandList& commands);
void add_soiltest_synthetic_command(CLI::App& soiltest, CommandList& commands);
void add_calibrate_command(CLI::App& app, CommandList& commands);
void add_tradeoff_command(CLI::App& app, CommandList& commands);
void add_plan_command(CLI::App& app, CommandList& commands);
void add_pile_command(CLI::App& app, CommandList& commands);
void add_column_command(CLI::App& app, CommandList& commands);

// The hypothesis verdicts of a set of comparisons (`compare --runs`, `sweep`), title and verdict.
void print_hypothesis_checks(const nlohmann::json& hypotheses);

// A soil test's --amplitude and --cycles (dem soiltest, soiltest synthetic) with a --test other
// than cyclicshear, which would ignore them: InputError naming the option and its value.
void refuse_cyclic_options(const CLI::App& soiltest, const std::string& test);

}  // namespace iwb::app
