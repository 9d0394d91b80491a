// The models of this folder, as the registry knows them (models/registry.hpp).
#include "models/registry.hpp"

namespace iwb::models {

ModelSpec api_tz_spec();

IWB_REGISTER_MODELS(api_tz, api_tz_spec())

}  // namespace iwb::models
