// The models of this folder, as the registry knows them (models/registry.hpp).
#include "models/registry.hpp"

namespace iwb::models {

ModelSpec mc_spec();

IWB_REGISTER_MODELS(mc, mc_spec())

}  // namespace iwb::models
