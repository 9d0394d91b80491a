// The root README's Layout block names every folder of src/, so that a new folder cannot be
// added without saying what it holds.
#include <catch2/catch.hpp>
#include <filesystem>

#include "io/run_directory.hpp"

namespace iwb {

TEST_CASE("the README's layout names every folder of src/", "[readme]") {
  const std::string readme = io::read_file("README.md");
  const auto begin = readme.find("## Layout");
  REQUIRE(begin != std::string::npos);
  const auto end = readme.find("```", readme.find("```", begin) + 3);
  const std::string layout = readme.substr(begin, end - begin);
  for (const auto& entry : std::filesystem::directory_iterator("src"))
    if (entry.is_directory()) {
      const std::string folder = "\nsrc/" + entry.path().filename().string() + "/";
      INFO(folder.substr(1) << " is missing from README.md's Layout");
      CHECK(layout.find(folder) != std::string::npos);
    }
}

}  // namespace iwb
