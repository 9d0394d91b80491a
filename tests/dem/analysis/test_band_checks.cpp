// The momentum-balance and band checks on constructed profiles: in the free soil between the wall
// and the plate no force but the contacts' acts along x, so sigma_xz is uniform there and equals
// the wall's tau; under the plate's clamp an external force holds the grains and carries part of
// the shear (seen in the truth runs: sigma_xz falls from the wall's 16 kPa to ~2 kPa inside the
// clamp).
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "dem/analysis/band_checks.hpp"
#include "io/run_directory.hpp"

using namespace iwb;

namespace {

constexpr double kTauPa = 16e3, kSigmaPa = 50e3, kTopD50 = 20.0;

dem::Scene truth() {
  return dem::parse_scene(io::read_file("data/scenes/truth.toml"), "truth.toml");
}

// A specimen of solid fraction 0.6 from the wall's mean height to kTopD50; sigma_xz is tau_free up
// to z_drop (in d50) and tau_above beyond it.
io::CsvTable profile(double z_drop, double tau_above) {
  io::CsvTable t;
  t.columns = {"z_over_d50",   "solid_fraction", "velocity_x_m_s", "shear_rate_dvx_dz_1_s",
               "stress_xz_Pa", "stress_zz_Pa"};
  for (double z = -3.0; z <= kTopD50 + 3.0; z += 0.25) {
    const bool solid = z >= 0.0 && z <= kTopD50;
    t.rows.push_back({z, solid ? 0.6 : 0.0, 0.0, 0.0,
                      solid ? (z < z_drop ? kTauPa : tau_above) : 0.0, solid ? kSigmaPa : 0.0});
  }
  return t;
}

io::CsvTable series() {
  io::CsvTable t;
  t.columns = {"t_s", "u_x_mm", "tau_kPa", "sigma_n_kPa", "e_band"};
  t.rows = {{0.0, 0.0, kTauPa / 1e3, kSigmaPa / 1e3, 0.65},
            {1.0, 10.0, kTauPa / 1e3, kSigmaPa / 1e3, 0.65}};
  return t;
}

bool passed(const dem::BandChecks& c, const std::string& name) {
  for (const auto& check : c.json["checks"])
    if (check["name"] == name) return check["passed"].get<bool>();
  FAIL("no check named " << name);
  return false;
}

dem::BandChecks checks_of(const dem::Scene& s, const io::CsvTable& p,
                          const coarse_graining::BinnedProfile& grain_velocity = {}) {
  const double d50 = s.particles.d50_m;
  const double grains = 0.6 * kTopD50 * d50 * s.area_m2();
  return dem::band_checks(s, dem::derive(s), series(),
                          {{0.0, p, grains, grain_velocity}, {1.0, p, grains, grain_velocity}},
                          0.5 * d50);
}

// v / v_wall of an erfc band of standard deviation sigma centred 8 d50 above the wall (1 there).
double erfc_band(double z, double sigma) {
  return 0.5 * std::erfc((z - 8.0) / (sigma * std::sqrt(2.0)));
}

// The profile's coarse-grained velocity is an erfc band of sigma.
io::CsvTable with_band(io::CsvTable t, const dem::Scene& s, double sigma) {
  const auto z = t.column("z_over_d50"), v = t.column("velocity_x_m_s");
  for (auto& row : t.rows) row[v] = erfc_band(row[z], sigma) * s.shear.velocity_m_s;
  return t;
}

// The grains of the same instant binned by centre (0.5 d50) from an erfc band of sigma.
coarse_graining::BinnedProfile grains_with_band(double sigma) {
  coarse_graining::BinnedProfile b;
  for (double z = 0.25; z < kTopD50; z += 0.5)
    b.z.push_back(z), b.mean.push_back(erfc_band(z, sigma));
  return b;
}

const nlohmann::json& check_named(const dem::BandChecks& c, const std::string& name) {
  for (const auto& check : c.json["checks"])
    if (check["name"] == name) return check;
  FAIL("no check named " << name);
  return c.json;
}

}  // namespace

TEST_CASE("the clamp's held grains are not in the momentum balance's interior",
          "[coarse_graining]") {
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

TEST_CASE("the band check compares the coarse-grained width with the same snapshot's grains",
          "[coarse_graining]") {
  const auto s = truth();
  const double w = 0.5;  // checks_of's kernel width, d50: it convolves the grains' erfc band of
                         // sigma into one of sqrt(sigma^2 + w^2)
  auto value = [&](double sigma_field, double sigma_grains) {
    const auto c = checks_of(s, with_band(profile(kTopD50, kTauPa), s, sigma_field),
                             grains_with_band(sigma_grains));
    return std::make_pair(check_named(c, "band_thickness_agrees")["value"].get<double>(),
                          passed(c, "band_thickness_agrees"));
  };
  // a narrow band (0.3 d50 in the grains): smeared to 0.58 d50, 1.49 d50 wide against the grains'
  // 0.77; the check expects the smear (within the 0.5 d50 bins' interpolation)
  const auto narrow = value(std::sqrt(0.3 * 0.3 + w * w), 0.3);
  CHECK(narrow.first == Approx(0.0).margin(0.15));
  CHECK(narrow.second);
  // a 2 d50 band seen through the kernel: as expected
  CHECK(value(std::sqrt(4.0 + w * w), 2.0).first == Approx(0.0).margin(0.1));
  // grains whose band is 3.5 d50 against a field of 2 d50: 2.563 x (3.536 - 2.062) = 3.78 d50 off,
  // caught
  const auto wider = value(std::sqrt(4.0 + w * w), 3.5);
  CHECK(wider.first == Approx(3.78).margin(0.1));
  CHECK_FALSE(wider.second);
}
