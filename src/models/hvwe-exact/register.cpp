// The models of this folder, as the registry knows them (models/registry.hpp).
#include "models/registry.hpp"

namespace iwb::models {

ModelSpec hvwe_exact_spec();
ModelSpec hvwe_exact_igs_spec();

IWB_REGISTER_MODELS(hvwe_exact, hvwe_exact_spec(), hvwe_exact_igs_spec())

}  // namespace iwb::models
