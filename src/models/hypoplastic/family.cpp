#include "models/hypoplastic/family.hpp"

namespace iwb::models {

ModelSpec with_intergranular_strain(ModelSpec base, HypoplasticBuilder build) {
  base.name += "-igs";
  base.summary += ", with Niemunis & Herle's intergranular strain";
  base.equations += "; intergranular strain 5.42-5.48 (ERRATA 10)";
  base.tables.push_back(&IntergranularStrainParameters::table());
  base.make = [build](const ModelInputs& in) { return build(in, WithIntergranularStrain::kYes); };
  return base;
}

}  // namespace iwb::models
