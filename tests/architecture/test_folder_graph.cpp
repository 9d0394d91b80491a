// The folders of src/ form layers: no chain of #includes leads from a folder back to itself
// (issue 33: "no folder arrow runs back up"). A cycle would mean two folders that can be
// understood, tested and changed only together.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

namespace iwb {

namespace {

namespace fs = std::filesystem;
using FolderGraph = std::map<std::string, std::set<std::string>>;

// folder -> the other folders of src/ its files include
FolderGraph include_graph() {
  FolderGraph g;
  const std::regex include(R"(^#include "([a-z_0-9]+)/)");
  for (const auto& f : fs::recursive_directory_iterator("src")) {
    const auto ext = f.path().extension();
    if (ext != ".cpp" && ext != ".hpp") continue;
    // A family's calibration recipe (models/<family>/calibration_recipe.*) lives in its family's
    // folder, so that a family is one folder (issue 58), but belongs to the calibration's layer:
    // it is compiled into iwb_calibration (src/CMakeLists.txt) and reads soil tests and fits.
    const bool recipe = f.path().stem() == "calibration_recipe" &&
                        fs::relative(f.path(), "src").begin()->string() == "models";
    const std::string folder =
        recipe ? "calibration" : fs::relative(f.path(), "src").begin()->string();
    std::ifstream in(f.path());
    std::smatch m;
    for (std::string line; std::getline(in, line);)
      if (std::regex_search(line, m, include) && m[1] != folder &&
          fs::is_directory("src/" + m[1].str()))
        g[folder].insert(m[1]);
  }
  return g;
}

// A cycle through `node` as a path of folders, empty if none.
bool find_cycle(const FolderGraph& g, const std::string& node, std::map<std::string, int>& state,
                std::vector<std::string>& path) {
  state[node] = 1;
  path.push_back(node);
  if (const auto it = g.find(node); it != g.end())
    for (const auto& next : it->second) {
      if (state[next] == 1) {
        path.push_back(next);
        return true;
      }
      if (state[next] == 0 && find_cycle(g, next, state, path)) return true;
    }
  path.pop_back();
  state[node] = 2;
  return false;
}

std::vector<std::string> a_cycle(const FolderGraph& g) {
  std::map<std::string, int> state;
  for (const auto& [node, _] : g) {
    std::vector<std::string> path;
    if (state[node] == 0 && find_cycle(g, node, state, path)) return path;
  }
  return {};
}

}  // namespace

TEST_CASE("no chain of includes leads from a folder of src/ back to itself", "[architecture]") {
  const auto g = include_graph();
  REQUIRE(g.size() > 10);  // the walk found the tree (tests run from the source root)
  std::string cycle;
  for (const auto& f : a_cycle(g)) cycle += (cycle.empty() ? "" : " -> ") + f;
  INFO("include cycle: " << cycle);
  CHECK(cycle.empty());
}

TEST_CASE("the cycle finder finds a planted cycle", "[architecture]") {
  FolderGraph g{{"io", {"common"}}, {"element", {"io", "driver"}}, {"driver", {"element"}}};
  const auto c = a_cycle(g);
  REQUIRE(c.size() == 3);
  CHECK(c.front() == c.back());
  CHECK(a_cycle({{"io", {"common"}}, {"element", {"io"}}}).empty());
}

}  // namespace iwb
