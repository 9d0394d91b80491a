// `iwb pile PILE.toml`: load transfer along a pile shaft whose t-z springs are interface stress
// points through the C interface (src/pile/README.md).
#include <fmt/core.h>

#include <filesystem>
#include <memory>

#include "app/command_list.hpp"
#include "app/commands/commands.hpp"
#include "app/option_checks.hpp"
#include "app/progress.hpp"
#include "io/run_directory.hpp"
#include "pile/pile_run.hpp"

namespace iwb::app {

namespace {

struct PileOptions {
  std::string file, out;
  bool force = false;
};

int run_pile_command(const PileOptions& o, const CommandContext& context) {
  const auto spec = pile::load_pile_spec(o.file);
  const auto dir = o.out.empty()
                       ? std::filesystem::path("runs") / std::filesystem::path(o.file).stem()
                       : std::filesystem::path(o.out);
  pile::PileRunOptions opt{dir,
                           o.force,
                           context.command_line,
                           io::read_file(o.file),
                           context.interrupt,
                           increment_progress()};
  const int code = pile::run_pile(spec, opt);
  fmt::print(code == 0 ? stdout : stderr, "{}: {} -> {}\n", o.file,
             code == 0 ? "complete" : "failed (manifest.json says why)", dir.string());
  return code;
}

}  // namespace

void add_pile_command(CLI::App& app, CommandList& commands) {
  auto o = std::make_shared<PileOptions>();
  auto* pile =
      app.add_subcommand("pile",
                         "Load transfer along a pile shaft (t-z analysis after Randolph's RATZ): a "
                         "1D finite-element pile (EA, length, "
                         "diameter) whose elements each carry one interface stress point of any "
                         "model through the C interface, under "
                         "constant normal stiffness K = 4G/D (Boulon & Foray) from sigma_n0 = K0 "
                         "gamma' z; a linear base spring; the head "
                         "pushed to a settlement or loaded cyclically. Writes load_settlement.csv, "
                         "profiles.csv (friction, normal stress, "
                         "axial force along the shaft at the chosen loads), mesh_convergence.csv "
                         "(half and twice the elements), "
                         "summary.json and figures/ (schema: data/piles/README.md).\n\nExample: "
                         "iwb pile data/piles/example.toml");
  pile->add_option("file", o->file, "pile TOML file (data/piles/README.md)")
      ->required()
      ->check(input_file());
  pile->add_option("--out,-o", o->out, "run directory (default runs/<file stem>)")
      ->check(output_directory());
  pile->add_flag("--force", o->force, "replace an earlier run in the same directory");
  commands.add(pile, [o](const CommandContext& c) { return run_pile_command(*o, c); });
}

}  // namespace iwb::app
