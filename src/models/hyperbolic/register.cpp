// The models of this folder, as the registry knows them (models/registry.hpp).
#include "models/registry.hpp"

namespace iwb::models {

ModelSpec hyperbolic_spec();

IWB_REGISTER_MODELS(hyperbolic, hyperbolic_spec())

}  // namespace iwb::models
