// The models of this folder, as the registry knows them (models/registry.hpp).
#include "models/registry.hpp"

namespace iwb::models {

ModelSpec ah_spec();

IWB_REGISTER_MODELS(ah, ah_spec())

}  // namespace iwb::models
