// Scene files: refused before any engine starts, with file, key and value; derived geometry.
#include <catch2/catch.hpp>
#include <fstream>

#include "common/errors.hpp"
#include "dem/numerics.hpp"
#include "dem/scene.hpp"
#include "io/run_directory.hpp"

using namespace iwb;

namespace {
std::string smoke() { return io::read_file("data/scenes/smoke.toml"); }

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto p = text.find(from);
  REQUIRE(p != std::string::npos);
  return text.replace(p, from.size(), to);
}

std::string error_of(const std::string& text) {
  try {
    dem::parse_scene(text, "scene.toml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}
}  // namespace

TEST_CASE("the smoke scene resolves R_n, particle sizes and the inertial number", "[dem]") {
  const auto s = dem::parse_scene(smoke(), "data/scenes/smoke.toml");
  CHECK(s.wall.normalized_roughness(s.particles.d50_m) == Approx(0.5));
  CHECK(s.plate.normalized_roughness(s.particles.d50_m) == Approx(1.0));
  CHECK(s.particles.d_max() == Approx(2.4e-3));
  CHECK(s.shear.inertial_number == Approx(1e-3));
  CHECK(s.particle_count == 400);
  CHECK(s.warnings.size() == 1);  // 8 d50 is too low for a band
}

TEST_CASE("cyclic shear: a triangle wave 0 -> +A -> -A -> 0 and its travel", "[dem]") {
  const auto s = dem::parse_scene(io::read_file("data/scenes/smoke_cyclic.toml"), "smoke_cyclic.toml");
  const auto& sh = s.shear;
  REQUIRE(sh.cyclic());
  const double T = sh.amplitude_m / sh.velocity_m_s;  // a quarter cycle
  CHECK(sh.displacement_at(0.0) == Approx(0.0).margin(1e-15));
  CHECK(sh.displacement_at(T) == Approx(sh.amplitude_m));
  CHECK(sh.displacement_at(2 * T) == Approx(0.0).margin(1e-12));
  CHECK(sh.displacement_at(3 * T) == Approx(-sh.amplitude_m));
  CHECK(sh.displacement_at(4.5 * T) == Approx(0.5 * sh.amplitude_m));
  CHECK(sh.travel_m() == Approx(4 * 0.5e-3 * 2));
  CHECK_THAT(error_of(replaced(io::read_file("data/scenes/smoke_cyclic.toml"), "cycles = 2\n", "")),
             Catch::Contains("key 'shear.cycles' is missing"));
}

TEST_CASE("R_n over a gauge length of d50 for sawtooth and sinusoid walls", "[dem]") {
  dem::RoughnessProfile saw{dem::ProfileKind::kSawtooth, 4e-3, 1e-3};
  CHECK(saw.normalized_roughness(2e-3) == Approx(0.5));   // the window spans a full rise
  CHECK(saw.normalized_roughness(1e-3) == Approx(0.5));   // half the rise in half the length
  dem::RoughnessProfile sine{dem::ProfileKind::kSinusoid, 8e-3, 1e-3};
  CHECK(sine.normalized_roughness(2e-3) == Approx(1e-3 * std::sin(M_PI / 4) / 2e-3));
  CHECK(dem::RoughnessProfile{}.normalized_roughness(2e-3) == 0.0);
}

TEST_CASE("glued walls: R_n from the sampled sphere profile, spacing checked in x and y", "[dem]") {
  dem::RoughnessProfile touching{dem::ProfileKind::kGlued, 2e-3, 2e-3};
  CHECK(touching.normalized_roughness(2e-3) == Approx(0.5).epsilon(1e-3));  // valleys at the equator
  dem::RoughnessProfile sparse{dem::ProfileKind::kGlued, 4e-3, 2e-3};
  CHECK(sparse.normalized_roughness(2e-3) == Approx(1.0).epsilon(1e-3));    // the flat base shows
  CHECK(touching.mean_height_m() > 0.5 * 2e-3);
  CHECK(touching.mean_height_m() < 2e-3);
  const std::string glued = io::read_file("data/scenes/smoke_glued.toml");
  CHECK(dem::parse_scene(glued, "g.toml").wall.normalized_roughness(2e-3) == Approx(0.5).epsilon(1e-3));
  CHECK_THAT(error_of(replaced(glued, "spacing_d50 = 1.0", "spacing_d50 = 1.5")),
             Catch::Contains("key 'wall.spacing_d50' = 1.5 does not divide the box width 4 d50"));
  CHECK_THAT(error_of(replaced(smoke(), "[plate]\nprofile = \"sawtooth\"\npitch_d50 = 2\nheight_d50 = 1.0",
                               "[plate]\nprofile = \"glued\"\nsphere_d50 = 1\nspacing_d50 = 1")),
             Catch::Contains("key 'plate.profile' = \"glued\""));
}

TEST_CASE("broken scenes are refused with file, key and value", "[dem]") {
  CHECK_THAT(error_of(replaced(smoke(), "d50_mm = 2.0\n", "")),
             Catch::Contains("scene.toml: key 'particles.d50_mm' is missing"));
  CHECK_THAT(error_of(replaced(smoke(), "d50_mm = 2.0", "d50_mm = -2.0")),
             Catch::Contains("scene.toml: key 'particles.d50_mm' = -2 is out of range; allowed (0, inf)"));
  CHECK_THAT(error_of(replaced(smoke(), "length_d50 = 12", "length_d50 = 10")),
             Catch::Contains("scene.toml: key 'specimen.length_d50' = 10") &&
                 Catch::Contains("shorter than 10 d_max = 24 mm"));
  CHECK_THAT(error_of(replaced(replaced(smoke(), "pitch_d50 = 2\n", "pitch_d50 = 5\n"), "length_d50 = 12", "length_d50 = 12")),
             Catch::Contains("scene.toml: key 'wall.pitch_d50' = 5 does not divide the box length 12 d50"));
  CHECK_THAT(error_of(replaced(smoke(), "type = \"CNL\"", "type = \"CNS\"")),
             Catch::Contains("scene.toml: key 'boundary.K_kPa_per_mm' is missing"));
  CHECK_THAT(error_of(replaced(smoke(), "mass_fraction = [0.25, 0.5, 0.25]", "mass_fraction = [0.25, 0.5, 0.3]")),
             Catch::Contains("mass_fraction sums to 1.05"));
  CHECK_THAT(error_of(replaced(smoke(), "profile = \"sawtooth\"", "profile = \"knurled\"")),
             Catch::Contains("key 'wall.profile' = \"knurled\"; allowed \"flat\", \"sawtooth\", \"sinusoid\""));
  CHECK_THAT(error_of(smoke() + "\n[shaer]\nx = 1\n"), Catch::Contains("key 'shaer' is not a known key"));
}

TEST_CASE("numerics dt_fraction sets the timestep as a fraction of the Rayleigh time, validated", "[dem]") {
  const auto base = dem::parse_scene(smoke(), "scene.toml");
  const auto finer = dem::parse_scene(smoke() + "\n[numerics]\ndt_fraction = 0.075\n", "scene.toml");
  CHECK(base.dt_fraction == 0.15);
  CHECK(dem::derive(finer).dt == Approx(0.5 * dem::derive(base).dt).epsilon(1e-12));
  CHECK(dem::derive(base).dt == Approx(0.15 * dem::rayleigh_time(base.particles)).epsilon(1e-12));
  CHECK_THAT(error_of(smoke() + "\n[numerics]\ndt_fraction = 0.8\n"),
             Catch::Contains("scene.toml: key 'numerics.dt_fraction' = 0.8 is out of range; allowed (0, 0.5]"));
  CHECK_THAT(error_of(smoke() + "\n[numerics]\ndt_fraction = -0.1\n"),
             Catch::Contains("key 'numerics.dt_fraction' = -0.1 is out of range"));
}

TEST_CASE("requirements name quantities of interest with tolerances or not needed", "[dem]") {
  const auto s = dem::parse_scene(smoke() + "\n[requirements]\nresidual_friction = 0.05\npeak_friction = 0.1\n"
                                            "band_thickness = \"not needed\"\n", "scene.toml");
  REQUIRE(s.requirements.size() == 3);
  CHECK(*s.requirements.at("residual_friction") == 0.05);
  CHECK(*s.requirements.at("peak_friction") == 0.1);
  CHECK_FALSE(s.requirements.at("band_thickness").has_value());
  CHECK(dem::parse_scene(smoke(), "scene.toml").requirements.empty());
  CHECK_THAT(error_of(smoke() + "\n[requirements]\nresidual_fricton = 0.05\n"),
             Catch::Contains("scene.toml: key 'requirements.residual_fricton' is not a known key (value 0.05") &&
                 Catch::Contains("peak_friction, residual_friction, dilation_rate, band_thickness"));
  CHECK_THAT(error_of(smoke() + "\n[requirements]\npeak_friction = 1.5\n"),
             Catch::Contains("scene.toml: key 'requirements.peak_friction' = 1.5: a tolerance is a number in (0, 1]"));
  CHECK_THAT(error_of(smoke() + "\n[requirements]\ndilation_rate = 0\n"),
             Catch::Contains("key 'requirements.dilation_rate' = 0: a tolerance"));
  CHECK_THAT(error_of(smoke() + "\n[requirements]\ndilation_rate = \"roughly\"\n"),
             Catch::Contains("key 'requirements.dilation_rate' = \"roughly\": a tolerance is a number in (0, 1] "
                             "(0.05 = 5 %) or \"not needed\""));
}
