#pragma once
// LIGGGHTS 3.8 (Debian) as a DEM engine: renders the stage templates of dem-scripts/liggghts/
// (embedded at build time), writes the wall and plate STL, runs `liggghts` (through mpirun for
// more than one rank), follows its output for progress and failures, and converts its raw
// outputs into the contract.
#include <map>
#include <string>

#include "common/template.hpp"
#include "dem/engines/engine.hpp"
#include "dem/engines/stage_follower.hpp"
#include "dem/scene/numerics.hpp"

namespace iwb::dem {

class LiggghtsEngine final : public Engine {
 public:
  LiggghtsEngine() = default;
  // Other stages than consolidate + shear, each the template `<stage>.in` of dem-scripts/liggghts/
  // (the soil cell's oedometer), with the values they need beyond the scene's.
  LiggghtsEngine(std::vector<std::string> stages, TemplateValues extra)
      : stages_(std::move(stages)), extra_(std::move(extra)) {}
  std::string name() const override { return "liggghts"; }
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
  TemplateValues extra_;
};

// The stage templates as shipped in dem-scripts/liggghts/ (generated at build time).
const std::map<std::string, std::string>& liggghts_templates();

// What every LIGGGHTS template of a scene reads: grains and materials, insertion, servo and
// acceptance, the wall's motion, output periods; z0 is the plate height the consolidation left.
TemplateValues liggghts_values(const Scene& scene, const Numerics& numerics,
                               double z0_consolidated);

// The command that runs `input` (through mpirun for more than one rank).
std::vector<std::string> liggghts_command(const std::string& input, int processes,
                                          const std::string& executable = "liggghts");

// LIGGGHTS's "Loop time of T on P procs for S steps with A atoms": the engine's own cost.
void read_liggghts_loop_time(const std::vector<std::string>& words, EngineCost& cost);

}  // namespace iwb::dem
