// Scene identity by content (dem/scene_content.hpp): what `iwb validate` reuses a DEM run by and
// `iwb plan` accepts a tradeoff by. Comments, layout, key order, the description and the
// requirements do not count; every value that reaches the engine does, and is named.
#include <catch2/catch.hpp>

#include "dem/scene_content.hpp"
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
  CHECK(content_differences(scene_content(kScene, "a.toml"), scene_content(kSameScene, "b.toml")).empty());
}

TEST_CASE("a changed value, a missing and an added key are named with both values", "[dem][scene]") {
  std::string changed = kScene;
  changed.replace(changed.find("friction = 0.5"), 14, "friction = 0.6");
  changed.replace(changed.find("particles = 400"), 15, "");
  changed += "[numerics]\ndt_fraction = 0.1\n";
  const auto diff = content_differences(scene_content(changed, "mine.toml"), scene_content(kScene, "base.toml"));
  REQUIRE(diff.size() == 3);
  CHECK(diff[0] == "key 'numerics' = {\"dt_fraction\":0.1} here, absent there");
  CHECK(diff[1] == "key 'particles.friction' = 0.6 here, = 0.5 there");
  CHECK(diff[2] == "key 'specimen.particles' absent here, = 400 there");
  CHECK(iwb::dem::differences_text(diff).find("; key 'particles.friction'") != std::string::npos);
}

TEST_CASE("the committed default tradeoff records the content of data/scenes/default.toml", "[dem][scene][tradeoff]") {
  const auto t = nlohmann::json::parse(iwb::io::read_file("data/tradeoff/default/tradeoff.json"));
  const auto content = scene_content(iwb::io::read_file("data/scenes/default.toml"), "default.toml");
  CHECK(content_differences(content, t.at("dem_scene")).empty());
}
