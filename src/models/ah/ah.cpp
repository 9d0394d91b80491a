// ah: Arnold & Herle (2006): reduced tensors with sigma_22 = sigma_33 = sigma_n (eqs. 5.16-5.19),
// cos 3theta = 0, which makes F eq. 5.20, and the coefficient a of eq. 5.21.
#include "models/hypoplastic/family.hpp"

namespace iwb::models {

ModelSpec ah_spec() {
  return {"ah",
          "Arnold & Herle (2006) hypoplastic interface model",
          "seed 5.16-5.21 (ERRATA 8)",
          true,
          {&HypoplasticParameters::table()},
          [](const ModelInputs& in) {
            return make_hypoplastic(
                "ah", ReducedInterfaceKinematics<algebra::ReducedOps>{true},
                HypoplasticVariant{LodeRule::kZero, CoefficientARule::kArnoldHerle}, in);
          },
          with_plan_rank(hypoplastic_declaration(
                             ReducedInterfaceKinematics<algebra::ReducedOps>::component_names(),
                             true, InPlaneStart::kIsotropic, 1),
                         4)};
}

}  // namespace iwb::models
