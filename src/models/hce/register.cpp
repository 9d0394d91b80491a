// The models of this folder, as the registry knows them (models/registry.hpp).
#include "models/registry.hpp"

namespace iwb::models {

ModelSpec hce_spec();
ModelSpec hce3d_spec();
ModelSpec hce_igs_spec();
ModelSpec hce3d_igs_spec();

IWB_REGISTER_MODELS(hce, hce_spec(), hce3d_spec(), hce_igs_spec(), hce3d_igs_spec())

}  // namespace iwb::models
