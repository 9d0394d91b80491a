#pragma once
// Building a member of the hypoplastic family from its inputs: shared by the model folders so each
// of them states only what makes it different (kinematics and variant data).
#include <memory>

#include "models/hypoplastic/hypoplastic_model.hpp"
#include "models/registry.hpp"

namespace iwb::models {

template <class Kinematics>
std::unique_ptr<Model> make_hypoplastic(const std::string& name, const Kinematics& kin,
                                        const HypoplasticVariant& variant,
                                        const ModelInputs& in) {
  const auto p = HypoplasticParameters::from(require_table(in, "hypoplastic"),
                                             in.source + " [hypoplastic]");
  return std::make_unique<HypoplasticModel<Kinematics>>(name, kin, p, variant, in.roughness);
}

}  // namespace iwb::models
