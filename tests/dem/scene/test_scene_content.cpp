// Scene identity by content (dem/scene/scene_content.hpp): what `iwb validate` reuses a DEM run by
// and `iwb plan` accepts a tradeoff by. Comments, layout, key order, the description and the
// requirements do not count; every value that reaches the engine does, and is named.
#include <catch2/catch.hpp>
#include <filesystem>

#include "dem/scene/scene.hpp"
#include "dem/scene/scene_content.hpp"
#include "io/run_directory.hpp"

using iwb::dem::content_differences;
using iwb::dem::scene_content;

namespace {

const std::string kScene = R"(description = "a"
seed = 1
[particles]
d50_mm = 2.0
friction = 0.5
[specimen]
particles = 400
[requirements]
residual_friction = 0.05
)";

// The same scene written otherwise: another description and requirements, comments, key order,
// 2 for 2.0.
const std::string kSameScene = R"(# a copy
description = "b"
seed = 1
[specimen]
particles = 400   # as before
[particles]
friction = 0.5
d50_mm = 2
[requirements]
residual_friction = 0.01
)";

}  // namespace

TEST_CASE("a scene written otherwise has the same content", "[dem][scene]") {
  CHECK(content_differences(scene_content(kScene, "a.toml"), scene_content(kSameScene, "b.toml"))
            .empty());
}

TEST_CASE("a changed value, a missing and an added key are named with both values",
          "[dem][scene]") {
  std::string changed = kScene;
  changed.replace(changed.find("friction = 0.5"), 14, "friction = 0.6");
  changed.replace(changed.find("particles = 400"), 15, "");
  changed += "[numerics]\ndt_fraction = 0.1\n";
  const auto diff =
      content_differences(scene_content(changed, "mine.toml"), scene_content(kScene, "base.toml"));
  REQUIRE(diff.size() == 3);
  CHECK(diff[0] == "key 'numerics' = {\"dt_fraction\":0.1} here, absent there");
  CHECK(diff[1] == "key 'particles.friction' = 0.6 here, = 0.5 there");
  CHECK(diff[2] == "key 'specimen.particles' absent here, = 400 there");
  CHECK(iwb::dem::differences_text(diff).find("; key 'particles.friction'") != std::string::npos);
}

TEST_CASE("the committed default tradeoff records the content of data/scenes/default.toml",
          "[dem][scene][tradeoff]") {
  const auto t = nlohmann::json::parse(iwb::io::read_file("data/tradeoff/default/tradeoff.json"));
  const auto content =
      scene_content(iwb::io::read_file("data/scenes/default.toml"), "default.toml");
  CHECK(content_differences(content, t.at("dem_scene")).empty());
}

TEST_CASE(
    "a scene naming a wall file is another scene when the file's heights change but not when it "
    "moves",
    "[dem]") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "iwb_scene_file_identity";
  fs::create_directories(dir / "elsewhere");
  const std::string profile = iwb::io::read_file("data/walls/sandblasted_like.csv");
  iwb::io::write_atomically(dir / "wall.csv", profile);
  iwb::io::write_atomically(dir / "elsewhere" / "wall.csv", profile);
  std::string text = iwb::io::read_file("data/scenes/smoke_file.toml");
  text.replace(text.find("../walls/sandblasted_like.csv"), 29, "wall.csv");
  const auto here = (dir / "scene.toml").string(),
             there = (dir / "elsewhere" / "scene.toml").string();
  const auto sha = iwb::dem::scene_sha256(iwb::dem::parse_scene(text, here), text);
  CHECK(sha == iwb::dem::scene_sha256(iwb::dem::parse_scene(text, there), text));
  CHECK(content_differences(scene_content(text, here), scene_content(text, there)).empty());
  // one height changed by 1 um
  std::string changed = profile;
  changed.replace(changed.find("\n0.015,") + 7, 8, "-0.00900");
  iwb::io::write_atomically(dir / "elsewhere" / "wall.csv", changed);
  CHECK(sha != iwb::dem::scene_sha256(iwb::dem::parse_scene(text, there), text));
  CHECK(content_differences(scene_content(text, here), scene_content(text, there)).size() == 1);
  // a scene naming no file: the text's own sha256, as before wall files
  const std::string smoke = iwb::io::read_file("data/scenes/smoke.toml");
  CHECK(iwb::dem::scene_sha256(iwb::dem::parse_scene(smoke, "smoke.toml"), smoke) ==
        iwb::io::sha256_hex(smoke));
}
