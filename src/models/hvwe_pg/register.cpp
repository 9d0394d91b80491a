// The models of this folder, as the registry knows them (models/registry.hpp).
#include "models/registry.hpp"

namespace iwb::models {

ModelSpec hvwe_pg_spec();

IWB_REGISTER_MODELS(hvwe_pg, hvwe_pg_spec())

}  // namespace iwb::models
