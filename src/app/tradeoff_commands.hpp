#pragma once
// `iwb tradeoff` and `iwb plan` (issue 7, items 4 and 5): set up on the CLI11 app, run after
// parsing (src/tradeoff/).
#include <CLI/CLI.hpp>
#include <atomic>
#include <memory>
#include <optional>
#include <string>

namespace iwb::app {

struct TradeoffCommands;

// Adds the subcommands to `app`; the returned object holds their options (keep it alive).
std::shared_ptr<TradeoffCommands> add_tradeoff_commands(CLI::App& app);

// Runs whichever of them was given; nullopt if none was. Exit code otherwise.
std::optional<int> run_tradeoff_commands(const TradeoffCommands& c, const std::string& command_line,
                                         const std::atomic<bool>* interrupt);

}  // namespace iwb::app
