// The models of this folder, as the registry knows them (models/registry.hpp).
#include "models/registry.hpp"

namespace iwb::models {

ModelSpec mcc_spec();
ModelSpec mcc3d_spec();

IWB_REGISTER_MODELS(mcc, mcc_spec(), mcc3d_spec())

}  // namespace iwb::models
