// Gold-file regression tests (STYLE.md, after MOOSE's CSVDiff): every model on each of its paths in
// data/gold/gold.toml, run as `iwb element` runs it, against its committed history, column by
// column within the tolerances stated there. Any change of a model's response fails here and shows
// in review as a diff of data/gold/. When a change is intended, data/gold/regenerate.sh rewrites
// the files (IWB_GOLD_REGENERATE=1) and the diff is reviewed instead.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <set>

#include "element/element_run.hpp"
#include "element/element_test_file.hpp"
#include "io/toml_override.hpp"
#include "io/toml_reader.hpp"
#include "models/registry.hpp"
#include "support/csv_diff.hpp"

using namespace iwb;
namespace fs = std::filesystem;

namespace {

const fs::path kGoldDir = "data/gold";  // the tests run from the source tree (tests/CMakeLists.txt)

struct GoldCase {
  std::string model;
  std::string path;
  fs::path gold_file() const { return kGoldDir / model / (path + ".csv"); }
  fs::path template_file() const { return kGoldDir / "tests" / (path + ".toml"); }
};

const toml::table& config() {
  static const toml::table root = io::parse_toml_file((kGoldDir / "gold.toml").string());
  return root;
}

// [models] NAME = [paths], models sorted by name (toml++ keeps a table's keys sorted).
std::vector<GoldCase> all_cases() {
  std::vector<GoldCase> out;
  const auto* models = config()["models"].as_table();
  REQUIRE(models != nullptr);
  for (const auto& [name, paths] : *models) {
    REQUIRE(paths.is_array());
    for (const auto& p : *paths.as_array())
      out.push_back({std::string(name.str()), *p.value<std::string>()});
  }
  return out;
}

// The path's template with the model's name; continuum models (vw3d) refuse [roughness], so it
// goes.
element::ElementTestSpec spec_of(const GoldCase& c) {
  const std::string file = c.template_file().string();
  auto root = io::parse_toml_file(file);
  io::set_dotted(root, "model.name", c.model, file);
  if (!models::find_model(c.model).uses_roughness) root.erase("roughness");
  return element::parse_element_test(root, file + " with model " + c.model,
                                     c.template_file().parent_path());
}

// A run directory as `iwb element` writes it, kept under build/test-runs/gold/ for inspection.
// Empty, with the reason in `why`, when the run did not complete: a gold file of a failed run
// would pin the failure, and one broken case must not hide the others.
std::optional<fs::path> run(const GoldCase& c, std::string& why) {
  element::ElementRunOptions opt;
  opt.out = fs::path(IWB_TEST_RUNS_DIR) / "gold" / c.model / c.path;
  opt.force = true;
  opt.command_line = "iwb_tests [gold]";
  try {
    const auto outcome = element::run_element_to_directory(spec_of(c), opt);
    why = outcome.result.status;
    if (outcome.result.complete()) return opt.out / "history.csv";
  } catch (const std::exception& e) {
    why = e.what();
  }
  return std::nullopt;
}

bool regenerating() {
  const char* v = std::getenv("IWB_GOLD_REGENERATE");
  return v != nullptr && std::string(v) == "1";
}

void regenerate(const GoldCase& c, const fs::path& history) {
  fs::create_directories(c.gold_file().parent_path());
  fs::copy_file(history, c.gold_file(), fs::copy_options::overwrite_existing);
  WARN("regenerated " << c.gold_file().string());
}

// Every model on `path`, each failure reported and the next model run.
void check_path(const std::string& path) {
  const auto tolerances = test::read_tolerances(config(), (kGoldDir / "gold.toml").string());
  int cases = 0;
  for (const auto& c : all_cases()) {
    if (c.path != path) continue;
    ++cases;
    std::string why;
    const auto history = run(c, why);
    if (!history) {
      FAIL_CHECK(c.model << " on " << path << ": the run did not complete: " << why);
    } else if (regenerating()) {
      regenerate(c, *history);
    } else if (const auto d = test::diff_csv_files(c.gold_file(), *history, tolerances); d.failed) {
      FAIL_CHECK(c.model << " on " << path << ": " << d.message
                         << "\n(if the change is intended: data/gold/regenerate.sh, then review "
                            "the diff)");
    }
  }
  CHECK(cases > 0);
}

}  // namespace

TEST_CASE("gold: monotonic CNL of every model matches its gold file", "[gold][gold-files]") {
  check_path("CNL");
}

TEST_CASE("gold: monotonic CNS of every model matches its gold file", "[gold][gold-files]") {
  check_path("CNS");
}

TEST_CASE("gold: monotonic CV of every model matches its gold file", "[gold][gold-files]") {
  check_path("CV");
}

TEST_CASE("gold: cyclic CNL of every -igs model matches its gold file", "[gold][gold-files]") {
  check_path("cyclic_CNL");
}

TEST_CASE("gold: oedometric loading of every model that has one matches its gold file",
          "[gold][gold-files]") {
  check_path("oedometric");
}

TEST_CASE(
    "gold: the reference interface models (mc, hyperbolic, lashkari, mortara) on CNL, CNS and CV "
    "match their gold files",
    "[gold][gold-files]") {
  for (const std::string path : {"mc_CNL", "mc_CNS", "mc_CV", "hyperbolic_CNL", "hyperbolic_CNS",
                                 "hyperbolic_CV", "lashkari_CNL", "lashkari_CNS", "lashkari_CV",
                                 "mortara_CNL", "mortara_CNS", "mortara_CV"}) {
    INFO(path);
    check_path(path);
  }
}

TEST_CASE(
    "gold: the models of seed chapter 8 (modified Cam clay, Barodesy) on CNL, CNS and CV match "
    "their gold files",
    "[gold][gold-files]") {
  for (const std::string path : {"table_8_1_CNL", "table_8_1_CNS", "table_8_1_CV"}) {
    INFO(path);
    check_path(path);
  }
}

TEST_CASE(
    "gold: Masin's clay and the thermo-hydro model (Table 6.5) on CNL, CV and a heat-dry-wet path "
    "match their gold files",
    "[gold][gold-files]") {
  for (const std::string path : {"table_6_5_CNL", "table_6_5_CV", "table_6_5_thermo_hydro"}) {
    INFO(path);
    check_path(path);
  }
}

// A model added to the registry without gold files, or a gold file no case produces, fails here.
TEST_CASE("gold: the clay models on their paths (Table 6.4) match their gold files",
          "[gold][gold-files]") {
  for (const std::string path :
       {"clay_CNL", "clay_CNS", "clay_CV", "clay_oedometric", "clay_cyclic_CNL"}) {
    INFO(path);
    check_path(path);
  }
}

TEST_CASE("gold: every registered model has gold cases and every gold file a case", "[gold]") {
  std::set<std::string> expected;
  for (const auto& c : all_cases()) {
    CHECK(fs::exists(c.template_file()));
    CHECK(models::find_model(c.model).name == c.model);
    expected.insert(c.gold_file().string());
  }
  for (const auto& spec : models::model_registry()) {
    INFO(spec.name << " has no entry in data/gold/gold.toml [models]");
    CHECK(config()["models"][spec.name].is_array());
  }
  for (const auto& f : fs::recursive_directory_iterator(kGoldDir)) {
    if (f.path().extension() != ".csv") continue;
    INFO(f.path().string() << " is produced by no case of data/gold/gold.toml");
    CHECK(expected.count(f.path().string()) == 1);
  }
}
