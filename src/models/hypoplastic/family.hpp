#pragma once
// Building a member of the hypoplastic family from its inputs: shared by the model folders so each
// of them states only what makes it different (kinematics and variant data).
#include <memory>

#include "models/hypoplastic/hypoplastic_model.hpp"
#include "models/registry.hpp"

namespace iwb::models {

enum class WithIntergranularStrain : bool { kNo = false, kYes = true };

template <class Kinematics>
std::unique_ptr<Model> make_hypoplastic(const std::string& name, const Kinematics& kin,
                                        const HypoplasticVariant& variant, const ModelInputs& in,
                                        WithIntergranularStrain igs = WithIntergranularStrain::kNo) {
  const auto p = HypoplasticParameters::from(require_table(in, "hypoplastic"),
                                             in.source + " [hypoplastic]");
  if (igs == WithIntergranularStrain::kNo)
    return std::make_unique<HypoplasticModel<Kinematics>>(name, kin, p, variant, in.roughness);
  const auto q = IntergranularStrainParameters::from(require_table(in, "intergranular_strain"),
                                                     in.source + " [intergranular_strain]");
  return std::make_unique<HypoplasticModel<Kinematics>>(name + "-igs", kin, p, variant,
                                                        in.roughness, q);
}

// Builds one member of the family, with or without the intergranular strain.
using HypoplasticBuilder = std::unique_ptr<Model> (*)(const ModelInputs&, WithIntergranularStrain);

// The spec of `base` extended by the intergranular strain (seed 5.6): name `<base>-igs`, one more
// parameter table, and `make` = `build` with the extension.
ModelSpec with_intergranular_strain(ModelSpec base, HypoplasticBuilder build);

}  // namespace iwb::models
