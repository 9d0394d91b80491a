#include "column/column_scene.hpp"

#include <fmt/core.h>

#include <cmath>

#include "common/band_zone.hpp"
#include "common/errors.hpp"
#include "io/csv_table.hpp"
#include "models/roughness/roughness.hpp"

namespace iwb::column {

ColumnWall wall_from_roughness(double R_n, double phi_c) {
  if (R_n >= 0.5) return {WallRotation::kFree, std::numeric_limits<double>::infinity()};
  // eq. 5.35 clamps kappa_r at 0.05 below R_n ~ 1e-4 (the flat wall): its warning is the
  // column's README's statement that the map means nothing there
  const double kappa_r = models::kappa_r_from_normalized_roughness(std::max(R_n, 1e-12)).value;
  const double phi_r = std::asin(kappa_r * std::sin(phi_c));
  return {WallRotation::kFree, models::simple_shear_critical_ratio(phi_r)};
}

ColumnSpec on_scene(ColumnSpec spec, const dem::Scene& scene, double elements_per_d50) {
  if (scene.shear.cyclic())
    throw InputError(fmt::format("{}: a cyclic scene; the column shears one way", scene.source));
  const double d50_mm = scene.particles.d50_m * 1e3;
  spec.d50_mm = d50_mm;
  spec.height_mm = (scene.height_m - scene.plate_clamp_m) * 1e3;
  spec.elements = std::max(2, int(std::lround(spec.height_mm / d50_mm * elements_per_d50)));
  spec.sigma_n0_kPa = scene.boundary.sigma_n_Pa * 1e-3;
  spec.top = scene.boundary.kind == driver::BoundaryKind::kCNS
                 ? TopBoundary::kCNS
                 : (scene.boundary.kind == driver::BoundaryKind::kCV ? TopBoundary::kCV
                                                                     : TopBoundary::kCNL);
  spec.stiffness_kPa_per_mm = scene.boundary.K_Pa_per_m * 1e-6;
  spec.travel_mm = scene.shear.travel_m() * 1e3;
  spec.wall_zone_mm = wall_zone_thickness(scene.particles.d50_m, scene.height_m) * 1e3;
  const auto wall =
      wall_from_roughness(scene.wall.normalized_roughness(scene.particles.d50_m), spec.soil.phi_c);
  spec.wall_rotation = wall.rotation;
  spec.wall_friction = wall.friction;
  return spec;
}

double start_void_ratio(const std::vector<std::filesystem::path>& runs) {
  double sum = 0.0;
  for (const auto& r : runs) {
    const auto t = io::read_csv_table(r / "timeseries.csv");
    const auto e = t.values("e_specimen", (r / "timeseries.csv").string());
    if (e.empty()) throw InputError(fmt::format("{}: no rows in timeseries.csv", r.string()));
    sum += e.front();
  }
  return sum / double(runs.size());
}

std::vector<double> profile_windows(const std::filesystem::path& run, double travel_mm) {
  const auto path = run / "profiles.csv";
  if (!std::filesystem::exists(path)) return {};
  const auto u = io::read_csv_table(path).values("u_x_mm_window", path.string());
  std::vector<double> at;
  for (double x : u)
    if (x > 0.0 && x <= travel_mm && (at.empty() || x > at.back())) at.push_back(x);
  return at;
}

}  // namespace iwb::column
