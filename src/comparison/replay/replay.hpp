#pragma once
// Drives a continuum model along a DEM run's own path (issue 6): the measured u_x(t) as shear
// through a shear-zone thickness d_s, and in the normal direction the DEM's boundary condition
// (CNL with the measured sigma_n(t), CNS with the scene's K, CV), from the DEM's first state
// (sigma_n, band void ratio as e0).
#include <memory>
#include <string>
#include <vector>

#include "comparison/replay/dem_run.hpp"
#include "driver/element_test.hpp"
#include "models/registry.hpp"

namespace iwb::comparison {

struct Variant {
  std::string label;  // says how kappa_r and d_s were chosen
  std::string model;
  models::ModelInputs inputs;  // parameters and roughness (kappa_r)
  double d_s_mm;
};

struct Replay {
  Variant variant;
  std::string status;  // the driver's status: "complete" or why it stopped
  // at every DEM row reached: the model's response, contract units
  std::vector<double> u_x_mm, tau_kPa, sigma_n_kPa, u_n_mm;
  // the void ratio the model's band gives the DEM's wall zone (common/band_zone.hpp), from the
  // band's own void ratio (quantities.hpp, wall_zone_dilation)
  std::vector<double> e_band;
  double e0 = 0.0;
};

// Largest shear-strain increment of the replay: finer DEM rows are split into this.
inline constexpr double kReplayStrainIncrement = 1e-3;

Replay replay(const DemRun& dem, const Variant& variant, const driver::RunSettings& settings = {});

// The variant's model and its state at the DEM's first row (its sigma_n, the void ratio of its
// wall band); InputError where that state lies outside the model's domain.
struct Start {
  std::unique_ptr<models::Model> model;
  models::StateVector state;
};
Start start_of(const DemRun& dem, const Variant& variant);

// Why the variant cannot start from the DEM's first state; empty where it can.
std::string inadmissible_start(const DemRun& dem, const Variant& variant);

}  // namespace iwb::comparison
