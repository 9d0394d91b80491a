// ahe: Arnold & Herle's reduced tensors (sigma_22 = sigma_33 = sigma_n, eps_n on the whole
// diagonal of D, eqs. 5.16-5.19) with the standard Lode angle, a (eq. 5.15) and F (eq. 5.10).
#include "models/hypoplastic/family.hpp"

namespace iwb::models {

namespace {
std::unique_ptr<Model> build(const ModelInputs& in, WithIntergranularStrain igs) {
  return make_hypoplastic("ahe", ReducedInterfaceKinematics<algebra::ReducedOps>{true},
                          HypoplasticVariant{}, in, igs);
}
}  // namespace

ModelSpec ahe_spec() {
  return {"ahe",
          "Arnold & Herle reduced tensors with the standard cos 3theta, a and F",
          "seed 5.16-5.19 with 5.10, 5.11, 5.15 (ERRATA 8)",
          true,
          {&HypoplasticParameters::table()},
          [](const ModelInputs& in) { return build(in, WithIntergranularStrain::kNo); },
          with_plan_rank(hypoplastic_declaration(
                             ReducedInterfaceKinematics<algebra::ReducedOps>::component_names(),
                             true, InPlaneStart::kIsotropic, 2),
                         5)};
}

ModelSpec ahe_igs_spec() {
  auto spec = with_intergranular_strain(ahe_spec(), build);
  spec.declaration.plan_rank = 11;
  return spec;
}

}  // namespace iwb::models
