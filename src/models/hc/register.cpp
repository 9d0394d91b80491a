// The models of this folder, as the registry knows them (models/registry.hpp).
#include "models/registry.hpp"

namespace iwb::models {

ModelSpec hc_spec();
ModelSpec hc3d_spec();

IWB_REGISTER_MODELS(hc, hc_spec(), hc3d_spec())

}  // namespace iwb::models
