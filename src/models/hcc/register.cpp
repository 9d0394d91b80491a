// The models of this folder, as the registry knows them (models/registry.hpp).
#include "models/registry.hpp"

namespace iwb::models {

ModelSpec hcc_spec();
ModelSpec hcc3d_spec();
ModelSpec hcc_igs_spec();
ModelSpec hcc3d_igs_spec();

IWB_REGISTER_MODELS(hcc, hcc_spec(), hcc3d_spec(), hcc_igs_spec(), hcc3d_igs_spec())

}  // namespace iwb::models
