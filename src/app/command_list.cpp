#include "app/command_list.hpp"

namespace iwb::app {

void CommandList::add(CLI::App* command, CommandRun run) {
  commands_.emplace_back(command, std::move(run));
}

std::optional<int> CommandList::run_parsed(const CommandContext& context) const {
  for (const auto& [command, run] : commands_)
    if (command->parsed()) return run(context);
  return std::nullopt;
}

}  // namespace iwb::app
