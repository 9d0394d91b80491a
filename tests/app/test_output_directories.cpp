// Issue 60: `iwb element T.toml --out DIR --force` removed the whole directory, the user's
// thesis.txt included. Each command that writes a run directory is run here as a user would: into
// DIR, then the user puts a file there, then the command again with --force (or again, where a
// command replaces its own output without it): the user's file is there, unchanged, and the
// command's own output is complete. (The refusals of a directory the workbench did not write, for
// every command, are the bad-input corpus's outputs.cases.)
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "io/output_directory.hpp"
#include "support/cli.hpp"

using namespace iwb;
namespace fs = std::filesystem;

namespace {

struct Case {
  std::vector<std::string> args;  // before "--out DIR"
  bool has_force;
  std::string a_file_it_writes;
};

}  // namespace

TEST_CASE("every command's --force keeps a file of the user's beside its run", "[app][io]") {
  const std::vector<Case> cases = {
      {{"element", "data/tests/hvwe_cnl_dense.toml"}, true, "history.csv"},
      {{"soiltest", "synthetic", "--params", "data/params/table_5_2_hostun.toml", "--test",
        "oedometer"},
       true,
       "timeseries.csv"},
      {{"compare", "data/convergence/truth_clamped/runs/s1", "--model", "hvwe", "--params",
        "data/params/truth_grains_epsd2.toml"},
       true,
       "compare.json"},
      {{"run", "--study", "clay"}, true, "study.json"},
      {{"pile", "data/piles/example.toml"}, true, "manifest.json"},
  };
  for (const auto& c : cases) {
    const fs::path dir = fs::path(IWB_TEST_RUNS_DIR) / "app" / "output_directories" / c.args[0];
    fs::remove_all(dir);
    auto args = c.args;
    args.insert(args.end(), {"--out", dir.string()});
    std::string line = "iwb";
    for (const auto& a : args) line += " " + a;
    INFO(line);
    REQUIRE(test::run_iwb(args).exit_code == 0);
    std::ofstream(dir / "thesis.txt") << "my thesis\n";
    if (c.has_force) args.push_back("--force");
    const auto again = test::run_iwb(args);
    INFO(again.output);
    CHECK(again.exit_code == 0);
    CHECK(io::read_file(dir / "thesis.txt") == "my thesis\n");
    CHECK(fs::exists(dir / c.a_file_it_writes));
    const auto ledger = nlohmann::json::parse(io::read_file(dir / io::kLedgerFileName));
    const auto written = ledger.at("written").get<std::vector<std::string>>();
    CHECK(std::find(written.begin(), written.end(), "thesis.txt") == written.end());
    CHECK(std::find(written.begin(), written.end(), c.a_file_it_writes) != written.end());
  }
}
