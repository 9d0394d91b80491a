// hvwe: the enhanced interface model (Stutz et al. 2016, seed 5.5): von Wolffersdorff's rate on
// the reduced vectors [sigma_n, sigma_p, tau_x, tau_y] with independent in-plane stress.
#include "models/hypoplastic/family.hpp"

namespace iwb::models {

namespace {
std::unique_ptr<Model> build(const ModelInputs& in, WithIntergranularStrain igs) {
  return make_hypoplastic("hvwe", ReducedInterfaceKinematics<algebra::ReducedOps>{},
                          HypoplasticVariant{}, in, igs);
}
}  // namespace

ModelSpec hvwe_spec() {
  return {"hvwe",
          "enhanced hypoplastic interface model on [sigma_n, sigma_p, tau_x, tau_y]",
          "seed 5.2, 5.4 (5.22-5.34), 5.5, roughness 5.35-5.41",
          true,
          {&HypoplasticParameters::table()},
          [](const ModelInputs& in) { return build(in, WithIntergranularStrain::kNo); },
          with_plan_rank(hypoplastic_declaration(
                             ReducedInterfaceKinematics<algebra::ReducedOps>::component_names(),
                             true, InPlaneStart::kFreeK0, 3),
                         8)};
}

// On cyclic paths `iwb plan` tries it last (intergranular strain matters where the path reverses).
ModelSpec hvwe_igs_spec() {
  auto spec = with_intergranular_strain(hvwe_spec(), build);
  spec.declaration.plan_rank = 12;
  return spec;
}

}  // namespace iwb::models
