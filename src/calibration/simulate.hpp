#pragma once
// A continuum model driven along a soil test's own control (the measured sigma_v or gamma, row by
// row) from the test's initial state, through the element-test driver. Used both to make
// synthetic soil tests and to compare a trial parameter set with measured ones.
#include <string>
#include <vector>

#include "models/registry.hpp"
#include "soil_test/soil_test.hpp"

namespace iwb::calibration {

struct Simulated {
  // At every row reached (the first is the initial state); measured quantities of the contract.
  std::vector<double> e, eps_v, tau_kPa, sigma_n_kPa;
  std::string status = "complete";  // the driver's, or why the initial state was refused
  std::size_t rows() const { return e.size(); }
};

// Runs `model_name` with `inputs` along `test.control`. Never throws for a parameter set the
// model refuses (inadmissible initial state, domain left on the way): the status says why and
// the rows stop there, which the calibration penalises.
Simulated simulate(const soil_test::SoilTest& test, const std::string& model_name,
                   const models::ModelInputs& inputs);

// Initial lateral stress ratio of `test` under `inputs`: the test's K0, or 1 - sin(phi_c).
double initial_K0(const soil_test::SoilTest& test, const std::string& model_name,
                  const models::ModelInputs& inputs);

}  // namespace iwb::calibration
