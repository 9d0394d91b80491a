// `iwb claims`: a campaign's declared claims tested in one analysis (claims/claims.hpp), and the
// README's answers generated from it.
#include "claims/claims.hpp"

#include <fmt/core.h>

#include <memory>

#include "app/command_list.hpp"
#include "app/commands/commands.hpp"
#include "app/option_checks.hpp"
#include "claims/seed_plan.hpp"
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
    "current (exit 1 if not). With --plan-seeds DIR and --budget-core-hours H it plans the runs "
    "that would resolve the claims left undecided (issue 59, \"evidence where it decides\"): per "
    "group of runs, the seeds its claims need at the measured effect and scatter, more where some "
    "of its runs were left out (split, at the plate, not steady), each priced at the group's mean "
    "engine core-hours; claims cheapest first within the budget; writes plan.md, plan.json and "
    "an `iwb sweep` file per group to DIR.\n"
    "Example: iwb claims data/cyclic/claims.toml -o runs/claims-cyclic --readme "
    "data/cyclic/README.md\n"
    "Example: iwb claims data/cyclic/claims.toml --plan-seeds runs/seeds-cyclic "
    "--budget-core-hours 10";

struct ClaimsCommand {
  std::string file, out, readme, check_readme, plan_seeds;
  double budget_core_hours = 0.0;
  bool force = false;
};

const io::OutputKind kClaimsOutput{"claims"};
const io::OutputKind kSeedPlanOutput{"seed-plan", "plan.json"};

int run_seed_plan(const ClaimsCommand& c, const claims::ClaimsReport& report,
                  const CommandContext& context) {
  const auto plan = claims::plan_seeds(report, c.budget_core_hours);
  io::prepare_run_directory(c.plan_seeds, kSeedPlanOutput, c.force);
  claims::write_seed_plan(plan, c.plan_seeds);
  std::vector<std::string> files = {"plan.json", "plan.md"};
  for (const auto& g : plan.groups)
    if (!g.soil_cells)
      files.push_back("scenes/" + g.name + ".toml"), files.push_back("sweeps/" + g.name + ".toml");
  io::write_manifest(c.plan_seeds, {{"kind", "seed-plan"},
                                    {"command_line", context.command_line},
                                    {"finished", io::utc_timestamp()},
                                    {"status", "complete"},
                                    {"files", files}});
  fmt::print("{}", claims::markdown(plan));
  return 0;
}

int run_claims(const ClaimsCommand& c, const CommandContext& context) {
  const auto file = claims::read_claims(c.file);
  const auto report = claims::test_claims(file);  // every run read before anything is written
  if (!c.plan_seeds.empty()) return run_seed_plan(c, report, context);
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
  auto* plan = cmd->add_option("--plan-seeds", c->plan_seeds,
                               "directory for the plan of seeds that would resolve the undecided "
                               "claims (plan.md, plan.json, sweeps/, scenes/)")
                   ->check(output_directory());
  auto* budget = cmd->add_option("--budget-core-hours", c->budget_core_hours,
                                 "engine core-hours the planned runs may cost, in all")
                     ->check(number_in(positive(1e6), "core-hours"));
  plan->needs(budget);
  budget->needs(plan);
  cmd->add_flag("--force", c->force, "replace an earlier output in the same directory");
  check->excludes(out)->excludes(readme)->excludes(plan);
  plan->excludes(out)->excludes(readme);
  commands.add(cmd, [c](const CommandContext& context) {
    if (c->check_readme.empty() && c->out.empty() && c->plan_seeds.empty())
      throw InputError("iwb claims: --out is required (or --check-readme or --plan-seeds alone)");
    return run_claims(*c, context);
  });
}

}  // namespace iwb::app
