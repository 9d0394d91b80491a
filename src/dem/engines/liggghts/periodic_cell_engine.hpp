#pragma once
// The periodic soil cell (dem/scene/periodic_cell.hpp) in LIGGGHTS: the box sheared by its tilt
// (Lees-Edwards, `fix deform ... remap v`). The stages "consolidate" and "shear" are
// dem-scripts/liggghts/periodic_consolidate.in and periodic_shear.in, run by liggghts_tri
// (Debian's LIGGGHTS 3.8.0 makes no ghost grains in a triclinic box: liggghts_tri.cpp). The raw
// outputs have the plate cell's columns, so the soil cell reads both alike.
#include <string>
#include <vector>

#include "dem/engines/engine.hpp"

namespace iwb::dem {

class LiggghtsPeriodicCell final : public Engine {
 public:
  std::string name() const override { return "liggghts"; }
  std::string version() const override;
  std::vector<std::string> stages() const override { return {kConsolidationStage, "shear"}; }
  nlohmann::json numerics(const Scene& scene) const override;
  StageResult run_stage(const std::string& stage, const StageContext& ctx,
                        const nlohmann::json& facts) override;
  ContractTables assemble(const StageContext& ctx, const nlohmann::json& facts) override;
  std::string restart_file(const std::string& stage) const override;
  std::string consolidation_inputs(const Scene& scene) const override;
};

// liggghts_tri: next to the running iwb, else where the build put it.
std::string liggghts_tri_path();

}  // namespace iwb::dem
