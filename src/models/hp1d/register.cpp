// The models of this folder, as the registry knows them (models/registry.hpp).
#include "models/registry.hpp"

namespace iwb::models {

ModelSpec hp1d_spec();

IWB_REGISTER_MODELS(hp1d, hp1d_spec())

}  // namespace iwb::models
