#pragma once
// LIGGGHTS raw outputs (timeseries.raw from fix print, profiles.raw from fix ave/spatial, VTK
// dumps) into the contract tables and .pvd indexes, converting SI to kPa and mm once, here.
#include "dem/engines/engine.hpp"
#include "dem/scene/numerics.hpp"

namespace iwb::dem {

ContractTables assemble_liggghts_outputs(const StageContext& ctx, const nlohmann::json& facts,
                                         const Numerics& numerics);

}  // namespace iwb::dem
