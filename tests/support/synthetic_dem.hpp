#pragma once
// A "DEM" run directory written from a continuum element test: the contract's files with the
// model's curves, so that the comparison chain (compare, hypotheses, report) runs without an
// engine. The shear zone of thickness d_s gives the velocity profile (linear drop over d_s at the
// wall, or over the whole specimen for distributed shear), and summary.json is computed from the
// files by the DEM layer's own summarize().
#include <fmt/core.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <random>

#include "common/band_zone.hpp"
#include "dem/analysis/summary.hpp"
#include "io/run_directory.hpp"
#include "support/fixtures.hpp"

namespace iwb::test {

struct SyntheticDem {
  std::string name;
  driver::BoundaryCondition bc{driver::BoundaryKind::kCNL, 0.0};
  double K_per_mm = 0.0;  // CNS, for the manifest
  double kappa_r = 1.0;   // of the generating model
  double d_s_mm = 1.0;    // shear-zone thickness: u_x = gamma d_s, u_n = eps_n d_s
  double R_n = 1.0;
  double d50_mm = 0.2;
  double gamma = 0.5;        // the shear strain at the end: u_x = gamma d_s
  bool distributed = false;  // velocity profile over the whole specimen instead of a wall band
  int increments = 250;
  int output_every = 5;
  // Seed noise: each row's tau and u_n plus Gaussian noise of these SDs, drawn with `seed`
  // (runs that differ only in the seed are seeds of one scene to the comparison layer).
  int seed = 0;
  double tau_noise_kPa = 0.0, u_n_noise_mm = 0.0;
  // tau written times this: a "DEM" the generating model's form cannot follow (1: its own curve)
  double tau_scale = 1.0;
};

inline constexpr double kSyntheticHeightD50 = 20.0;  // specimen height of the synthetic profile

// profiles.csv: one window at the last u_x, bins of d50 / 2 up to kSyntheticHeightD50.
inline std::string synthetic_profile(const SyntheticDem& s, double u_x_end_mm) {
  const double band = s.distributed ? kSyntheticHeightD50 : s.d_s_mm / s.d50_mm;
  std::string p = "u_x_mm_window,z_over_d50,vx_over_vwall,porosity,sigma_zz_kPa,tau_zx_kPa\n";
  for (double z = 0.25; z < kSyntheticHeightD50; z += 0.5)
    p += fmt::format("{:.6g},{:.6g},{:.6g},0.4,100,50\n", u_x_end_mm, z,
                     std::max(0.0, 1.0 - z / band));
  return p;
}

// The contract's e_band (common/band_zone.hpp) of a band of thickness d_s and void ratio e at the
// bottom of a zone of height h, from the band's own void ratio: its grains' volume d_s / (1 + e0)
// now fills d_s (1 + e) / (1 + e0); above it, up to h, the grains at e0 that the band did not
// push out of the zone; a band thicker than the zone fills it at its own e. (Written from the
// solid volumes, apart from the replay's own zone_void_ratio, which the comparison tests check.)
inline double zone_void_ratio(double e0, double e, double d_s, double h) {
  const double band = d_s * (1.0 + e) / (1.0 + e0);
  if (band >= h) return e;
  const double solid = d_s / (1.0 + e0) + (h - band) / (1.0 + e0);
  return h / solid - 1.0;
}

inline std::filesystem::path write_synthetic_dem(const SyntheticDem& spec) {
  ShearSpec s;
  s.e0 = 0.70;
  s.bc = spec.bc;
  s.inputs = table_5_1(spec.kappa_r);
  s.gamma = spec.gamma;
  s.increments = spec.increments;
  s.output_every = spec.output_every;
  const auto run = shear(s);
  REQUIRE(run.result.complete());
  const std::filesystem::path dir =
      std::filesystem::path(IWB_TEST_RUNS_DIR) / "comparison" / spec.name;
  std::filesystem::create_directories(dir);
  std::string ts = "t_s,u_x_mm,u_n_mm,sigma_n_kPa,tau_kPa,e_specimen,e_band,coordination\n";
  std::mt19937 random(std::uint32_t(spec.seed));
  std::normal_distribution<double> noise(0.0, 1.0);
  for (std::size_t i = 0; i < run.result.rows.size(); ++i) {
    const auto& r = run.result.rows[i];
    const auto st = run.model->stress(r.state);
    const double e = run.model->void_ratio(r.state);
    const double e_zone = zone_void_ratio(
        s.e0, e, spec.d_s_mm, wall_zone_thickness(spec.d50_mm, kSyntheticHeightD50 * spec.d50_mm));
    const double dtau = i == 0 ? 0.0 : spec.tau_noise_kPa * noise(random);
    const double dun = i == 0 ? 0.0 : spec.u_n_noise_mm * noise(random);
    ts += fmt::format("{},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},4\n", 0.01 * double(i),
                      r.gamma_x * spec.d_s_mm, r.eps_n * spec.d_s_mm + dun, st.sigma_n,
                      spec.tau_scale * st.tau_x + dtau, e, e_zone);
  }
  io::write_atomically(dir / "timeseries.csv", ts);
  io::write_atomically(dir / "profiles.csv",
                       synthetic_profile(spec, run.result.rows.back().gamma_x * spec.d_s_mm));
  const nlohmann::json m = {{"status", "complete"},
                            {"engine", {{"name", "synthetic"}}},
                            {"R_n", spec.R_n},
                            {"scene",
                             {{"resolved",
                               {{"boundary",
                                 {{"type", driver::to_string(spec.bc.kind)},
                                  {"sigma_n_kPa", 100.0},
                                  {"K_kPa_per_mm", spec.K_per_mm}}},
                                {"particles", {{"d50_mm", spec.d50_mm}}},
                                {"specimen", {{"height_mm", kSyntheticHeightD50 * spec.d50_mm}}},
                                {"seed", spec.seed},
                                {"generator",
                                 {{"kappa_r", spec.kappa_r},
                                  {"d_s_mm", spec.d_s_mm},
                                  {"R_n", spec.R_n},
                                  {"distributed", spec.distributed},
                                  {"increments", spec.increments}}}}}}}};
  io::write_manifest(dir, m);
  dem::Scene scene{};
  scene.boundary.sigma_n_Pa = 100e3;
  const auto summary = dem::summarize(scene, io::read_csv_table(dir / "timeseries.csv"),
                                      io::read_csv_table(dir / "profiles.csv"));
  io::write_atomically(dir / "summary.json", dem::to_json(summary).dump(2) + "\n");
  return dir;
}

}  // namespace iwb::test
