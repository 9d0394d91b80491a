#include "dem/engines/yade/yade_engine.hpp"

#include <fmt/core.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <sstream>

#include "common/subprocess.hpp"
#include "dem/engines/contract_outputs.hpp"
#include "dem/engines/snapshots.hpp"
#include "dem/engines/stage_follower.hpp"
#include "dem/scene/ramp_numerics.hpp"
#include "dem/scene/wall_geometry.hpp"
#include "io/run_directory.hpp"

namespace iwb::dem {

namespace fs = std::filesystem;

namespace {

// The servo closes kServoGain of the force error per update, every kServoEvery steps: the
// fraction per step that converged on the smoke scene was 0.02 (interface_shear.py says why).
constexpr double kServoGain = 0.2;
constexpr int kServoEvery = 10;
// While shearing, an integral term adds this share of the closing velocity per update.
constexpr double kServoIntegralGain = 0.02;

// Rolling resistance. Both LIGGGHTS models cap the torque at mu_r R* F_n (R* = R1 R2 / (R1 + R2));
// YADE's Mindlin law caps an elastic bending moment at eta R_mean F_n (R_mean = (R1 + R2) / 2),
// so eta = mu_r R* / R_mean = mu_r / 2 equalises the caps of two grains of d50. The moment's
// stiffness follows the LIGGGHTS model it stands in for, taken at a d50 contact carrying
// sigma_n0 d50^2 (YADE's krot is one number for every contact):
// - epsd2 (rolling_model_epsd2.h): k_r = k_t R*^2, with k_t = 8 G* sqrt(R* delta) Mindlin's
//   tangential stiffness, the same k_s YADE's Mindlin law computes. The moment reaches its cap
//   within ~1e-3 rad.
// - cdt is rigid-plastic: Ai et al.'s (2011) k_r = 2.25 k_n mu_r^2 R*^2 (k_n Hertz's tangent
//   stiffness) reaches the cap within a few hundredths of a radian. Taken for epsd2 too, it was
//   38 times softer than LIGGGHTS's spring (data/reference/README.md, answer 7).
nlohmann::json rolling(const Scene& s) {
  const auto& p = s.particles;
  const double mu_r = p.rolling_friction;
  const double r_star = 0.25 * p.d50_m;
  const double e_star = p.youngs_modulus_Pa / (2.0 * (1.0 - p.poisson * p.poisson));
  const double g_star = p.youngs_modulus_Pa / (2.0 * (1.0 + p.poisson)) / (2.0 * (2.0 - p.poisson));
  const double kno = 4.0 / 3.0 * e_star * std::sqrt(r_star);  // Hertz: F = kno delta^(3/2)
  const double force = s.boundary.sigma_n_Pa * p.d50_m * p.d50_m;
  const double overlap = std::pow(force / kno, 2.0 / 3.0);
  const double k_n = 1.5 * kno * std::sqrt(overlap);
  const double k_t = 8.0 * g_star * std::sqrt(r_star * overlap);
  const double k_r = p.rolling_model == "epsd2" ? k_t * r_star * r_star
                                                : 2.25 * k_n * mu_r * mu_r * r_star * r_star;
  return {{"eta", 0.5 * mu_r}, {"krot", k_r}, {"mu_r", mu_r}, {"stiffness_from", p.rolling_model}};
}

nlohmann::json glued_spheres(const Scene& s) {
  nlohmann::json g = nlohmann::json::array();
  if (s.wall.kind != ProfileKind::kGlued) return g;
  const double d = s.wall.height_m, a = s.wall.pitch_m;
  for (int i = 0; i < int(std::lround(s.length_m / a)); ++i)
    for (int j = 0; j < int(std::lround(s.width_m / a)); ++j)
      g.push_back({(i + 0.5) * a, (j + 0.5) * a, 0.5 * d, d});
  return g;
}

nlohmann::json shear_parameters(const Scene& s, const Numerics& n) {
  return {{"velocity", s.shear.velocity_m_s},
          {"amplitude", s.shear.amplitude_m},
          {"cyclic", s.shear.cyclic()},
          {"cycles_travel", s.shear.cycles_travel_m()},
          {"ramp_s", s.shear.cyclic() ? 0.0 : s.shear.ramp_s},
          {"steps", n.shear_steps},
          {"ts_every", n.ts_every},
          {"progress_every", n.progress_every},
          {"profile_every", n.profile_every},
          {"profile_repeat", n.profile_repeat},
          {"vtk_every", n.vtk_every},
          {"u_total", s.shear.travel_m()}};
}

// The script's profiles.raw: "step z count vx solid s_zz s_xz" per bin, stresses per bin volume
// and compression negative, as LIGGGHTS's stress/atom.
ProfileBlocks yade_profile_blocks(const fs::path& raw, const Scene& s, const Numerics& n) {
  ProfileBlocks blocks;
  for (const auto& v : numeric_lines(raw))
    if (v.size() >= 7)
      blocks[long(v[0])].push_back(
          {(v[1] - s.wall.mean_height_m()) / n.d50, v[2], v[3], v[4], -v[5], -v[6]});
  return blocks;
}

// The law reads "M(r=<ratio>)" from the working directory and runs dry, with a warning only, when
// they are missing: they are written for every stage of a wet scene.
void write_capillary_tables(const fs::path& dir) {
  for (const auto& [name, text] : yade_capillary_tables()) {
    const std::string ratio = name.substr(3, name.size() - 3 - 4);  // M_r<ratio>.txt
    io::write_atomically(dir / ("M(r=" + ratio + ")"), text);
  }
}

}  // namespace

std::vector<std::string> yade_command(const std::string& stage, int threads) {
  // -n: no GUI; -x: exit when the script ends. stdbuf keeps the IWB_ lines live.
  return {"stdbuf",
          "-oL",
          "yade",
          "-n",
          "-x",
          "-j",
          std::to_string(std::max(1, threads)),
          kYadeScript,
          "yade_params.json",
          stage};
}

nlohmann::json yade_parameters(const Scene& s, const Numerics& n) {
  const auto& p = s.particles;
  nlohmann::json sizes = nlohmann::json::array();
  for (const auto& c : p.sizes) sizes.push_back({c.diameter_m, c.mass_fraction});
  return {
      {"Lx", s.length_m},
      {"Ly", s.width_m},
      {"zlo", n.zlo},
      {"zhi", n.zhi},
      {"d_max", p.d_max()},
      {"dt", n.dt},
      {"skin", n.skin},
      {"plate_z", n.plate_z},
      {"ins_zlo", n.ins_zlo},
      {"ins_zhi", n.ins_zhi},
      {"sizes", sizes},
      {"density", p.density_kg_m3},
      {"E", p.youngs_modulus_Pa},
      {"nu", p.poisson},
      {"restitution", p.restitution},
      {"mu_consolidation", s.consolidation.friction},
      {"mu_test", p.friction},
      {"rolling", rolling(s)},
      {"glued", glued_spheres(s)},
      {"capillary", p.wet() ? nlohmann::json{{"suction_Pa", p.suction_Pa},
                                             {"surface_tension_N_m", p.surface_tension_N_m}}
                            : nlohmann::json(nullptr)},
      {"wall_stl", "wall.stl"},
      {"plate_stl", "top.stl"},
      {"n_particles", s.particle_count},
      {"seed", s.seed},
      {"settle_steps", n.settle_steps},
      {"window_steps", s.consolidation.window_steps},
      {"approach_windows", n.approach_windows},
      {"approach_sigma", kApproachSigmaShare * s.boundary.sigma_n_Pa},
      {"windows_required", s.consolidation.windows_required},
      {"max_windows", s.consolidation.max_windows},
      {"sigma_n0", s.boundary.sigma_n_Pa},
      {"sigma_tol", s.consolidation.sigma_tolerance},
      {"plate_tol", s.consolidation.plate_tolerance_d50 * n.d50},
      {"ke_tol", s.consolidation.kinetic_energy_J},
      {"F0", s.boundary.sigma_n_Pa * s.area_m2()},
      {"area", s.area_m2()},
      {"servo",
       {{"vel_max", s.servo.vel_max_m_s},
        {"gain", kServoGain},
        {"integral_gain", kServoIntegralGain},
        {"every", kServoEvery}}},
      {"bc", driver::to_string(s.boundary.kind)},
      {"K_Pa_per_m", s.boundary.kind == driver::BoundaryKind::kCNS ? s.boundary.K_Pa_per_m : 0.0},
      {"relax_steps", n.relax_steps},
      {"plate_clamp", s.plate.height_m + s.plate_clamp_m},
      {"clamp", s.plate_clamp_m > 0.0},
      {"band_zlo", n.band_zlo},
      {"band_zhi", n.band_zhi},
      {"bin_dz", s.outputs.profile_bin_d50 * n.d50},
      {"shear", shear_parameters(s, n)},
  };
}

std::string YadeEngine::version() const {
  std::string v = "unknown";
  try {
    run_process({"yade", "--version"}, fs::temp_directory_path(), [&v](const std::string& l) {
      if (l.find("Yade") != std::string::npos) v = l;
      return true;
    });
  } catch (const std::exception&) {
  }
  return v;
}

nlohmann::json YadeEngine::numerics(const Scene& s) const {
  const Numerics n = derive(s);
  return {{"timestep_s", n.dt},
          {"timestep_rule",
           fmt::format("{:g} x Rayleigh time of the smallest particle (the LIGGGHTS runner's rule)",
                       s.dt_fraction)},
          {"rayleigh_time_s", rayleigh_time(s.particles)},
          {"shear_steps", n.shear_steps},
          {"wall_velocity_mm_s", s.shear.velocity_m_s * 1e3},
          {"wall_ramp", ramp_numerics(s, n.dt)},
          {"contact_law",
           "Ip2_FrictMat_FrictMat_MindlinPhys (en = es = restitution, krot, eta) + "
           "Law2_ScGeom_MindlinPhys_Mindlin(includeMoment); walls: facets from the STL"},
          {"rolling", rolling(s)},
          {"servo",
           {{"vel_max_m_s", s.servo.vel_max_m_s},
            {"gain_per_update", kServoGain},
            {"integral_gain_while_shearing", kServoIntegralGain},
            {"steps_per_update", kServoEvery}}}};
}

StageResult YadeEngine::run_stage(const std::string& stage, const StageContext& ctx,
                                  const nlohmann::json&) {
  const auto t0 = std::chrono::steady_clock::now();
  const Scene& s = ctx.scene;
  const Numerics n = derive(s);
  write_scene_meshes(s, n.plate_z, ctx.work_dir);
  nlohmann::json params = yade_parameters(s, n);
  params.update(extra_);
  io::write_atomically(ctx.work_dir / "yade_params.json", params.dump(2) + "\n");
  io::write_atomically(ctx.work_dir / kYadeScript, yade_scripts().at(kYadeScript));
  if (s.particles.wet()) write_capillary_tables(ctx.work_dir);
  const double generation =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  StageResult r = run_followed_stage(yade_command(stage, ctx.processes), stage, ctx);
  r.facts["generation_seconds"] = generation;
  return r;
}

// yade_params.json without what only the later stages read (interface_shear.py: the shear
// program, the boundary condition and K, the relaxation, the band and bins, the test friction,
// the soil cell's oedometer levels), the script and the meshes.
std::string YadeEngine::consolidation_inputs(const Scene& s) const {
  const Numerics n = derive(s);
  nlohmann::json params = yade_parameters(s, n);
  params.update(extra_);
  for (const char* later : {"shear", "bc", "K_Pa_per_m", "relax_steps", "plate_clamp", "clamp",
                            "band_zlo", "band_zhi", "bin_dz", "mu_test", "oedometer"})
    params.erase(later);
  const SceneMeshes meshes = scene_meshes(s, n.plate_z);
  return params.dump(2) + yade_scripts().at(kYadeScript) + meshes.wall_stl + meshes.top_stl;
}

// interface_shear.py's O.save at the end of consolidation; the later stages O.load it.
// The rolling resistance is a property of YADE's contact-physics functor (ip2's eta), built once
// for every stage, not of a material that consolidation can swap as LIGGGHTS's property/global.
std::string YadeEngine::unsupported(const Scene& s) const {
  if (s.consolidation.rolling_friction != s.particles.rolling_friction)
    return "[specimen] consolidation_rolling_friction: a rolling resistance while consolidating "
           "other than the grains' is modelled in LIGGGHTS only (run with --engine liggghts)";
  return {};
}

std::string YadeEngine::restart_file(const std::string& stage) const {
  return stage == kConsolidationStage ? "consolidated.yade.gz" : "";
}

ContractTables YadeEngine::assemble(const StageContext& ctx, const nlohmann::json& facts) {
  const Numerics n = derive(ctx.scene);
  const long step0 = facts.at("shear").at("step0").get<long>();
  const double z0 = facts.at("shear").at("z0_m").get<double>();
  ContractTables out;
  out.timeseries = timeseries_table(ctx.scene, n, ctx.work_dir / "timeseries.raw", z0);
  out.profiles = profile_table(
      ctx.scene, n, yade_profile_blocks(ctx.work_dir / "profiles.raw", ctx.scene, n), step0);
  // interface_shear.py lifts the scene by d_max - zlo (YADE's cell starts at z = 0)
  const Eigen::Vector3d shift(0.0, 0.0, -(ctx.scene.particles.d_max() - n.zlo));
  write_snapshot_series(ctx.scene, ctx.work_dir / "dumps",
                        {"yade-spheres-0*([0-9]+)\\.vtk", "yade-facets-0*([0-9]+)\\.vtk"},
                        {shift, step0, n.dt}, ctx.run_dir / "vtk");
  out.facts = plate_facts(ctx.scene, out.timeseries);
  out.facts["timestep_s"] = n.dt;
  out.facts["shear_start_step"] = step0;
  return out;
}

}  // namespace iwb::dem
