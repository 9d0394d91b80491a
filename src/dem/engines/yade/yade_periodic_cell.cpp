#include "dem/engines/yade/yade_periodic_cell.hpp"

#include <fmt/core.h>

#include "dem/engines/contract_outputs.hpp"
#include "dem/engines/stage_follower.hpp"
#include "dem/engines/yade/yade_engine.hpp"
#include "dem/scene/numerics.hpp"
#include "dem/scene/periodic_cell.hpp"
#include "io/run_directory.hpp"

namespace iwb::dem {

namespace fs = std::filesystem;

namespace {

// yade_params.json of the plate cell's parameters with the periodic cell's: the cloud's height
// (YADE's placement checks overlaps across every face: no margin), the servo's gains, the bins.
// The servo acts every step: the LIGGGHTS cell's gains, held for ten steps as the plate cell's
// servo is, would correct ten times as much per update.
nlohmann::json periodic_parameters(const Scene& s, const Numerics& n) {
  nlohmann::json p = yade_parameters(s, n);
  const PeriodicServoGains k = periodic_servo_gains(s, n.dt);
  p["servo"]["every"] = 1;
  p["periodic"] = {{"Lz_insert", periodic_insertion_height(s, 0.0)},
                   {"gain_consolidation", k.consolidation},
                   {"gain_shear", k.shear},
                   {"bin_dz", s.outputs.profile_bin_d50 * n.d50}};
  return p;
}

// profiles.raw rows "step z count vx solid szz tau" (interface_shear.py's PeriodicOutputs: z in
// the cell, stresses per bin volume, compression and shear along the tilt positive).
ProfileBlocks periodic_profile_blocks(const fs::path& raw, const Numerics& n) {
  ProfileBlocks blocks;
  for (const auto& v : numeric_lines(raw))
    if (v.size() >= 7) blocks[long(v[0])].push_back({v[1] / n.d50, v[2], v[3], v[4], v[5], v[6]});
  return blocks;
}

}  // namespace

std::string YadePeriodicCell::version() const {
  return YadeEngine().version();
}

nlohmann::json YadePeriodicCell::numerics(const Scene& s) const {
  nlohmann::json j = YadeEngine().numerics(s);
  const PeriodicServoGains k = periodic_servo_gains(s, derive(s).dt);
  j["cell"] = "fully periodic, sheared by the cell's velocity gradient, no walls, no gravity";
  j["servo"] = {{"vel_max_m_s", s.servo.vel_max_m_s},
                {"height_gain_consolidation_m_s_per_Pa", k.consolidation},
                {"height_gain_shear_m_s_per_Pa", k.shear},
                {"steps_per_update", 1}};
  return j;
}

StageResult YadePeriodicCell::run_stage(const std::string& stage, const StageContext& ctx,
                                        const nlohmann::json&) {
  const Numerics n = derive(ctx.scene);
  io::write_atomically(ctx.work_dir / "yade_params.json",
                       periodic_parameters(ctx.scene, n).dump(2) + "\n");
  io::write_atomically(ctx.work_dir / kYadeScript, yade_scripts().at(kYadeScript));
  return run_followed_stage(yade_command("periodic_" + stage, ctx.processes), stage, ctx);
}

// yade_params.json without what only the shear stage reads, and the script.
std::string YadePeriodicCell::consolidation_inputs(const Scene& s) const {
  nlohmann::json params = periodic_parameters(s, derive(s));
  for (const char* later : {"shear", "bc", "relax_steps", "mu_test"}) params.erase(later);
  params["periodic"].erase("gain_shear");
  params["periodic"].erase("bin_dz");
  return params.dump(2) + yade_scripts().at(kYadeScript);
}

std::string YadePeriodicCell::restart_file(const std::string& stage) const {
  return stage == kConsolidationStage ? "consolidated.yade.gz" : "";
}

ContractTables YadePeriodicCell::assemble(const StageContext& ctx, const nlohmann::json& facts) {
  const Scene& s = ctx.scene;
  const Numerics n = derive(s);
  const long step0 = facts.at("shear").at("step0").get<long>();
  ContractTables out;
  out.timeseries = timeseries_table(s, n, ctx.work_dir / "timeseries.raw",
                                    facts.at("shear").at("z0_m").get<double>());
  band_is_the_cell(out.timeseries);
  out.profiles =
      profile_table(s, n, periodic_profile_blocks(ctx.work_dir / "profiles.raw", n), step0);
  out.facts = plate_facts(s, out.timeseries);
  out.facts["timestep_s"] = n.dt;
  out.facts["shear_start_step"] = step0;
  return out;
}

}  // namespace iwb::dem
