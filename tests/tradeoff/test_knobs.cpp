// The knob variants of `iwb tradeoff`: each halves or doubles one resolution knob of the scene and
// nothing else, and every variant is a valid scene. No engine runs here.
#include <algorithm>
#include <catch2/catch.hpp>

#include "dem/scene/numerics.hpp"
#include "dem/scene/scene.hpp"
#include "io/run_directory.hpp"
#include "tradeoff/knobs.hpp"
#include "tradeoff/tradeoff.hpp"

using namespace iwb;

namespace {
dem::Scene variant(const std::string& base_text, const std::string& knob, double f) {
  const auto base = dem::parse_scene(base_text, "smoke.toml");
  const auto settings = tradeoff::knob_settings(base, base_text, {{knob, f}});
  return dem::parse_scene(tradeoff::derived_scene(base_text, "smoke.toml", settings, knob),
                          "variant.toml");
}
}  // namespace

TEST_CASE("tradeoff knobs: dt, kappa and I scale their own quantity and leave the rest",
          "[tradeoff]") {
  const std::string text = io::read_file("data/scenes/smoke.toml");
  const auto base = dem::parse_scene(text, "smoke.toml");
  const auto dt = variant(text, "dt", 0.5);
  CHECK(dem::derive(dt).dt == Approx(0.5 * dem::derive(base).dt).epsilon(1e-9));
  CHECK(dem::derive(dt).shear_steps ==
        Approx(2.0 * double(dem::derive(base).shear_steps)).epsilon(1e-3));
  CHECK(dt.particle_count == base.particle_count);
  // consolidation windows of the same physical duration: twice the steps
  CHECK(dt.consolidation.window_steps == 2 * base.consolidation.window_steps);
  CHECK(dt.consolidation.max_windows == base.consolidation.max_windows);
  const auto stiff = variant(text, "kappa", 2.0);
  CHECK(stiff.stiffness_level() ==
        Approx(2.0 * base.stiffness_level()).epsilon(1e-3));  // E rounded to 4 digits
  CHECK(dem::derive(stiff).dt ==
        Approx(dem::derive(base).dt / std::pow(2.0, 0.75)).epsilon(1e-3));  // dt ~ E^-1/2
  const auto slow = variant(text, "I", 0.5);
  CHECK(slow.shear.inertial_number == Approx(0.5 * base.shear.inertial_number).epsilon(1e-9));
  CHECK(slow.shear.velocity_m_s == Approx(0.5 * base.shear.velocity_m_s).epsilon(1e-9));
  CHECK(slow.dt_fraction == base.dt_fraction);
}

TEST_CASE(
    "tradeoff knobs: box scales length, height and particles, or the height alone at the length "
    "limit",
    "[tradeoff]") {
  const std::string text = io::read_file("data/scenes/smoke.toml");
  const auto base = dem::parse_scene(text, "smoke.toml");
  const auto big = variant(text, "box", 2.0);
  CHECK(big.length_m == Approx(2.0 * base.length_m));
  CHECK(big.height_m == Approx(2.0 * base.height_m));
  CHECK(big.width_m == Approx(base.width_m));
  CHECK(big.particle_count == 4 * base.particle_count);
  CHECK(big.shear.inertial_number ==
        Approx(base.shear.inertial_number));  // I held: the wall moves faster
  CHECK(big.consolidation.max_windows ==
        2 * base.consolidation.max_windows);  // the plate travels twice as far
  CHECK(big.consolidation.window_steps == base.consolidation.window_steps);
  // 12 d50 is the shortest box the scene rules allow (10 d_max = 12 d50): only the height halves
  const auto small = variant(text, "box", 0.5);
  CHECK(small.length_m == Approx(base.length_m));
  CHECK(small.height_m == Approx(0.5 * base.height_m));
  CHECK(small.particle_count == base.particle_count / 2);
}

TEST_CASE(
    "tradeoff knobs: the plate's clamp scales with the height, so a halved truth keeps its free "
    "share",
    "[tradeoff]") {
  const std::string text = io::read_file("data/scenes/truth.toml");
  const auto base = dem::parse_scene(text, "truth.toml");
  REQUIRE(base.plate_clamp_m > 0.0);
  for (double f : {0.5, 2.0}) {
    const auto v = variant(text, "box", f);
    CHECK(v.plate_clamp_m == Approx(f * base.plate_clamp_m));
    CHECK(v.height_m == Approx(f * base.height_m));
  }
}

TEST_CASE(
    "tradeoff variants: base seeds, each knob both ways, refined and coarsened, requirements left "
    "out",
    "[tradeoff]") {
  tradeoff::TradeoffOptions opt;
  opt.scene_file = "data/scenes/default.toml";
  opt.knobs = {"dt", "I"};
  opt.seeds = 3;
  const auto v = tradeoff::expand_variants(opt);
  std::vector<std::string> names;
  for (const auto& x : v) names.push_back(x.job.name);
  // the base and the reference first; then cheapest first (coarsened: dt and I both doubled)
  REQUIRE(names.size() == 9);
  CHECK(std::vector<std::string>(names.begin(), names.begin() + 5) ==
        std::vector<std::string>{"base_s1", "refined", "base_s2", "base_s3", "coarsened"});
  CHECK(std::is_permutation(names.begin() + 5, names.end(),
                            std::vector<std::string>{"dtx0.5", "dtx2", "Ix0.5", "Ix2"}.begin()));
  const auto base = dem::parse_scene(v[0].job.scene_text, "b.toml");
  const auto refined = dem::parse_scene(v[1].job.scene_text, "r.toml");
  // the steps at full speed scale with 1 / (v dt): four times as many; the start-up ramp adds
  // T / 2, and T follows from the specimen (its shear-wave speed), not from v: twice the steps
  const auto ramp_steps = [](const dem::Scene& s) {
    return 0.5 * s.shear.ramp_s / dem::derive(s).dt;
  };
  CHECK(double(dem::derive(refined).shear_steps) - ramp_steps(refined) ==
        Approx(4.0 * (double(dem::derive(base).shear_steps) - ramp_steps(base))).epsilon(1e-3));
  CHECK(ramp_steps(refined) == Approx(2.0 * ramp_steps(base)));
  CHECK(dem::parse_scene(v[3].job.scene_text, "s3.toml").seed == 3);
  for (const auto& x : v) CHECK(dem::parse_scene(x.job.scene_text, "x.toml").requirements.empty());
  opt.seeds = 1;
  CHECK_THROWS_WITH(tradeoff::expand_variants(opt),
                    Catch::Contains("--seeds 1: the noise floor needs at least 2 seeds"));
  CHECK_THROWS_WITH(tradeoff::parse_knob_list("dt,mass"),
                    Catch::Contains("unknown knob 'mass'; the knobs are box, kappa, dt, I"));
}
