#pragma once
// YADE 2023.02a (Debian) as a DEM engine: writes the scene's derived numbers to yade_params.json
// and the wall and plate STL, runs dem-scripts/yade/interface_shear.py headless
// (`yade -n -x -jN`), follows its IWB_ lines, and converts its raw outputs into the contract with
// the same code as the LIGGGHTS runner. Contact-law mapping: dem-scripts/yade/README.md.
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "dem/engine.hpp"
#include "dem/numerics.hpp"

namespace iwb::dem {

class YadeEngine final : public Engine {
 public:
  std::string name() const override { return "yade"; }
  std::string version() const override;
  std::vector<std::string> stages() const override { return {"consolidate", "shear"}; }
  nlohmann::json numerics(const Scene& scene) const override;
  StageResult run_stage(const std::string& stage, const StageContext& ctx,
                        const nlohmann::json& facts) override;
  ContractTables assemble(const StageContext& ctx, const nlohmann::json& facts) override;
};

// The YADE parameters of a scene: geometry and step counts of `derive`, materials, the rolling
// resistance mapped from LIGGGHTS's cdt coefficient, servo and output periods (SI).
nlohmann::json yade_parameters(const Scene& scene, const Numerics& numerics);

// The runner script as shipped in dem-scripts/yade/ (embedded at build time).
const std::map<std::string, std::string>& yade_scripts();

}  // namespace iwb::dem
