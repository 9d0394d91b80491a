// Which built-in parameter set replays a DEM run: the set calibrated on the scene's own grains,
// and none for grains no set was calibrated on (then the closest phi_c, not tested here).
#include <catch2/catch.hpp>

#include "io/run_directory.hpp"
#include "validation/parameter_choice.hpp"

using namespace iwb;

namespace {
std::string chosen_for(const std::string& scene_text, const std::string& name) {
  const auto sets = io::parameter_sets({});
  std::string why;
  const auto* set =
      validation::calibrated_parameters(sets, dem::parse_scene(scene_text, name), why);
  return set ? set->name : "";
}
}  // namespace

TEST_CASE("parameter choice: each scene's grains get the set calibrated on them, other grains none",
          "[validation]") {
  for (const char* f :
       {"data/scenes/default.toml", "data/scenes/smoke.toml", "data/scenes/convergence.toml"})
    CHECK(chosen_for(io::read_file(f), f) == "dem_default_grains.toml");  // E 1e8 Pa
  const std::string truth = io::read_file("data/scenes/truth.toml");
  // the truth grains with cdt rolling resistance, as truth_grains.toml was calibrated; with the
  // scene's epsd2 they are other grains, calibrated in data/calibration/truth_grains_epsd2/
  std::string cdt = truth;
  cdt.replace(cdt.find("rolling_model = \"epsd2\""), 23, "rolling_model = \"cdt\"");
  CHECK(chosen_for(cdt, "truth-cdt.toml") == "truth_grains.toml");
  CHECK(chosen_for(truth, "truth.toml") == "truth_grains_epsd2.toml");
  std::string stiffer = truth;
  stiffer.replace(stiffer.find("youngs_modulus_Pa = 6.9e8"), 25, "youngs_modulus_Pa = 4.2e9");
  CHECK(chosen_for(stiffer, "stiffer.toml").empty());
}
