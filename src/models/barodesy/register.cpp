// The models of this folder, as the registry knows them (models/registry.hpp).
#include "models/registry.hpp"

namespace iwb::models {

ModelSpec barodesy_clay_spec();
ModelSpec barodesy_clay3d_spec();

IWB_REGISTER_MODELS(barodesy, barodesy_clay_spec(), barodesy_clay3d_spec())

}  // namespace iwb::models
