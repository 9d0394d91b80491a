// vw3d: von Wolffersdorff (1996) on full 3x3 tensors, driven in simple shear. The continuum
// reference the interface models are measured against; no wall roughness.
#include "models/hypoplastic/family.hpp"

namespace iwb::models {

ModelSpec vw3d_spec() {
  return {"vw3d",
          "von Wolffersdorff (1996) hypoplasticity, full 3x3 tensors in simple shear",
          "seed 5.7-5.15 (ERRATA 4-6)",
          false,
          {&HypoplasticParameters::table()},
          [](const ModelInputs& in) {
            ModelInputs rough_free = in;
            rough_free.roughness = Roughness{};  // a continuum has no wall
            return make_hypoplastic("vw3d", SimpleShearKinematics{}, HypoplasticVariant{}, rough_free);
          }};
}

}  // namespace iwb::models
