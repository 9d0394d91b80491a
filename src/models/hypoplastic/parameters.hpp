#pragma once
// Parameters of von Wolffersdorff's (1996) hypoplasticity, shared by vw3d and the interface
// models derived from it (ah, ahe, hvwe, hvwe-exact, hp1d): seed Table 3.4, eqs. 5.10-5.15.
#include <string>

#include "models/parameters.hpp"

namespace iwb::models {

struct HypoplasticParameters {
  double phi_c;          // critical state friction angle, rad
  double hs;             // granular hardness, kPa
  double n;              // compression exponent
  double ed0, ec0, ei0;  // minimum, critical, maximum void ratio at zero pressure
  double alpha;          // pyknotropy exponent (peak friction vs density)
  double beta;           // stiffness exponent (density vs stiffness)

  static const ParameterTable& table();  // TOML table [hypoplastic]
  // Validates bounds, ed0 < ec0 < ei0 and require_admissible; errors name `source`.
  static HypoplasticParameters from(const ParameterValues& values, const std::string& source);
};

// von Wolffersdorff's (1996) admissibility of a set: 3 + a^2 - sqrt(3) a f_d > 0 at the loosest
// state, where f_d = ((e_i - e_d)/(e_c - e_d))^alpha is largest, a from phi_c by eq. 5.15. The
// ratio does not depend on the pressure (the three limit void ratios scale alike, eq. 5.13), so the
// check at e_i0 covers every state a test can reach (e <= e_i). Inside the declared bounds a set
// can break it (issue 38: ei0 1.62 with alpha 0.8 turned tau negative under positive shear).
// InputError naming `source`, the condition, its value and the largest alpha these void ratios
// admit.
void require_admissible(double phi_c, double ed0, double ec0, double ei0, double alpha,
                        const std::string& source);

}  // namespace iwb::models
