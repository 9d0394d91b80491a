#include "app/exit_codes.hpp"

#include <fmt/core.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "common/errors.hpp"

namespace iwb::app {

namespace {

// The deepest subcommand the parser had reached ("dem run" in `iwb dem run ...`), and its path.
const CLI::App& reached(const CLI::App& app, std::string& path) {
  path = "iwb";
  const CLI::App* sub = &app;
  while (!sub->get_subcommands().empty()) {
    sub = sub->get_subcommands().front();
    path += " " + sub->get_name();
  }
  return *sub;
}

// What was wrong with the command line. CLI11 reports `iwb` and `iwb bogus` alike as "A subcommand
// is required"; say instead which word is not a command, and what the commands are.
std::string parse_error_message(const CLI::App& sub, const CLI::ParseError& e) {
  // Option groups are unnamed subcommands in CLI11: not commands.
  const auto commands =
      sub.get_subcommands([](const CLI::App* c) { return !c->get_name().empty(); });
  if (e.get_name() != "RequiredError" || sub.get_require_subcommand_min() == 0) return e.what();
  std::string known;
  for (const auto* c : commands) known += (known.empty() ? "" : ", ") + c->get_name();
  const auto extra = sub.remaining();
  if (extra.empty()) return fmt::format("give a command: {}", known);
  return fmt::format("unknown command '{}'; the commands are {}", extra.front(), known);
}

}  // namespace

// CLI11 ends a bad command line with its own codes (105 validator, 106 required, 109 extras, ...);
// the README promises 2 for every bad input, so all parse errors but --help map to 2.
int parse_error_exit(const CLI::App& app, const CLI::ParseError& e) {
  if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return app.exit(e);
  std::string path;
  const auto& sub = reached(app, path);
  fmt::print(stderr, "error: {}: {}\nRun `{} --help` for the options.\n", path,
             parse_error_message(sub, e), path);
  return 2;
}

int exit_for(const std::exception_ptr& error) {
  const auto fail = [](const std::string& message, int code) {
    fmt::print(stderr, "error: {}\n", message);
    return code;
  };
  try {
    std::rethrow_exception(error);
  } catch (const iwb::InputError& e) {
    return fail(e.what(), 2);
  } catch (const std::filesystem::filesystem_error& e) {
    // A path given to the command (--out under a file, an unreadable directory); what() names it.
    return fail(e.what(), 2);
  } catch (const nlohmann::json::parse_error& e) {
    // Every JSON file iwb parses is in a run or comparison directory given to the command.
    return fail(fmt::format("a JSON file in the given directories is not JSON: {}", e.what()), 2);
  } catch (const std::exception& e) {
    return fail(e.what(), 1);
  } catch (...) {
    return fail("unknown exception", 1);
  }
}

}  // namespace iwb::app
