#pragma once
// Fitting kappa_r and d_s of a continuum model to a DEM run (issue 6): least squares on the
// replay's tau(u_x) against the DEM's, with NLopt's bounded derivative-free BOBYQA over
// (kappa_r, ln d_s), through fitting::fit_least_squares (src/fitting/), which also gives the
// Gauss-Newton covariance s^2 (J^T J)^-1 of the residuals at the optimum.
#include <string>

#include "comparison/replay.hpp"

namespace iwb::comparison {

struct FitBounds {
  double kappa_min = models::kKappaRFloor, kappa_max = 1.0;
  double d_s_min_d50 = 1.0, d_s_max_d50 = 40.0;
};

struct FitResult {
  double kappa_r = 0.0, d_s_mm = 0.0;
  double sigma_kappa_r = 0.0, sigma_d_s_mm = 0.0;  // one standard deviation
  double rmse_tau_kPa = 0.0;                        // residual at the optimum
  int evaluations = 0;
  std::string algorithm = "NLopt LN_BOBYQA on (kappa_r, ln d_s), residuals of tau";
  std::string stop_reason;
};

// `start` gives the model, its parameters and the starting kappa_r and d_s.
FitResult fit_kappa_and_ds(const DemRun& dem, const Variant& start, const FitBounds& bounds = {});

}  // namespace iwb::comparison
