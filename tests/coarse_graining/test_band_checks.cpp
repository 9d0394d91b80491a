// The momentum-balance checks on constructed profiles: in the free soil between the wall and the
// plate no force but the contacts' acts along x, so sigma_xz is uniform there and equals the
// wall's tau; under the plate's clamp an external force holds the grains and carries part of the
// shear (seen in the truth runs: sigma_xz falls from the wall's 16 kPa to ~2 kPa inside the clamp).
#include <catch2/catch.hpp>
#include <string>

#include "coarse_graining/band_checks.hpp"
#include "io/run_directory.hpp"

using namespace iwb;

namespace {

constexpr double kTauPa = 16e3, kSigmaPa = 50e3, kTopD50 = 20.0;

dem::Scene truth() { return dem::parse_scene(io::read_file("data/scenes/truth.toml"), "truth.toml"); }

// A specimen of solid fraction 0.6 from the wall's mean height to kTopD50; sigma_xz is tau_free up
// to z_drop (in d50) and tau_above beyond it.
io::CsvTable profile(double z_drop, double tau_above) {
  io::CsvTable t;
  t.columns = {"z_over_d50", "solid_fraction", "velocity_x_m_s", "shear_rate_dvx_dz_1_s", "stress_xz_Pa", "stress_zz_Pa"};
  for (double z = -3.0; z <= kTopD50 + 3.0; z += 0.25) {
    const bool solid = z >= 0.0 && z <= kTopD50;
    t.rows.push_back({z, solid ? 0.6 : 0.0, 0.0, 0.0, solid ? (z < z_drop ? kTauPa : tau_above) : 0.0, solid ? kSigmaPa : 0.0});
  }
  return t;
}

io::CsvTable series() {
  io::CsvTable t;
  t.columns = {"t_s", "u_x_mm", "tau_kPa", "sigma_n_kPa", "e_band"};
  t.rows = {{0.0, 0.0, kTauPa / 1e3, kSigmaPa / 1e3, 0.65}, {1.0, 10.0, kTauPa / 1e3, kSigmaPa / 1e3, 0.65}};
  return t;
}

bool passed(const coarse_graining::BandChecks& c, const std::string& name) {
  for (const auto& check : c.json["checks"])
    if (check["name"] == name) return check["passed"].get<bool>();
  FAIL("no check named " << name);
  return false;
}

coarse_graining::BandChecks checks_of(const dem::Scene& s, const io::CsvTable& p) {
  const double d50 = s.particles.d50_m;
  const double grains = 0.6 * kTopD50 * d50 * s.area_m2();
  return coarse_graining::band_checks(s, dem::derive(s), series(), nlohmann::json::object(), {{0.0, p, grains}, {1.0, p, grains}},
                                      0.5 * d50);
}

}  // namespace

TEST_CASE("the clamp's held grains are not in the momentum balance's interior", "[coarse_graining]") {
  const auto s = truth();
  REQUIRE(s.plate_clamp_m / s.particles.d50_m == Approx(6.0));
  const double plate_tips = kTopD50 - 1.5;  // the truth's plate teeth are 1.5 d50 high
  const double clamp_edge = plate_tips - 6.0;
  // The shear carried by the clamp from its lower edge up: the free soil below still balances.
  const auto clamped = checks_of(s, profile(clamp_edge, 2e3));
  CHECK(passed(clamped, "shear_stress_uniform"));
  CHECK(passed(clamped, "shear_stress_equals_wall"));
  CHECK(passed(clamped, "normal_stress_equals_wall"));
  // The same profile without a clamp is a broken balance, and it is caught.
  auto unclamped = s;
  unclamped.plate_clamp_m = 0.0;
  CHECK_FALSE(passed(checks_of(unclamped, profile(clamp_edge, 2e3)), "shear_stress_uniform"));
  // A drop 3 d50 below the clamp's edge is in the free soil: still caught with the clamp.
  CHECK_FALSE(passed(checks_of(s, profile(clamp_edge - 3.0, 2e3)), "shear_stress_uniform"));
}
