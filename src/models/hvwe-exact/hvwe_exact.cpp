// hvwe-exact: hvwe with every invariant (trace, ':', tr of the cube) evaluated on the embedded
// 3x3 tensor (ERRATA item 2). Kept to show that the reduced operators are exact where the model
// uses them: its test asserts it equals hvwe to round-off.
#include "models/hypoplastic/family.hpp"

namespace iwb::models {

namespace {
std::unique_ptr<Model> build(const ModelInputs& in, WithIntergranularStrain igs) {
  return make_hypoplastic("hvwe-exact", ReducedInterfaceKinematics<algebra::EmbeddedReducedOps>{},
                          HypoplasticVariant{}, in, igs);
}
}  // namespace

ModelSpec hvwe_exact_spec() {
  return {
      "hvwe-exact",
      "hvwe with invariants evaluated on the embedded 3x3 tensor",
      "seed 5.5, ERRATA 2",
      true,
      {&HypoplasticParameters::table()},
      [](const ModelInputs& in) { return build(in, WithIntergranularStrain::kNo); },
      hypoplastic_declaration(ReducedInterfaceKinematics<algebra::ReducedOps>::component_names(),
                              true, InPlaneStart::kFreeK0, 4)};
}

ModelSpec hvwe_exact_igs_spec() {
  return with_intergranular_strain(hvwe_exact_spec(), build);
}

}  // namespace iwb::models
