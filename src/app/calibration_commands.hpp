#pragma once
// `iwb soiltest synthetic` and `iwb calibrate`: set up on the CLI11 app, run after parsing.
#include <CLI/CLI.hpp>
#include <memory>
#include <optional>
#include <string>

namespace iwb::app {

struct CalibrationCommands;

// Adds the subcommands to `app`; the returned object holds their options (keep it alive).
std::shared_ptr<CalibrationCommands> add_calibration_commands(CLI::App& app);

// Runs whichever of them was given; nullopt if none was. Exit code otherwise.
std::optional<int> run_calibration_commands(const CalibrationCommands& c,
                                            const std::string& command_line);

}  // namespace iwb::app
