#pragma once
// The periodic soil cell (dem/scene/periodic_cell.hpp) in YADE: interface_shear.py's stages
// periodic_consolidate and periodic_shear, YADE's periodic cell sheared by its velocity gradient
// (O.cell.velGrad), the height servo-controlled by the same law and gains as the LIGGGHTS cell,
// applied every step.
#include <string>
#include <vector>

#include "dem/engines/engine.hpp"

namespace iwb::dem {

class YadePeriodicCell final : public Engine {
 public:
  std::string name() const override { return "yade"; }
  std::string version() const override;
  std::vector<std::string> stages() const override { return {kConsolidationStage, "shear"}; }
  nlohmann::json numerics(const Scene& scene) const override;
  StageResult run_stage(const std::string& stage, const StageContext& ctx,
                        const nlohmann::json& facts) override;
  ContractTables assemble(const StageContext& ctx, const nlohmann::json& facts) override;
  std::string restart_file(const std::string& stage) const override;
  std::string consolidation_inputs(const Scene& scene) const override;
};

}  // namespace iwb::dem
