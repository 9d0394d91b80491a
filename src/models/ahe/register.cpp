// The models of this folder, as the registry knows them (models/registry.hpp).
#include "models/registry.hpp"

namespace iwb::models {

ModelSpec ahe_spec();
ModelSpec ahe_igs_spec();

IWB_REGISTER_MODELS(ahe, ahe_spec(), ahe_igs_spec())

}  // namespace iwb::models
