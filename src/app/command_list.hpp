#pragma once
// The `iwb` commands as a list: each command adds its subcommand and options to a parent (in its
// own file under commands/) and registers what runs when that subcommand is given. main() only
// parses and runs the one that was parsed, so adding a command touches its file and one line of
// commands/all.cpp.
#include <CLI/CLI.hpp>
#include <atomic>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace iwb::app {

// What every command may need beyond its own options.
struct CommandContext {
  std::string command_line;                      // as typed, for the manifests
  const std::atomic<bool>* interrupt = nullptr;  // set by SIGINT or SIGTERM: stop cleanly
};

// Exit code: 0 done, 1 the run failed or was interrupted, 2 bad input (README).
using CommandRun = std::function<int(const CommandContext&)>;

class CommandList {
 public:
  // `run` is what happens when `command` (a leaf subcommand) is given on the command line.
  void add(CLI::App* command, CommandRun run);
  // The exit code of the command that was parsed; nullopt when none of the list was.
  std::optional<int> run_parsed(const CommandContext& context) const;

 private:
  std::vector<std::pair<CLI::App*, CommandRun>> commands_;
};

// Adds every command of `iwb` to `app`, in the order `iwb --help` lists them (commands/all.cpp).
void add_all_commands(CLI::App& app, CommandList& commands);

}  // namespace iwb::app
