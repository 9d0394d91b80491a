#pragma once
// YADE 2023.02a (Debian) as a DEM engine: writes the scene's derived numbers to yade_params.json
// and the wall and plate STL, runs dem-scripts/yade/interface_shear.py headless
// (`yade -n -x -jN`), follows its IWB_ lines, and converts its raw outputs into the contract with
// the same code as the LIGGGHTS runner. Contact-law mapping: dem-scripts/yade/README.md.
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "dem/engines/engine.hpp"
#include "dem/scene/numerics.hpp"

namespace iwb::dem {

class YadeEngine final : public Engine {
 public:
  YadeEngine() = default;
  // Other stages than consolidate + shear (the soil cell's oedometer), with the parameters they
  // need beyond the scene's, merged into yade_params.json.
  YadeEngine(std::vector<std::string> stages, nlohmann::json extra)
      : stages_(std::move(stages)), extra_(std::move(extra)) {}
  std::string name() const override { return "yade"; }
  std::string version() const override;
  std::vector<std::string> stages() const override { return stages_; }
  nlohmann::json numerics(const Scene& scene) const override;
  StageResult run_stage(const std::string& stage, const StageContext& ctx,
                        const nlohmann::json& facts) override;
  ContractTables assemble(const StageContext& ctx, const nlohmann::json& facts) override;
  std::string restart_file(const std::string& stage) const override;
  std::string consolidation_inputs(const Scene& scene) const override;
  std::string unsupported(const Scene& scene) const override;

 private:
  std::vector<std::string> stages_ = {"consolidate", "shear"};
  nlohmann::json extra_ = nlohmann::json::object();
};

// The YADE parameters of a scene: geometry and step counts of `derive`, materials, the rolling
// resistance mapped from LIGGGHTS's cdt coefficient, servo and output periods (SI).
nlohmann::json yade_parameters(const Scene& scene, const Numerics& numerics);

// The runner script, run from the stage's work directory.
inline constexpr const char* kYadeScript = "interface_shear.py";

// `yade -n -x -jN interface_shear.py yade_params.json STAGE`, output line-buffered.
std::vector<std::string> yade_command(const std::string& script_stage, int threads);

// The runner script as shipped in dem-scripts/yade/ (embedded at build time).
const std::map<std::string, std::string>& yade_scripts();
// The capillary tables of Law2_ScGeom_CapillaryPhys_Capillarity, M_r<ratio>.txt of
// dem-scripts/yade/capillary (Debian ships none; README.md there says how they were made).
const std::map<std::string, std::string>& yade_capillary_tables();

}  // namespace iwb::dem
