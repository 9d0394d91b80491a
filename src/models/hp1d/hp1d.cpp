// hp1d: Gutjahr's (2003) 1D interface model (seed 3.3.4): von Wolffersdorff's rate on
// [sigma_n, tau] x [eps_n, gamma] with F = 1 and a = 1/tan(phi_c); derivation in README.md.
#include "models/hypoplastic/family.hpp"

namespace iwb::models {

ModelSpec hp1d_spec() {
  return {"hp1d",
          "Gutjahr (2003) 1D hypoplastic interface model, one shear direction",
          "seed 3.68-3.77 (eq. 3.75 re-derived, ERRATA 7)",
          true,
          {&HypoplasticParameters::table()},
          [](const ModelInputs& in) {
            return make_hypoplastic(
                "hp1d", ShearPlaneKinematics{},
                HypoplasticVariant{LodeRule::kStandard, CoefficientARule::kGutjahr1D}, in);
          },
          with_plan_rank(hypoplastic_declaration(ShearPlaneKinematics::component_names(), true,
                                                 InPlaneStart::kNone, 5),
                         3)};
}

}  // namespace iwb::models
