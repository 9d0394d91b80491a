// The models of this folder, as the registry knows them (models/registry.hpp).
#include "models/registry.hpp"

namespace iwb::models {

ModelSpec mortara_spec();

IWB_REGISTER_MODELS(mortara, mortara_spec())

}  // namespace iwb::models
