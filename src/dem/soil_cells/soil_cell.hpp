#pragma once
// `iwb dem soiltest`: soil element tests on a DEM cell of a scene's grains, without the wall under
// test, into the soil-test contract (src/calibration/README.md) that `iwb calibrate` reads.
//
// The cell is the scene with its geometry replaced: a box periodic in x and y (fixed: zero lateral
// strain) between two rough sawtooth meshes, the bottom one fixed (oedometer) or moved in +x
// (simple shear; back and forth in cyclic shear), the top one servo-controlled (oedometer, CNL) or
// held (CV). Same grains, same contact law (walls carry the grains' friction), same engine inputs:
// LIGGGHTS's consolidate.in (YADE: interface_shear.py's consolidate stage) prepares the specimen at
// the first stress with a preparation friction that sets the density (0: dense, high: loose),
// shear.in (shear) shears it, oedometer.in (oedometer) loads and unloads it in ramped and held
// steps.
#include <string>

#include "dem/run/run.hpp"
#include "soil_test/soil_test.hpp"

namespace iwb::dem {

// kAsScene: prepared with the scene's own [specimen] consolidation_friction, so that the cell has
// the density of the scene's specimen (a soil test to set beside the interface runs of that scene).
enum class SoilDensity { kDense, kLoose, kAsScene };

SoilDensity parse_soil_density(const std::string& text, const std::string& where);
const char* to_string(SoilDensity d);

// Inter-particle friction while the specimen is prepared (consolidated): none for dense, high for
// loose (the scene's own `consolidation_friction` is replaced).
inline constexpr double kDenseConsolidationFriction = 0.0;
inline constexpr double kLooseConsolidationFriction = 1.0;

// The cell: a box periodic in x and y between two rough plates, or periodic in every direction and
// sheared by its own tilt (dem/engines/liggghts/periodic_cell_engine.hpp): no plate, so no band
// next to one (issue 38: the plate cells of 12 d50 localised in ~5.5 d50 at the top plate).
enum class CellKind { kPlates, kPeriodic };

CellKind parse_cell_kind(const std::string& text, const std::string& where);
const char* to_string(CellKind k);

// The cell's boundaries: sawtooth with ridges of 1 d50 at a 2 d50 pitch (R_n = 1), so that the
// first grain layer moves with the boundary (DEM.md: R_n >= 0.5 drags it at 0.9-1.0).
inline constexpr double kCellPitchD50 = 2.0;
inline constexpr double kCellRidgeD50 = 1.0;
// Their ridges meet 1.45 times the grains an interface scene's plate meets per area, and the
// servo's loop gain with them (dem/scene/scene.hpp, servo_loop_number): a 6 d50 cell of the truth's
// grains at 10 kPa chattered from step to step at the interface scenes' default gains.
inline constexpr double kCellPlateLoopFactor = 1.45;

struct SoilCellSpec {
  std::string engine = "liggghts";  // or "yade" (dem/engines/engines.hpp)
  CellKind cell = CellKind::kPlates;
  soil_test::SoilTestKind test = soil_test::SoilTestKind::kOedometer;
  driver::BoundaryKind boundary = driver::BoundaryKind::kCNL;  // simple shear: CNL or CV
  SoilDensity density = SoilDensity::kDense;
  double sigma0_kPa = 0.0;       // 0: 10 kPa (oedometer) or 50 kPa (simple shear)
  double sigma_max_kPa = 400.0;  // oedometer: the largest level
  double gamma = 1.0;            // simple shear: wall travel / target cell height
  // cyclic shear: 0 -> +A -> -A -> 0 `cycles` times, A = gamma_amplitude x target cell height
  double gamma_amplitude = 0.01;
  int cycles = 3;
  double length_d50 = 12.0, width_d50 = 4.0, height_d50 = 10.0;  // the cell (target height)
  double inertial_number = 1e-3;  // simple shear: gamma_dot d50 sqrt(rho / sigma_n)
  int load_levels = 10;           // oedometer: geometric levels from sigma0 to sigma_max ...
  int unload_levels = 5;          // ... and back to sigma0
  int level_windows = 2;          // oedometer: ramp and hold, each this many consolidation windows

  double initial_stress_kPa() const;
};

// The cell's scene text: the scene's [particles], seed and [consolidation] with the cell's
// specimen, boundaries, normal control, shear and outputs (a scene file of its own, validated by
// parse_scene and recorded in the manifest).
std::string cell_scene_text(const std::string& scene_text, const std::string& source,
                            const SoilCellSpec& spec);

// The oedometer's target stresses, kPa: sigma0, the loading levels up to sigma_max, the
// unloading levels down to sigma0.
std::vector<double> oedometer_levels_kPa(const SoilCellSpec& spec);

// Runs the cell into options.out: manifest.json (kind "soiltest", source "dem:<engine>", the
// scene and the cell with their sha256, status), timeseries.csv, for simple shear profiles.csv
// and vtk/, the engine's inputs and logs in <engine>/. --resume continues from the last finished
// stage of the same cell.
RunOutcome run_soil_test(const std::string& scene_text, const std::string& source,
                         const SoilCellSpec& spec, const RunOptions& options);

// A complete simple-shear cell's cell_summary recomputed from its committed files (the cell's
// scene in the manifest, timeseries.csv, profiles.csv) and written back into its manifest: what
// `iwb dem summary` does for an interface run. InputError for anything else.
nlohmann::json resummarize_cell(const std::filesystem::path& dir);

}  // namespace iwb::dem
