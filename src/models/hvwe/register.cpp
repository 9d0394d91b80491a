// The models of this folder, as the registry knows them (models/registry.hpp).
#include "models/registry.hpp"

namespace iwb::models {

ModelSpec hvwe_spec();
ModelSpec hvwe_igs_spec();

IWB_REGISTER_MODELS(hvwe, hvwe_spec(), hvwe_igs_spec())

}  // namespace iwb::models
