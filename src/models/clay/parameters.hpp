#pragma once
// Parameters of Masin's clay hypoplasticity (seed 6.2.2-6.2.3, Table 6.1): the `[hypoplastic_clay]`
// table shared by the clay models (hcc, and hce to come). N is ln(1+e) on the isotropic normal
// compression line at p = 1 kPa (ERRATA 15).
#include <string>

#include "models/parameters.hpp"
#include "models/roughness/roughness.hpp"

namespace iwb::models {

struct ClayParameters {
  double lambda_star;  // slope of the NCL in ln(1+e) - ln p
  double kappa_star;   // slope of the unloading line in ln(1+e) - ln p
  double nu;           // ratio of shear to bulk stiffness (eq. 6.6)
  double phi_c;        // critical state friction angle, rad
  double N;            // ln(1+e) on the NCL at p = 1 kPa

  static const ParameterTable& table();
  // Validated against table(); also lambda* > kappa* (a normal compression line stiffer than
  // unloading is not a clay). InputError naming `source`.
  static ClayParameters from(const ParameterValues& v, const std::string& source);
};

// The Poisson ratio a clay law uses on a wall of roughness r. Both clay schemes put phi_c kappa_r
// into the critical state (eqs. 6.22, 6.26-6.28, in each law's constants); Stutz & Masin's also
// scales the ratio r of eq. 6.23 by kappa_r (eq. 6.24) and replaces nu by nu_r (eq. 6.25), which
// leaves the bulk stiffness and multiplies the shear stiffness (1 - 2nu)/(1 + nu) by 1/kappa_r.
// Arnold & Herle's keeps nu.
double poisson_ratio_on_wall(const ClayParameters& p, const Roughness& r);

}  // namespace iwb::models
