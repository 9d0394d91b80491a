#pragma once
// Synthetic soil tests: the contract filled by a continuum model with known parameters, the
// target on which a calibration must find those parameters again (`iwb soiltest synthetic`).
#include <optional>
#include <string>

#include "calibration/simulate.hpp"

namespace iwb::calibration {

struct SyntheticSpec {
  std::string model = "vw3d";
  soil_test::SoilTestKind kind = soil_test::SoilTestKind::kOedometer;
  driver::BoundaryKind boundary = driver::BoundaryKind::kCNL;  // simple shear
  std::optional<double> e0;  // default: the critical void ratio at the initial mean stress
  double sigma0_kPa = 100.0;
  // oedometer: loading to sigma_max in geometric steps, then unloading to sigma_end (none if
  // sigma_end >= sigma_max)
  double sigma_max_kPa = 2000.0;
  double sigma_end_kPa = 100.0;
  double gamma_max = 1.0;  // simple shear: monotonic to this engineering shear strain
  // cyclic shear: 0 -> +A -> -A -> 0 `cycles` times, A = gamma_amplitude
  double gamma_amplitude = 0.01;
  int cycles = 3;
  int rows = 40;  // data rows per branch (cyclic: per quarter cycle)
};

// The test `spec` describes, run through `spec.model` with `inputs`; source "synthetic:<model>"
// and the parameters in source_parameters. InputError if the model refuses the initial state or
// the run does not complete (a synthetic target must be whole).
soil_test::SoilTest synthesise(const SyntheticSpec& spec, const models::ModelInputs& inputs);

// `iwb soiltest synthetic`: the test of `spec` with the parameter file `params`, written to the
// run directory `out` (write_soil_test) with the command line and the file's sha256 in its
// manifest; returns the test written.
soil_test::SoilTest write_synthetic_test(const SyntheticSpec& spec, const std::string& params,
                                         const std::string& out, bool force,
                                         const std::string& command_line);

}  // namespace iwb::calibration
