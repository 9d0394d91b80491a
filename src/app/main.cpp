// iwb, the interface workbench: command line. Thin: parses, validates, calls the library.
// Every command lives in its own file under commands/ (the list: commands/all.cpp).
// Exit codes: 0 done, 1 the run failed or was interrupted (its manifest says why), 2 bad input.
#include <CLI/CLI.hpp>
#include <atomic>
#include <csignal>
#include <string>

#include "app/command_list.hpp"
#include "app/exit_codes.hpp"
#include "io/output_directory.hpp"
#include "models/external/external_model.hpp"

namespace {

std::atomic<bool> g_interrupt{false};
void on_signal(int) {
  g_interrupt.store(true);
}

std::string joined(int argc, char** argv) {
  std::string s;
  for (int i = 0; i < argc; ++i) s += (i ? " " : "") + std::string(argv[i]);
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "iwb, the interface workbench: DEM interface-shear scenes (LIGGGHTS, YADE) and continuum\n"
      "hypoplastic interface models run side by side on the same path.\n\n"
      "Examples:\n"
      "  iwb models                                  list models, parameters, units, bounds\n"
      "  iwb element data/tests/hvwe_cnl_dense.toml  run one element test into runs/<name>/\n"
      "  iwb run --study clay                        the seed's clay interface comparisons (6.4)\n"
      "  iwb run --study chapter8                    HCE, Barodesy, modified Cam clay under CV "
      "(seed 8.4)\n"
      "  iwb dem run data/scenes/smoke.toml          a DEM interface-shear scene in LIGGGHTS\n"
      "  iwb sweep data/sweeps/example.toml -j 2     a campaign of scenes (R_n x d50 x CNL/CNS/CV "
      "x seed)\n"
      "  iwb tradeoff data/scenes/default.toml -j 2  DEM speed against accuracy, knob by knob\n"
      "  iwb bench element                           cost of the continuum core\n"
      "  iwb stability hvwe data/params/table_5_1_evaluation.toml   where a model runs and where "
      "it stops\n"};
  app.require_subcommand(1);
  // A user's own model (src/models/external/README.md): before the command, anywhere on the line.
  std::string model_lib, model_entry;
  auto* lib =
      app.add_option("--model-lib", model_lib,
                     "a user's interface model: a shared library with a UMAT-style entry point "
                     "(src/models/external/README.md), usable as --model NAME or [model] name = "
                     "NAME by every "
                     "command")
          ->check(CLI::ExistingFile);
  app.add_option("--entry", model_entry,
                 "the entry point in --model-lib, which is also the model's name")
      ->needs(lib);
  lib->needs(app.get_option("--entry"));
  app.fallthrough();  // the two may follow the command's own arguments
  iwb::app::CommandList commands;
  iwb::app::add_all_commands(app, commands);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return iwb::app::parse_error_exit(app, e);
  }
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  int code = 0;
  try {
    if (!model_lib.empty())
      iwb::models::add_runtime_model(iwb::models::external_model_spec(model_lib, model_entry));
    code = commands.run_parsed({joined(argc, argv), &g_interrupt}).value_or(0);
  } catch (...) {
    code = iwb::app::exit_for(std::current_exception());
  }
  // whatever the command wrote, finished or not, is entered in its directories' ledgers, so that
  // a later --force removes it (io/output_directory.hpp)
  iwb::io::release_claimed_directories();
  return code;
}
