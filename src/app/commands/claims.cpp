// `iwb claims`: a campaign's declared claims tested in one analysis (claims/claims.hpp), and the
// README's answers generated from it.
#include "claims/claims.hpp"

#include <fmt/core.h>

#include <memory>

#include "app/command_list.hpp"
#include "app/commands/commands.hpp"
#include "app/option_checks.hpp"
#include "common/errors.hpp"
#include "io/run_directory.hpp"

namespace iwb::app {

namespace {

constexpr const char* kClaimsHelp =
    "Tests a campaign's declared claims (issue 59): each [[claim]] of the claims file names two "
    "groups of DEM runs, a quantity of their summary.json (a JSON pointer, optionally relative to "
    "another), the direction it asserts and what to do with runs split between wall and plate or "
    "at the plate. Each is tested by Welch's t-test (one run against a group: its 95 % prediction "
    "interval), the file's claims together by Benjamini-Hochberg at its q; a claim is supported, "
    "contradicted, not resolved (with the seeds per group its effect would need) or not testable. "
    "Writes claims.json and claims.md to -o. With --readme FILE the table replaces FILE's block "
    "between '<!-- BEGIN claims: NAME -->' and '<!-- END claims -->' (NAME the claims file's name; "
    "nothing else of FILE is touched); with --check-readme FILE it only says whether that block is "
    "current (exit 1 if not).\n"
    "Example: iwb claims data/cyclic/claims.toml -o runs/claims-cyclic --readme "
    "data/cyclic/README.md";

struct ClaimsCommand {
  std::string file, out, readme, check_readme;
  bool force = false;
};

const io::OutputKind kClaimsOutput{"claims"};

int run_claims(const ClaimsCommand& c, const CommandContext& context) {
  const auto file = claims::read_claims(c.file);
  const auto report = claims::test_claims(file);  // every run read before anything is written
  const std::string table = claims::markdown(report);
  const std::string name = std::filesystem::path(c.file).filename().string();
  if (!c.check_readme.empty()) {
    const auto wanted = claims::readme_with_block(c.check_readme, name, table);
    if (wanted != io::read_file(c.check_readme)) {
      fmt::print(stderr,
                 "{}: the claims block is not what `iwb claims {}` gives now; rerun it with "
                 "--readme {}\n",
                 c.check_readme, c.file, c.check_readme);
      return 1;
    }
    fmt::print("{}: the claims block is current\n", c.check_readme);
    return 0;
  }
  const auto readme =
      c.readme.empty() ? std::string() : claims::readme_with_block(c.readme, name, table);
  io::prepare_run_directory(c.out, kClaimsOutput, c.force);
  auto j = claims::to_json(report);
  j["command_line"] = context.command_line;
  io::write_atomically(std::filesystem::path(c.out) / "claims.json", j.dump(2) + "\n");
  io::write_atomically(std::filesystem::path(c.out) / "claims.md", table);
  io::write_manifest(c.out, {{"kind", "claims"},
                             {"command_line", context.command_line},
                             {"finished", io::utc_timestamp()},
                             {"status", "complete"},
                             {"files", {"claims.json", "claims.md"}}});
  if (!readme.empty()) io::write_atomically(c.readme, readme);
  fmt::print("{}", table);
  return 0;
}

}  // namespace

void add_claims_command(CLI::App& app, CommandList& commands) {
  auto c = std::make_shared<ClaimsCommand>();
  auto* cmd = app.add_subcommand("claims", kClaimsHelp);
  cmd->add_option("file", c->file, "the claims file (data/<campaign>/claims.toml)")
      ->required()
      ->check(input_file());
  auto* out = cmd->add_option("--out,-o", c->out, "output directory")->check(output_directory());
  auto* readme = cmd->add_option("--readme", c->readme, "README whose claims block to replace")
                     ->check(input_file());
  auto* check = cmd->add_option("--check-readme", c->check_readme,
                                "README whose claims block to check (writes nothing)")
                    ->check(input_file());
  cmd->add_flag("--force", c->force, "replace an earlier claims output in the same directory");
  check->excludes(out)->excludes(readme);
  commands.add(cmd, [c](const CommandContext& context) {
    if (c->check_readme.empty() && c->out.empty())
      throw InputError("iwb claims: --out is required (or --check-readme alone)");
    return run_claims(*c, context);
  });
}

}  // namespace iwb::app
