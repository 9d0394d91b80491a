#pragma once
// Parameters of von Wolffersdorff's (1996) hypoplasticity, shared by vw3d and the interface
// models derived from it (ah, ahe, hvwe, hvwe-exact, hp1d): seed Table 3.4, eqs. 5.10-5.15.
#include <string>

#include "models/parameters.hpp"

namespace iwb::models {

struct HypoplasticParameters {
  double phi_c;  // critical state friction angle, rad
  double hs;     // granular hardness, kPa
  double n;      // compression exponent
  double ed0, ec0, ei0;  // minimum, critical, maximum void ratio at zero pressure
  double alpha;  // pyknotropy exponent (peak friction vs density)
  double beta;   // stiffness exponent (density vs stiffness)

  static const ParameterTable& table();  // TOML table [hypoplastic]
  // Validates bounds and ed0 < ec0 < ei0; errors name `source`.
  static HypoplasticParameters from(const ParameterValues& values, const std::string& source);
};

}  // namespace iwb::models
