// The cross-engine check's pieces that need no engine: seeding a scene text and the seed scatter.
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>

#include "common/errors.hpp"
#include "dem/engines/engines.hpp"
#include "dem/run/crosscheck.hpp"
#include "dem/scene/scene.hpp"
#include "io/json_file.hpp"
#include "io/run_directory.hpp"

using namespace iwb;
namespace fs = std::filesystem;

TEST_CASE("with_seed replaces the top-level seed or adds one, and the scene parses with it",
          "[dem]") {
  const std::string smoke = io::read_file("data/scenes/smoke.toml");
  const auto seeded = dem::with_seed(smoke, 7);
  CHECK(dem::parse_scene(seeded, "smoke+seed").seed == 7);
  CHECK(dem::parse_scene(smoke, "smoke").seed == 1);  // the original says seed = 1
  const std::string without = "description = \"x\"\n";
  CHECK(dem::with_seed(without, 3).rfind("seed = 3\n", 0) == 0);
  // a key that merely ends in "seed" inside a table is left alone
  const std::string nested = "seed = 1\n[particles]\nnot_a_seed = 2\n";
  CHECK(dem::with_seed(nested, 5) == "seed = 5\n[particles]\nnot_a_seed = 2\n");
}

TEST_CASE("seed scatter is the sample standard deviation", "[dem]") {
  const auto s = dem::scatter_of({0.50, 0.52, 0.54});
  CHECK(s.n == 3);
  CHECK(s.mean == Approx(0.52));
  CHECK(s.sd == Approx(0.02));
  CHECK(dem::scatter_of({0.4}).sd == 0.0);
  CHECK(dem::scatter_of({}).n == 0);
}

TEST_CASE("an unknown engine is refused with the engines available", "[dem]") {
  try {
    dem::make_engine("pfc");
    FAIL("pfc accepted");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()) == "--engine pfc: available engines: liggghts, yade");
  }
}

// Welch's standard error of a difference of two means, sqrt(sd_a^2/n_a + sd_b^2/n_b): with three
// seeds of SD 0.02 each it is 0.02 sqrt(2/3) = 0.01633, so two standard errors are 0.0327.
TEST_CASE("two engines agree on a quantity when their means lie within two standard errors",
          "[dem]") {
  const dem::Scatter a{0.50, 0.02, 3};
  const auto close = dem::agreement_of(a, {0.53, 0.02, 3});
  CHECK(close.judged);
  CHECK(close.difference == Approx(0.03));
  CHECK(close.standard_error == Approx(0.02 * std::sqrt(2.0 / 3.0)));
  CHECK(close.agree);                                        // 1.84 standard errors
  CHECK_FALSE(dem::agreement_of(a, {0.54, 0.02, 3}).agree);  // 2.45 standard errors
  // unequal scatter and counts: sqrt(0.01^2/2 + 0.04^2/4) = 0.02121
  CHECK(dem::agreement_of({0.5, 0.01, 2}, {0.55, 0.04, 4}).standard_error ==
        Approx(0.021213).epsilon(1e-4));
  // one seed has no scatter to judge by
  CHECK_FALSE(dem::agreement_of({0.5, 0.0, 1}, {0.5, 0.02, 3}).judged);
}

TEST_CASE(
    "a committed crosscheck seed run is reused for its scene and engine mapping, not once the "
    "mapping changed",
    "[dem]") {
  const std::string text = dem::with_seed(io::read_file("data/scenes/truth.toml"), 1);
  const dem::Scene scene = dem::parse_scene(text, "data/scenes/truth.toml");
  const auto liggghts = dem::make_engine("liggghts");
  const fs::path committed = "data/reference/crosscheck/liggghts-seed1";
  CHECK(dem::reusable_seed_run(committed, scene, text, *liggghts));
  CHECK_FALSE(dem::reusable_seed_run(committed, scene, dem::with_seed(text, 2),
                                     *liggghts));  // another scene
  CHECK_FALSE(dem::reusable_seed_run(committed, scene, text,
                                     *dem::make_engine("yade")));  // another engine's mapping
  // the same run with a different timestep in its manifest: stale
  const fs::path copy =
      fs::temp_directory_path() / ("iwb_stale_seed_run_" + std::to_string(::getpid()));
  fs::create_directories(copy);
  auto manifest = io::read_json_file(committed / "manifest.json");
  manifest["numerics"]["timestep_s"] = manifest["numerics"]["timestep_s"].get<double>() * 0.5;
  io::write_atomically(copy / "manifest.json", manifest.dump(2));
  CHECK_FALSE(dem::reusable_seed_run(copy, scene, text, *liggghts));
  fs::remove_all(copy);
  CHECK_FALSE(dem::reusable_seed_run(copy, scene, text, *liggghts));  // no run at all
}
