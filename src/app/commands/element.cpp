// `iwb element TEST.toml`: one element test into a run directory (element/element_run.hpp).
#include <fmt/core.h>

#include <filesystem>
#include <memory>

#include "app/command_list.hpp"
#include "app/commands/commands.hpp"
#include "app/option_checks.hpp"
#include "app/progress.hpp"
#include "element/element_run.hpp"
#include "element/element_test_file.hpp"
#include "io/run_directory.hpp"

namespace iwb::app {

namespace {

struct ElementOptions {
  std::string test_file, out;
  bool force = false;
};

int run_element(const ElementOptions& o, const CommandContext& context) {
  auto spec = element::load_element_test(o.test_file);
  for (const auto& w : spec.warnings) fmt::print(stderr, "warning: {}\n", w);
  const auto dir = o.out.empty()
                       ? std::filesystem::path("runs") / std::filesystem::path(o.test_file).stem()
                       : std::filesystem::path(o.out);
  element::ElementRunOptions opt{dir, o.force, context.command_line, io::read_file(o.test_file),
                                 context.interrupt};
  spec.settings.on_increment = increment_progress();
  const auto outcome = element::run_element_to_directory(spec, opt);
  const auto& r = outcome.result;
  // A failed or interrupted run is an error message: on stderr, with exit 1 (README).
  fmt::print(r.complete() ? stdout : stderr,
             "{}: {} ({} increments, {} rate evaluations, {} rejected substeps) -> {}\n",
             o.test_file, r.status, r.increments, r.counters.rate_evaluations,
             r.counters.rejected_substeps, dir.string());
  return r.complete() ? 0 : 1;
}

}  // namespace

void add_element_command(CLI::App& app, CommandList& commands) {
  auto o = std::make_shared<ElementOptions>();
  auto* element = app.add_subcommand(
      "element",
      "Run an element test described in a TOML file (schema: data/tests/README.md) and write a "
      "run directory with manifest.json and history.csv (compression positive, kPa, mm).");
  element->add_option("test", o->test_file, "element-test TOML file")
      ->required()
      ->check(input_file());
  element->add_option("--out,-o", o->out, "run directory (default runs/<test file stem>)")
      ->check(output_directory());
  element->add_flag("--force", o->force, "replace an earlier run in the same directory");
  commands.add(element, [o](const CommandContext& c) { return run_element(*o, c); });
}

}  // namespace iwb::app
