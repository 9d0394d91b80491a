#pragma once
// How a command line that could not be parsed, or a command that threw, ends: the message on
// stderr and the README's exit code (2 bad input, 1 a failed run).
#include <CLI/CLI.hpp>
#include <exception>

namespace iwb::app {

// --help exits 0 through CLI11; every other parse error says which command and why, exit 2.
int parse_error_exit(const CLI::App& app, const CLI::ParseError& e);

// 2 for bad input (InputError, a path, a JSON file that is not JSON), 1 for anything else.
int exit_for(const std::exception_ptr& error);

}  // namespace iwb::app
