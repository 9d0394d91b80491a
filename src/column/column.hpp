#pragma once
// A column of micro-polar hypoplastic soil sheared by a wall (issue 57): the specimen's height
// between the wall and the plate's clamp in linear elements, each node carrying u1 (along the
// wall's travel), u2 (normal, dilation positive) and the grains' rotation w; the law at one point
// per element (polar_law.hpp). Quasi-static and implicit: every increment of the wall's travel is
// solved by Newton's method on the nodal increments, the law integrated over it in explicit
// midpoint substeps. Equations, boundary conditions and sources: src/column/README.md.
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "column/polar_law.hpp"
#include "models/hypoplastic/parameters.hpp"

namespace iwb::column {

enum class TopBoundary { kCNL, kCNS, kCV };
enum class WallRotation {
  kFixed,  // w = 0: the grains at the wall are locked between its asperities (a rough wall)
  kFree,   // m = 0: the grains at the wall turn freely (a smooth wall)
};

struct ColumnSpec {
  models::HypoplasticParameters soil;
  double height_mm = 28.0;  // free soil between the wall and the clamp under the plate
  double d50_mm = 2.0;
  int elements = 56;
  double e0 = 0.65;
  double sigma_n0_kPa = 50.0;
  TopBoundary top = TopBoundary::kCNL;
  double stiffness_kPa_per_mm = 0.0;  // CNS: d sigma_n = K d u_n
  WallRotation wall_rotation = WallRotation::kFree;
  // The wall's friction tan(delta) on the soil: the wall slips under the soil where |tau| reaches
  // it times sigma_n; infinite: no slip.
  double wall_friction = std::numeric_limits<double>::infinity();
  bool polar = true;          // false: the plain model (no rotations, no couple stress)
  double imperfection = 0.0;  // relative raise of e0 in the element at the wall
  double travel_mm = 10.0;
  int increments = 2000;
  int profiles = 5;  // profiles at the ends of this many equal windows of the travel, unless:
  // profiles at the first increment's end at or past each of these travels (mm, ascending), and
  // at the end: a DEM run's windows, for the column's profiles to be set beside its own
  std::vector<double> profile_at_mm;
  // The wall zone whose void ratio the time series gives (e_wall_zone): the DEM's on a scene
  // (on_scene: common/band_zone.hpp's rule on the specimen), else 0: the rule on the column
  double wall_zone_mm = 0.0;
  double substep_strain = 2e-4;  // the law's substeps: at most this much ||D^c|| each
};

// One increment's end: the wall's travel, tau (on the soil, positive along the travel),
// sigma_n (compression positive), u_n (the plate's rise, dilation positive), the wall's slip, and
// the void ratio of the wall zone (voids over solids of the soil within wall_zone_mm of the wall
// in the deformed column, as the DEM's e_band is measured in a zone of fixed height).
struct ColumnRow {
  double u_mm, tau_kPa, sigma_n_kPa, u_n_mm, slip_mm, e_wall_zone;
};

// A profile over the height at an increment's end, per element centre: the increment's velocity
// and spin scaled by the wall's (vx / v_wall, w d50 / v_wall), the shear rate (du1/dy d50 /
// v_wall, magnitude), the void ratio and the stresses (kPa; m in kPa mm); the element centres'
// heights in the deformed column, its lengths those the increment's gradients were taken over.
struct ColumnProfile {
  double u_mm;
  std::vector<double> z_over_d50, vx_over_vwall, spin, shear_rate, e, tau_kPa, T21_kPa,
      sigma_zz_kPa, m_kPa_mm, length_mm;
};

struct ColumnResult {
  std::vector<ColumnRow> rows;
  std::vector<ColumnProfile> profiles;
  std::string status = "complete";  // or why the run stopped, and where
  int newton_iterations = 0;
  int cutbacks = 0;
};

// InputError where the spec cannot start: too few elements, non-positive sizes, e0 outside the
// soil's limits e_d .. e_i at sigma_n0.
void require_spec(const ColumnSpec& spec);

// The zone whose void ratio the rows give: spec.wall_zone_mm, or the DEM's rule on the column.
double wall_zone_of(const ColumnSpec& spec);

// progress(increment done, increments in all)
ColumnResult run_column(const ColumnSpec& spec,
                        const std::function<void(long, long)>& progress = {});

// The band of a profile as the DEM's are measured (coarse_graining/band_measures.hpp): the full
// width at half maximum of the shear rate over the whole height, and the velocity's 0.9 -> 0.1
// width from the wall up, both in d50.
struct BandWidths {
  double fwhm_d50, velocity_d50;
};
BandWidths band_widths(const ColumnProfile& p);

}  // namespace iwb::column
