#pragma once
// Building a member of the hypoplastic family from its inputs: shared by the model folders so each
// of them states only what makes it different (kinematics and variant data).
#include <memory>

#include "models/hypoplastic/hypoplastic_model.hpp"
#include "models/registry.hpp"

namespace iwb::models {

enum class WithIntergranularStrain : bool { kNo = false, kYes = true };

// The [intergranular_strain] table of `in`, checked; shared by every hypoplastic law.
IntergranularStrainParameters intergranular_strain_parameters(const ModelInputs& in);

template <class Kinematics>
std::unique_ptr<Model> make_hypoplastic(const std::string& name, const Kinematics& kin,
                                        const HypoplasticVariant& variant, const ModelInputs& in,
                                        WithIntergranularStrain igs = WithIntergranularStrain::kNo) {
  using Member = HypoplasticModel<Kinematics>;
  const auto p = HypoplasticParameters::from(require_table(in, "hypoplastic"),
                                             in.source + " [hypoplastic]");
  const auto c = make_constants(p, variant, in.roughness, Member::trace_of_unit());
  if (igs == WithIntergranularStrain::kNo) return std::make_unique<Member>(name, kin, c);
  return std::make_unique<Member>(name + "-igs", kin, c, intergranular_strain_parameters(in));
}

// How a member of the family starts: K0 free with the oedometric default (hvwe, vw3d), fixed at
// 1 by the kinematics (AH, AHE: eq. 5.16), or absent (hp1d has no in-plane stress).
enum class InPlaneStart { kFreeK0, kIsotropic, kNone };

// The declaration the sand family shares (src/models/README.md 8.1): the kinematics' stress
// components and e, sigma_n_kPa, K0 and e0 at the start, mean stress and Bauer's limiting void
// ratios as diagnostics, and for interface models Gutjahr's and Arnold & Herle's roughness with
// kappa_r and d_s for `iwb compare` to fit.
ModelDeclaration hypoplastic_declaration(const std::vector<std::string>& stress_components,
                                         bool interface_model, InPlaneStart start, int listing_order);

// `d` as a candidate of `iwb plan` at `rank` (simplest first).
inline ModelDeclaration with_plan_rank(ModelDeclaration d, int rank) {
  d.plan_rank = rank;
  return d;
}

// Builds one member of the family, with or without the intergranular strain.
using HypoplasticBuilder = std::unique_ptr<Model> (*)(const ModelInputs&, WithIntergranularStrain);

// The spec of `base` extended by the intergranular strain (seed 5.6): name `<base>-igs`, one more
// parameter table, and `make` = `build` with the extension.
ModelSpec with_intergranular_strain(ModelSpec base, HypoplasticBuilder build);

}  // namespace iwb::models
