// The models of this folder, as the registry knows them (models/registry.hpp).
#include "models/registry.hpp"

namespace iwb::models {

ModelSpec lashkari_spec();

IWB_REGISTER_MODELS(lashkari, lashkari_spec())

}  // namespace iwb::models
