// The models of this folder, as the registry knows them (models/registry.hpp).
#include "models/registry.hpp"

namespace iwb::models {

ModelSpec hcthm_spec();
ModelSpec hcthm3d_spec();

IWB_REGISTER_MODELS(thermo_hydro, hcthm_spec(), hcthm3d_spec())

}  // namespace iwb::models
