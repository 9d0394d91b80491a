// vw3d: von Wolffersdorff (1996) on full 3x3 tensors, driven in simple shear. The continuum
// reference the interface models are measured against; no wall roughness.
#include "models/hypoplastic/family.hpp"

namespace iwb::models {

namespace {
std::unique_ptr<Model> build(const ModelInputs& in, WithIntergranularStrain igs) {
  ModelInputs rough_free = in;
  rough_free.roughness = Roughness{};  // a continuum has no wall
  return make_hypoplastic("vw3d", SimpleShearKinematics{}, HypoplasticVariant{}, rough_free, igs);
}
}  // namespace

ModelSpec vw3d_spec() {
  return {"vw3d",
          "von Wolffersdorff (1996) hypoplasticity, full 3x3 tensors in simple shear",
          "seed 5.7-5.15 (ERRATA 4-6)",
          false,
          {&HypoplasticParameters::table()},
          [](const ModelInputs& in) { return build(in, WithIntergranularStrain::kNo); },
          hypoplastic_declaration(SimpleShearKinematics::component_names(), false,
                                  InPlaneStart::kFreeK0, 0)};
}

ModelSpec vw3d_igs_spec() {
  return with_intergranular_strain(vw3d_spec(), build);
}

}  // namespace iwb::models
