#pragma once
// A fully periodic soil cell in LIGGGHTS (issue 38): no walls and no gravity; the grains are
// consolidated by a servo on the box height (x and y held) and sheared by the box itself, its
// tilt moving the top image of the cell over the bottom one (Lees-Edwards), so that the cell is
// an element rather than a band next to a rough plate. The stages "consolidate" and "shear" are
// dem-scripts/liggghts/periodic_consolidate.in and periodic_shear.in, run by liggghts_tri
// (Debian's LIGGGHTS 3.8.0 makes no ghost grains in a triclinic box: liggghts_tri.cpp). The raw
// outputs have the plate cell's columns, so the soil cell reads both alike.
#include <string>
#include <vector>

#include "dem/engine.hpp"

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

// The servo's gains (m/s per Pa): d(lz)/dt = k (sigma_zz - sigma_n0), capped at the scene's servo
// speed. Consolidating and relaxing, the plate cell's law with kp = 1: the top speed while the
// grains carry nothing, slowing in proportion as sigma_zz nears the target (k = vel_max /
// sigma_n0). (A gentler gain after the first approach, the trial's, left a loose cloud that had
// jammed for a moment at 27 kPa and let go at 4 Pa 48 windows later, never accepted; with one gain
// the truth grains' loose and dense cells are accepted after 5 and 13 windows.) Shearing, the gain
// moves the height per step by a share c of the correction a grain skeleton of modulus E would
// need, k = c H / (E dt), c = 0.6: the sheared skeleton is far softer than E and the height must
// follow the dilation. At c = 0.15 (the trial's 4e-6 m/s/Pa on the truth grains) sigma_n lagged
// 3 % above the target on average (smoke grains, dense, I 1e-3) and 3.6 % (truth grains); at 0.6
// by 0.8 %, every row within 1 %, no oscillation.
struct PeriodicServoGains {
  double approach, settle, shear;
};
PeriodicServoGains periodic_servo_gains(const Scene& scene, double dt);

}  // namespace iwb::dem
