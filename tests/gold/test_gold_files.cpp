// Gold-file regression tests (STYLE.md, after MOOSE's CSVDiff): every gold file
// src/models/<folder>/gold/<model>/<path>.csv is the history of one element test, run here as
// `iwb element` runs it and compared column by column within the tolerances of
// data/gold/gold.toml. The files are the list of cases: a model's folder holds its gold files, so
// adding a model touches no list here (data/gold/README.md). Any change of a model's response fails
// here and shows in review as a diff of the gold files. When a change is intended,
// data/gold/regenerate.sh rewrites those that no longer pass (IWB_GOLD_REGENERATE=1) and the diff
// is reviewed instead.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <tuple>

#include "element/element_run.hpp"
#include "element/element_test_file.hpp"
#include "io/toml_override.hpp"
#include "io/toml_reader.hpp"
#include "models/registry.hpp"
#include "support/csv_diff.hpp"

using namespace iwb;
namespace fs = std::filesystem;

namespace {

// The tests run from the source tree (tests/CMakeLists.txt).
const fs::path kModelsDir = "src/models";
const fs::path kGoldDir = "data/gold";                // README, tolerances, regenerate.sh
const fs::path kSharedTemplates = "data/gold/tests";  // templates models of several folders run
const fs::path kTolerancesFile = "data/gold/gold.toml";

fs::path gold_dir_of(const std::string& folder) {
  return kModelsDir / folder / "gold";
}

// One gold file: the model, the folder that registers it, and the path (the template's name).
struct GoldCase {
  std::string folder;
  std::string model;
  std::string path;
  fs::path gold_file() const { return gold_dir_of(folder) / model / (path + ".csv"); }
  fs::path own_template() const { return gold_dir_of(folder) / (path + ".toml"); }
  fs::path shared_template() const { return kSharedTemplates / (path + ".toml"); }
  // The folder's own template, else the shared one; the layout test checks that exactly one exists.
  fs::path template_file() const {
    return fs::exists(own_template()) ? own_template() : shared_template();
  }
};

// Every src/models/*/gold/*/*.csv, sorted by model and path.
std::vector<GoldCase> all_cases() {
  std::vector<GoldCase> out;
  for (const auto& folder : fs::directory_iterator(kModelsDir)) {
    const auto gold = folder.path() / "gold";
    if (!fs::is_directory(gold)) continue;
    for (const auto& model : fs::directory_iterator(gold)) {
      if (!model.is_directory()) continue;
      for (const auto& f : fs::directory_iterator(model.path()))
        if (f.path().extension() == ".csv")
          out.push_back({folder.path().filename().string(), model.path().filename().string(),
                         f.path().stem().string()});
    }
  }
  std::sort(out.begin(), out.end(), [](const GoldCase& a, const GoldCase& b) {
    return std::tie(a.model, a.path) < std::tie(b.model, b.path);
  });
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
  fs::copy_file(history, c.gold_file(), fs::copy_options::overwrite_existing);
  WARN("regenerated " << c.gold_file().string());
}

// Every case `selected`, each failure reported and the next case run.
void check_cases(const std::function<bool(const GoldCase&)>& selected) {
  static const auto tolerances = test::read_tolerances(
      io::parse_toml_file(kTolerancesFile.string()), kTolerancesFile.string());
  int cases = 0;
  for (const auto& c : all_cases()) {
    if (!selected(c)) continue;
    ++cases;
    std::string why;
    const auto history = run(c, why);
    if (!history) {
      FAIL_CHECK(c.model << " on " << c.path << ": the run did not complete: " << why);
    } else if (const auto d = test::diff_csv_files(c.gold_file(), *history, tolerances);
               !d.failed) {
      // passes: kept as it is, also when regenerating, so that a regeneration rewrites only the
      // files whose response moved (and a new model's empty ones), not every file in the last
      // digits or the cost counters, which the tolerances hold to be the same response
    } else if (regenerating()) {
      regenerate(c, *history);
    } else {
      FAIL_CHECK(c.model << " on " << c.path << ": " << d.message
                         << "\n(if the change is intended: data/gold/regenerate.sh, then review "
                            "the diff)");
    }
  }
  CHECK(cases > 0);
}

void check_path(const std::string& path) {
  check_cases([&](const GoldCase& c) { return c.path == path; });
}

bool is_sand_path(const std::string& path) {
  return path == "CNL" || path == "CNS" || path == "CV" || path == "cyclic_CNL" ||
         path == "oedometric";
}

// The names of the templates in `dir` (data/gold/tests or a folder's gold/).
std::vector<std::string> templates_in(const fs::path& dir) {
  std::vector<std::string> out;
  if (fs::is_directory(dir))
    for (const auto& f : fs::directory_iterator(dir))
      if (f.path().extension() == ".toml") out.push_back(f.path().stem().string());
  return out;
}

// What is wrong with the layout of the gold files (data/gold/README.md), one line each; empty
// when every registered model has gold files in its own folder, every gold file belongs to a
// model that folder registers and names exactly one template, and every template is where the
// rule puts it.
std::vector<std::string> layout_problems() {
  std::vector<std::string> problems;
  std::map<std::string, std::set<std::string>> models_of_folder;
  for (const auto& spec : models::model_registry())
    if (!spec.folder.empty()) models_of_folder[spec.folder].insert(spec.name);
  std::map<std::string, std::set<std::string>> cases_of_model;
  std::map<std::string, std::set<std::string>> folders_running;  // template -> folders
  for (const auto& c : all_cases()) {
    cases_of_model[c.model].insert(c.path);
    folders_running[c.path].insert(c.folder);
    if (fs::exists(c.own_template()) == fs::exists(c.shared_template()))
      problems.push_back(c.gold_file().string() + ": the path '" + c.path + "' names " +
                         (fs::exists(c.own_template()) ? "two templates, " : "no template: ") +
                         c.own_template().string() + " and " + c.shared_template().string());
  }
  for (const auto& [folder, models] : models_of_folder)
    for (const auto& model : models)
      if (cases_of_model[model].empty())
        problems.push_back("model '" + model + "' has no gold file in " +
                           (gold_dir_of(folder) / model).string() + "/<path>.csv");
  // Whatever sits in a gold/ folder is a template or the gold files of a model registered there.
  std::map<std::string, std::vector<fs::path>> templates_named;
  for (const auto& t : templates_in(kSharedTemplates))
    templates_named[t].push_back(kSharedTemplates / (t + ".toml"));
  for (const auto& folder : fs::directory_iterator(kModelsDir)) {
    const auto name = folder.path().filename().string();
    const auto gold = folder.path() / "gold";
    if (!fs::is_directory(gold)) continue;
    for (const auto& entry : fs::directory_iterator(gold)) {
      const auto entry_name = entry.path().filename().string();
      if (!entry.is_directory()) {
        if (entry.path().extension() != ".toml")
          problems.push_back(entry.path().string() + ": neither a template nor a model's folder");
      } else if (models_of_folder[name].count(entry_name) == 0) {
        problems.push_back(entry.path().string() + ": no model '" + entry_name +
                           "' is registered by " + folder.path().string() + "/register.cpp");
      } else {
        for (const auto& f : fs::directory_iterator(entry.path()))
          if (f.path().extension() != ".csv")
            problems.push_back(f.path().string() + ": not a gold file (<path>.csv)");
      }
    }
    // A folder's template serves its own models, which must run it.
    for (const auto& t : templates_in(gold)) {
      templates_named[t].push_back(gold / (t + ".toml"));
      if (folders_running[t].count(name) == 0)
        problems.push_back((gold / (t + ".toml")).string() + ": no gold file of " + gold.string() +
                           "/<model>/ runs it");
    }
  }
  // A path means one element test wherever it is named (a failure says "hvwe on CNL").
  for (const auto& [t, files] : templates_named)
    if (files.size() > 1)
      problems.push_back("the path '" + t + "' has " + std::to_string(files.size()) +
                         " templates: " + files[0].string() + ", " + files[1].string());
  // A shared template serves models of several folders, else it belongs in the one folder's gold/.
  for (const auto& t : templates_in(kSharedTemplates))
    if (folders_running[t].size() < 2)
      problems.push_back((kSharedTemplates / (t + ".toml")).string() + ": run by " +
                         (folders_running[t].empty()
                              ? std::string("no gold file")
                              : "the models of " + *folders_running[t].begin() +
                                    " only: it belongs in " +
                                    gold_dir_of(*folders_running[t].begin()).string()));
  // The gold files live with their models only: nothing left where the hand list kept them.
  for (const auto& f : fs::recursive_directory_iterator(kGoldDir))
    if (f.path().extension() == ".csv")
      problems.push_back(f.path().string() + ": a gold file outside its model's folder");
  return problems;
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

// The clay paths (Table 6.4), Table 6.5's and Table 8.1's.
TEST_CASE("gold: every model on the other shared paths of data/gold/tests matches its gold file",
          "[gold][gold-files]") {
  check_cases([](const GoldCase& c) {
    return !is_sand_path(c.path) && c.template_file() == c.shared_template();
  });
}

// mc, hyperbolic, lashkari, mortara, hcthm's thermo-hydro path: any folder's own paths.
TEST_CASE("gold: every model on its own folder's paths matches its gold file",
          "[gold][gold-files]") {
  check_cases([](const GoldCase& c) { return c.template_file() == c.own_template(); });
}

TEST_CASE(
    "gold: every registered model has gold files in its folder and each names exactly one template",
    "[gold][gold-layout]") {
  const auto problems = layout_problems();
  for (const auto& p : problems) FAIL_CHECK(p << " (data/gold/README.md says where files go)");
  CHECK(problems.empty());
}
