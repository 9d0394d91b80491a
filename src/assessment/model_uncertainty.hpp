#pragma once
// Model uncertainty against reference data (issue 17; seed 4.2.1 and 4.3.3): a model's response
// compared with the reference's at a few states of the test, the seed's "multi-point objective
// function". Per point k (eq. 4.3)
//     UA_k = |Y_model - Y_ref| / (1.645 |Y_ref|),
// 1.645 being the standard normal's 95 % quantile, and per test the norm over its points
// (eq. 4.15, read as sqrt(sum UA_k^2): the print lost the squares as eq. 4.4's did, ERRATA 16).
// The global uncertainty is sqrt(UA_model^2 + UA_par^2) (eq. 4.4 with ERRATA 16).
//
// The seed judges the shear stress only (its 4.4: "unnecessary to use the framework twice"). The
// workbench's verdicts judge shear and dilation alike (issue 14), so a second set of points takes
// the free normal quantity: u_n under CNL and CNS, sigma_n under CV. Pure numerics over curves.
#include <string>
#include <vector>

namespace iwb::assessment {

// A response along the travelled displacement: u_x (mm), tau (kPa) and the free normal quantity's
// change from the first row (u_n in mm, or sigma_n in kPa under CV).
struct ResponseCurve {
  std::vector<double> u_x, tau, normal;
};

struct ObjectivePoint {
  std::string
      name;  // "hardening", "peak", "softening", "residual"; "normal at peak", "normal at end"
  double u_x = 0.0;  // where it is read on the reference (the peak: each curve's own maximum)
  double reference = 0.0, model = 0.0;
  double ua = 0.0;  // eq. 4.3
};

struct TestUncertainty {
  std::vector<ObjectivePoint> shear, normal;
  double shear_norm = 0.0, normal_norm = 0.0;  // eq. 4.15 over each set
  bool peaked = false;  // the reference peaks before its last fifth: peak and softening are points
};

inline constexpr double kNormalQuantile95 = 1.645;

// The points of `reference` and the model's values there. The shear points (seed 4.3.3): hardening
// (tau halfway to the reference's peak), peak (each curve's maximum), softening (tau halfway from
// the peak to the last fifth), residual (mean tau over the last fifth, as the DEM summary defines
// it). A reference still hardening in its last fifth has no peak to speak of: hardening (at half
// the travel) and residual only, as the seed did for its loose sands. The normal points: at the
// reference's peak displacement and at the end. `normal_floor` bounds the normal denominators
// from below (a dilation near 0 would make any miss infinite; the verdicts' floor, 0.02 d50 or
// 1 kPa). A model curve that stops early counts as 0 beyond its end.
TestUncertainty model_uncertainty(const ResponseCurve& reference, const ResponseCurve& model,
                                  double normal_floor);

// sqrt(sum of squares): eq. 4.15's norm and eq. 4.4's global combination.
double root_sum_square(const std::vector<double>& values);

}  // namespace iwb::assessment
