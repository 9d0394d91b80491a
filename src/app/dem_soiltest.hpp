#pragma once
// `iwb dem soiltest`: set up on the `dem` subcommand, run after parsing (src/dem/soil_cell.hpp).
#include <CLI/CLI.hpp>
#include <atomic>
#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace iwb::app {

struct DemSoiltestCommand;

// Adds `soiltest` to `dem`; the returned object holds its options (keep it alive).
std::shared_ptr<DemSoiltestCommand> add_dem_soiltest(CLI::App& dem);

// Runs it if it was given (nullopt otherwise); exit code 0 complete, 1 failed or interrupted.
std::optional<int> run_dem_soiltest(const DemSoiltestCommand& c, const std::string& command_line,
                                    const std::atomic<bool>* interrupt,
                                    std::function<void(const std::string&)> progress);

}  // namespace iwb::app
