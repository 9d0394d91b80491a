// The root README's index of the models is generated from the model folders (issue 33, item 5):
// one row per folder that registers models, with the models the registry says it registers and
// the title of its README (`# <models>: <title>`). A model added in a folder of its own thus needs
// no line in README.md; this test fails until the index is regenerated.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "io/run_directory.hpp"
#include "models/registry.hpp"
#include "support/generated_section.hpp"

using namespace iwb;

namespace {

const std::string kIndexReadme = "README.md";  // the tests run from the source tree
const std::string kIndexBegin =
    "<!-- BEGIN generated from src/models/*/README.md by tests/models/test_models_index.cpp -->\n";
const std::string kIndexEnd = "<!-- END generated -->";

// What the title line of the folder's README says after `# <models>: `; empty when the README or
// that form is missing.
std::string readme_title(const std::string& folder) {
  std::ifstream in("src/models/" + folder + "/README.md");
  std::string line;
  if (!std::getline(in, line) || line.rfind("# ", 0) != 0) return {};
  const auto colon = line.find(": ");
  return colon == std::string::npos ? std::string() : line.substr(colon + 2);
}

// Folders in the order of their first model in `iwb models`.
std::string models_index() {
  std::vector<std::string> folders;
  std::map<std::string, std::string> names;
  for (const auto& spec : models::model_registry()) {
    if (spec.folder.empty()) continue;  // added at run time: no folder, no row
    auto& list = names[spec.folder];
    if (list.empty()) folders.push_back(spec.folder);
    list += (list.empty() ? "`" : ", `") + spec.name + "`";
  }
  std::string out = "| models | what | equations, readings, tested facts |\n|---|---|---|\n";
  for (const auto& f : folders)
    out += "| " + names[f] + " | " + readme_title(f) + " | `src/models/" + f + "/README.md` |\n";
  return out;
}

}  // namespace

TEST_CASE("README.md's index of the models is the one the model folders give", "[readme-models]") {
  for (const auto& spec : models::model_registry()) {
    INFO("src/models/" << spec.folder << "/README.md: its first line is '# <models>: <title>'");
    CHECK((spec.folder.empty() || !readme_title(spec.folder).empty()));
  }
  test::check_generated_section(kIndexReadme, kIndexBegin, kIndexEnd, models_index(),
                                "[readme-models]");
}
