// The models of this folder, as the registry knows them (models/registry.hpp).
#include "models/registry.hpp"

namespace iwb::models {

ModelSpec vw3d_spec();
ModelSpec vw3d_igs_spec();

IWB_REGISTER_MODELS(vw3d, vw3d_spec(), vw3d_igs_spec())

}  // namespace iwb::models
