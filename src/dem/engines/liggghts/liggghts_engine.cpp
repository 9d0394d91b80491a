#include "dem/engines/liggghts/liggghts_engine.hpp"

#include <fmt/core.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <map>
#include <optional>

#include "common/errors.hpp"
#include "common/subprocess.hpp"
#include "common/template.hpp"
#include "dem/engines/liggghts/liggghts_outputs.hpp"
#include "dem/engines/liggghts/shear_checkpoint.hpp"
#include "dem/engines/stage_follower.hpp"
#include "dem/scene/numerics.hpp"
#include "dem/scene/ramp_numerics.hpp"
#include "dem/scene/wall_geometry.hpp"
#include "io/checksum_record.hpp"
#include "io/run_directory.hpp"

namespace iwb::dem {

namespace fs = std::filesystem;

namespace {

bool is_prime(long n) {
  if (n < 2) return false;
  for (long d = 2; d * d <= n; ++d)
    if (n % d == 0) return false;
  return true;
}

// LIGGGHTS wants distinct prime seeds above 10000 for each random stream.
long prime_seed(int scene_seed, int stream) {
  long n = 15485863L + 104729L * scene_seed + 7919L * stream;
  while (!is_prime(n)) ++n;
  return n;
}

std::string g(double x) {
  return fmt::format("{:.10g}", x);
}

// The wall's displacement ux (m) and its motion (the same functions as Shear::displacement_at and
// speed_at): monotonic at v, after a linear ramp of the speed over T when the scene has one, or
// cycles 0 -> +A -> -A -> 0 as a triangle wave, then the post-cyclic shear. LIGGGHTS 3.8's
// equal-style variables have no min(): the ramp is written with (a<b) factors.
bool ramped(const Shear& sh) {
  return !sh.cyclic() && sh.ramp_s > 0.0;
}

std::string wall_displacement(const Shear& sh) {
  const std::string v = g(sh.velocity_m_s), T = g(sh.ramp_s);
  if (ramped(sh))
    return fmt::format("variable ux equal {}*((v_t<{})*v_t*v_t/(2*{})+(v_t>={})*(v_t-{}/2))", v, T,
                       T, T, T);
  if (!sh.cyclic()) return fmt::format("variable ux equal {}*v_t", v);
  // after the cycles (t >= tc) the post-cyclic shear, from 0 at v
  const std::string tc = g(sh.cycles_travel_m() / sh.velocity_m_s);
  return fmt::format(
      "variable phase equal v_t*{}/{}\n"
      "variable ux equal (v_t<{})*{}*(abs(((v_phase+3)%4)-2)-1)+(v_t>={})*{}*(v_t-{})",
      v, g(sh.amplitude_m), tc, g(sh.amplitude_m), tc, v, tc);
}

// The distance the wall has travelled (progress): its displacement, or v t for cycles.
std::string wall_travel(const Shear& sh) {
  return sh.cyclic() ? fmt::format("{}*v_t", g(sh.velocity_m_s)) : "v_ux";
}

// The wall's speed vw (m/s) where it is not constant: during the ramp and in cycles. While ramping,
// the mesh moves by vw dt per step with t read at the step's end: vw is the speed at mid-step,
// the step's mean, so that the mesh stays at ux (at the end of the ramp a speed read at the
// step's end would put it half a step's travel ahead).
std::string wall_speed(const Shear& sh, double dt) {
  const std::string v = g(sh.velocity_m_s);
  if (ramped(sh))
    return fmt::format("variable vw equal {}*((v_t<{})*(v_t-{})/{}+(v_t>={}))", v, g(sh.ramp_s),
                       g(0.5 * dt), g(sh.ramp_s), g(sh.ramp_s));
  if (!sh.cyclic()) return "# the wall moves at a constant speed";
  const std::string tc = g(sh.cycles_travel_m() / sh.velocity_m_s);
  return fmt::format("variable vw equal {}*((v_t<{})*(1-2*(floor((v_phase+1)/2)%2))+(v_t>={}))", v,
                     tc, tc);
}

std::string wall_motion(const Shear& sh, double dt) {
  if (!sh.cyclic() && !ramped(sh))
    return fmt::format("fix mv all move/mesh mesh W linear {} 0 0", g(sh.velocity_m_s));
  return wall_speed(sh, dt) +
         "\nvariable zero equal 0\nfix mv all move/mesh mesh W linear/variable v_vw v_zero v_zero";
}

// The largest Young's modulus LIGGGHTS takes in SI units without `hard_particles yes`.
constexpr double kLiggghtsSoftLimitPa = 1e9;

// Frictionless grains between flat walls and periodic sides have a free mode: the whole specimen
// sliding sideways. Nothing stops it, and round-off feeds it: a dense soil cell (preparation
// friction 0, 1084 grains, E 6.9e8, 200 kPa) drifted at 4-8 cm/s with every grain alike, its
// kinetic energy growing to 6e-5 J, and never passed the acceptance (1e-6 J); with the drift
// removed every 100 steps it was accepted after 14 windows. With friction the walls take this
// momentum up, and the fix stays out so that those runs are unchanged.
std::string frictionless_drift(double consolidation_friction) {
  if (consolidation_friction > 0.0)
    return "# frictionless preparation only: no sideways drift to remove";
  return "fix nodrift grains momentum 100 linear 1 1 0";
}

// Material properties for one grain type, or two when the wall has a glued layer (same material).
std::string materials(const Particles& p, double friction, double rolling_friction, int types) {
  auto repeat = [](const std::string& v, int n) {
    std::string out;
    for (int i = 0; i < n; ++i) out += " " + v;
    return out;
  };
  const int pairs = types * types;
  // LIGGGHTS refuses E > 1e9 Pa in SI units unless told the grains are meant to be that hard
  // (global_properties.cpp); stiffness levels of ~2000 at 50 kPa need E ~ 4e9 (issue 20).
  const std::string hard = p.youngs_modulus_Pa > kLiggghtsSoftLimitPa ? "hard_particles yes\n" : "";
  return hard + fmt::format(
                    "fix m1 all property/global youngsModulus peratomtype{}\n"
                    "fix m2 all property/global poissonsRatio peratomtype{}\n"
                    "fix m3 all property/global coefficientRestitution peratomtypepair {}{}\n"
                    "fix m4 all property/global coefficientFriction peratomtypepair {}{}\n"
                    "fix m5 all property/global coefficientRollingFriction peratomtypepair {}{}",
                    repeat(g(p.youngs_modulus_Pa), types), repeat(g(p.poisson), types), types,
                    repeat(g(p.restitution), pairs), types, repeat(g(friction), pairs), types,
                    repeat(g(rolling_friction), pairs));
}

bool glued(const Scene& s) {
  return s.wall.kind == ProfileKind::kGlued;
}

// The glued layer: spheres of type 2 on a square grid, resting on the flat base mesh.
std::string glued_layer(const Scene& s) {
  if (!glued(s)) return "# no glued layer: the wall is its mesh";
  const double d = s.wall.height_m, a = s.wall.pitch_m;
  std::string out;
  for (int i = 0; i < int(std::lround(s.length_m / a)); ++i)
    for (int j = 0; j < int(std::lround(s.width_m / a)); ++j)
      out += fmt::format("create_atoms 2 single {} {} {} units box\n", g((i + 0.5) * a),
                         g((j + 0.5) * a), g(0.5 * d));
  return out +
         fmt::format("group glued type 2\nset group glued diameter {}\nset group glued density {}",
                     g(d), g(s.particles.density_kg_m3));
}

// The glued spheres move with the wall's mesh: the same displacement, by `fix move`.
std::string glued_motion(const Shear& sh) {
  if (!sh.cyclic() && !ramped(sh))
    return fmt::format("fix mvg glued move linear {} 0 0", g(sh.velocity_m_s));
  return "fix mvg glued move variable v_ux NULL NULL v_vw NULL NULL";
}

// Random insertion's tries per grain (LIGGGHTS's default is 50). A grain placed within 50 tries
// draws the same random numbers either way, so scenes that filled their region are unchanged; a
// narrow region near jamming (the truth halved to 12 x 4 x 10 d50 placed 639 of 640 grains in 50)
// gets the tries it needs.
constexpr int kInsertAttempts = 5000;

// The plate's clamp (scene.hpp, plate_clamp_m): the grains whose centres lie within the clamp's
// depth below the plate's teeth when shear starts keep x and y velocity 0 (setforce) and their
// spin (plain nve does not integrate omega; this build's `set` cannot zero it, so the relaxation's
// spin stays: the test reads it from the snapshots); z is integrated, so they follow the plate.
// A resumed shear finds the groups in its checkpoint (a restart keeps them) and makes the fixes
// again: the grains under the plate now are not the ones clamped when shear started.
std::string plate_clamp(const Scene& s, bool resumed) {
  if (!(s.plate_clamp_m > 0.0)) return "# no clamp under the plate";
  const std::string groups =
      resumed ? "# resumed: the groups clamped and sheared are the checkpoint's\n"
              : fmt::format(
                    "variable zclamp equal ${{z0}}-{}\n"
                    "region clampzone block INF INF INF INF ${{zclamp}} INF units box\n"
                    "group inclamp region clampzone\n"
                    "group clamped intersect inclamp grains\n"
                    "group sheared subtract grains clamped\n",
                    g(s.plate.height_m + s.plate_clamp_m));
  return groups + fmt::format(
                      "unfix integr\n"
                      "fix integr sheared nve/sphere\n"
                      "fix integrclamp clamped nve\n"
                      "fix clampxy clamped setforce 0.0 0.0 NULL\n"
                      "{}velocity clamped set 0.0 0.0 NULL units box\n"
                      "variable nclamped equal count(clamped)\n"
                      "print \"IWB_FACT clamped_grains ${{nclamped}}\"",
                      resumed ? "# (set when shear started) " : "");
}

// A row of timeseries.raw (fix print, and the row printed when shear starts) and its title.
constexpr const char* kTimeseriesRow =
    "${t} ${ux} ${zplate} ${sigma_wall} ${tau_wall} ${sigma_plate} ${vs} ${vb} ${coord} ${na} "
    "${kin}";
constexpr const char* kTimeseriesTitle =
    "t_s ux_m zplate_m sigma_wall_Pa tau_wall_Pa sigma_plate_Pa vsolid_m3 vband_m3 coordination "
    "atoms ke_J";

// LIGGGHTS keeps each grain's mesh neighbours (the triangles near it) in one chunk of at most
// `neigh_modify one` entries (2000 by default) and stops with "mesh neighbor list overflow" beyond
// it: a measured map at 0.1 d50 did (issue 60). The chunk is sized from the densest part of the
// meshes, with half again as margin; its page holds ten chunks (LAMMPS's neigh_modify advice).
// Beyond kMaxMeshNeighbours the memory is the user's to decide: refused, with the coarser
// resampling that fits.
constexpr int kLiggghtsDefaultOne = 2000;
constexpr double kMeshNeighbourMargin = 1.5;
constexpr int kMaxMeshNeighbours = 50000;

std::string neighbour_limits(const Scene& s, const Numerics& n) {
  const double reach = s.particles.d_max() + n.skin;
  const int densest = densest_scene_triangles(s, n.plate_z, reach);
  const int one = std::max(kLiggghtsDefaultOne, int(std::ceil(kMeshNeighbourMargin * densest)));
  if (one > kMaxMeshNeighbours)
    throw InputError(fmt::format(
        "{}: the wall's or plate's mesh has {} triangles within 3 (d_max + skin) = {:.3g} mm of "
        "one grain, more than the {} LIGGGHTS can be given per grain here; coarsen the surface "
        "(a larger [wall] resample_d50, about {:.2g} times the present cell)",
        s.source, densest, 3.0 * reach * 1e3, kMaxMeshNeighbours / kMeshNeighbourMargin,
        std::sqrt(kMeshNeighbourMargin * densest / kMaxMeshNeighbours) * 1.1));
  return fmt::format("one {} page {}", one, std::max(100000, 10 * one));
}

}  // namespace

TemplateValues liggghts_values(const Scene& s, const Numerics& n, double z0_consolidated) {
  const auto& p = s.particles;
  std::string templates;
  std::string distribution = fmt::format("fix pdd all particledistribution/discrete {} {}",
                                         prime_seed(s.seed, 0), p.sizes.size());
  for (std::size_t i = 0; i < p.sizes.size(); ++i) {
    templates += fmt::format(
        "fix pt{} all particletemplate/sphere {} atom_type 1 density constant {} "
        "radius constant {}\n",
        i, prime_seed(s.seed, int(i) + 2), g(p.density_kg_m3), g(0.5 * p.sizes[i].diameter_m));
    distribution += fmt::format(" pt{} {}", i, g(p.sizes[i].mass_fraction));
  }
  const double F0 = s.boundary.sigma_n_Pa * s.area_m2();
  const int types = glued(s) ? 2 : 1;
  TemplateValues values = {
      {"atom_types", std::to_string(types)},
      {"materials_consolidation",
       materials(p, s.consolidation.friction, s.consolidation.rolling_friction, types)},
      {"frictionless_drift", frictionless_drift(s.consolidation.friction)},
      {"materials_test", materials(p, p.friction, p.rolling_friction, types)},
      {"glued_layer", glued_layer(s)},
      {"glued_motion", glued(s) ? glued_motion(s.shear) : "# no glued layer"},
      {"plate_clamp", plate_clamp(s, false)},
      {"glued_force", glued(s) ? "compute fglued glued reduce sum fx fz" : "# no glued layer"},
      {"glued_fx", glued(s) ? "+c_fglued[1]" : ""},
      {"glued_fz", glued(s) ? "+c_fglued[2]" : ""},
      {"Lx", g(s.length_m)},
      {"Ly", g(s.width_m)},
      {"zlo", g(n.zlo)},
      {"zhi", g(n.zhi)},
      {"skin", g(n.skin)},
      {"neighbour_limits", neighbour_limits(s, n)},
      {"dt", g(n.dt)},
      {"rolling_model", p.rolling_model},
      {"plate_com", fmt::format("{} {} {}", g(0.5 * s.length_m), g(0.5 * s.width_m), g(n.plate_z))},
      {"F0", g(F0)},
      {"servo_vmax", g(s.servo.vel_max_m_s)},
      {"servo_kp", g(s.servo.kp)},
      {"particle_templates", templates + distribution},
      {"ins_zlo", g(n.ins_zlo)},
      {"ins_zhi", g(n.ins_zhi)},
      {"seed_insert", std::to_string(prime_seed(s.seed, 1))},
      {"n_particles", std::to_string(s.particle_count)},
      {"insert_attempts", std::to_string(kInsertAttempts)},
      {"thermo_every", "5000"},
      {"settle_steps", std::to_string(n.settle_steps)},
      {"windows_required", std::to_string(s.consolidation.windows_required)},
      {"max_windows", std::to_string(s.consolidation.max_windows)},
      {"window_steps", std::to_string(s.consolidation.window_steps)},
      {"approach_windows", std::to_string(n.approach_windows)},
      {"approach_sigma", g(kApproachSigmaShare * s.boundary.sigma_n_Pa)},
      {"sigma_n0", g(s.boundary.sigma_n_Pa)},
      {"sigma_tol", g(s.consolidation.sigma_tolerance)},
      {"plate_tol", g(s.consolidation.plate_tolerance_d50 * n.d50)},
      {"ke_tol", g(s.consolidation.kinetic_energy_J)},
      {"bc", driver::to_string(s.boundary.kind)},
      {"K_Pa_per_m",
       g(s.boundary.kind == driver::BoundaryKind::kCNS ? s.boundary.K_Pa_per_m : 0.0)},
      {"relax_steps", std::to_string(n.relax_steps)},
      {"cv_hold", s.boundary.kind == driver::BoundaryKind::kCV
                      ? "fix_modify P servo/integrate stop  # CV: the plate is held during shear"
                      : "# the servo keeps controlling the plate during shear"},
      {"v_wall", g(s.shear.velocity_m_s)},
      {"wall_displacement", wall_displacement(s.shear)},
      {"wall_motion", wall_motion(s.shear, n.dt)},
      {"wall_speed", wall_speed(s.shear, n.dt)},
      {"wall_travel", wall_travel(s.shear)},
      {"ts_row", kTimeseriesRow},
      {"ts_title", kTimeseriesTitle},
      {"ts_every", std::to_string(n.ts_every)},
      {"progress_every", std::to_string(n.progress_every)},
      {"u_total", g(s.shear.travel_m())},
      {"profile_repeat", std::to_string(n.profile_repeat)},
      {"profile_every", std::to_string(n.profile_every)},
      {"bin_dz", g(s.outputs.profile_bin_d50 * n.d50)},
      {"vtk_every", std::to_string(n.vtk_every)},
      {"shear_steps", std::to_string(n.shear_steps)},
      {"vtk_dir", "dumps"},
      {"z0_consolidated", g(z0_consolidated)},
      {"band_d50", g((n.band_zhi - n.band_zlo) / n.d50)},
      {"band_zlo", g(n.band_zlo)},
      {"band_zhi", g(n.band_zhi)},
      {"servo_kp_shear", g(s.servo.kp_shear)},
  };
  for (auto& [k, v] : shear_entry_values(n, std::nullopt, {})) values[k] = v;
  return values;
}

// --- running a stage --------------------------------------------------------------------

namespace {

// Which attempt of the shear stage this is (shear_checkpoint.hpp): resumed from the checkpoint
// that this input, rendered as a fresh attempt, and this consolidated specimen left (`values`
// then get what differs), or a fresh one.
std::optional<ShearStart> shear_entry(const Scene& s, const Numerics& n, const std::string& text,
                                      const StageContext& ctx, TemplateValues& values) {
  const fs::path record = io::checksum_record_path(ctx.work_dir / "consolidated.restart");
  const std::string basis = render_template(text, values, "shear.in") +
                            (fs::exists(record) ? io::read_file(record) : std::string());
  auto resumed = usable_checkpoint(ctx.work_dir, basis);
  if (!resumed) {
    begin_fresh_shear(ctx.work_dir, basis);
    return resumed;
  }
  prepare_resumed_shear(ctx.work_dir);
  for (auto& [k, v] : shear_entry_values(n, resumed, ctx.work_dir)) values[k] = v;
  values["plate_clamp"] = plate_clamp(s, true);
  if (ctx.progress) ctx.progress("shearing: resumed from the stage's last checkpoint");
  return resumed;
}

}  // namespace

std::vector<std::string> liggghts_command(const std::string& input, int processes,
                                          const std::string& executable) {
  // Line-buffered output: LIGGGHTS prints its ERROR line and then calls MPI_Abort, which loses a
  // block-buffered stdout (seen on Debian's 3.8.0: the message never appears).
  std::vector<std::string> cmd = {"stdbuf", "-oL", executable, "-in", input, "-nocite"};
  if (processes <= 1) return cmd;
  std::vector<std::string> mpi = {"mpirun", "--allow-run-as-root", "--oversubscribe", "-np",
                                  std::to_string(processes)};
  mpi.insert(mpi.end(), cmd.begin(), cmd.end());
  return mpi;
}

// "Loop time of T on P procs for S steps with A atoms, ...": the engine's own cost.
void read_liggghts_loop_time(const std::vector<std::string>& w, EngineCost& cost) {
  if (w.size() >= 12 && w[0] == "Loop" && w[1] == "time" && w[10] == "with") {
    cost.loop_seconds += std::stod(w[3]);
    cost.particle_steps += std::stod(w[8]) * std::stod(w[11]);
  }
}

std::string LiggghtsEngine::version() const {
  std::string v = "unknown";
  try {
    run_process({"liggghts", "-h"}, fs::temp_directory_path(), [&v](const std::string& l) {
      if (l.rfind("LIGGGHTS (", 0) == 0) v = l;
      return true;
    });
  } catch (const std::exception&) {
  }
  return v;
}

nlohmann::json LiggghtsEngine::numerics(const Scene& s) const {
  const Numerics n = derive(s);
  return {
      {"timestep_s", n.dt},
      {"timestep_rule",
       fmt::format("{:g} x Rayleigh time of the smallest particle", s.dt_fraction)},
      {"rayleigh_time_s", rayleigh_time(s.particles)},
      {"shear_steps", n.shear_steps},
      {"wall_velocity_mm_s", s.shear.velocity_m_s * 1e3},
      {"wall_ramp", ramp_numerics(s, n.dt)},
      {"contact_law", fmt::format("pair gran hertz, tangential history, rolling_friction {}; "
                                  "walls: wall/gran hertz on STL "
                                  "meshes",
                                  s.particles.rolling_model)},
      {"servo",
       {{"vel_max_m_s", s.servo.vel_max_m_s}, {"kp", s.servo.kp}, {"kp_shear", s.servo.kp_shear}}}};
}

StageResult LiggghtsEngine::run_stage(const std::string& stage, const StageContext& ctx,
                                      const nlohmann::json& facts) {
  const auto t0 = std::chrono::steady_clock::now();
  const Scene& s = ctx.scene;
  const Numerics n = derive(s);
  write_scene_meshes(s, n.plate_z, ctx.work_dir);
  const std::string input = stage + ".in";
  TemplateValues values =
      liggghts_values(s, n, facts.value("/consolidate/zplate_m"_json_pointer, n.plate_z));
  values.insert(extra_.begin(), extra_.end());
  const std::string& text = liggghts_templates().at(input);
  const std::optional<ShearStart> resumed =
      stage == "shear" ? shear_entry(s, n, text, ctx, values) : std::nullopt;
  io::write_atomically(ctx.work_dir / input, render_template(text, values, input));
  const double generation =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  StageResult r = run_followed_stage(liggghts_command(input, ctx.processes), stage, ctx,
                                     read_liggghts_loop_time);
  r.facts["generation_seconds"] = generation;
  if (resumed) {
    r.facts["step0"] = resumed->step0;  // the follower saw them too; the record is the source
    r.facts["z0_m"] = resumed->z0_m;
    for (const auto& [k, v] : resumed->facts.items()) r.facts[k] = v;
  }
  return r;
}

std::string LiggghtsEngine::unsupported(const Scene& s) const {
  if (s.particles.wet())
    return "[particles] suction_kPa: liquid bridges are modelled in YADE only "
           "(Law2_ScGeom_CapillaryPhys_Capillarity; "
           "run with --engine yade)";
  return {};
}

// consolidate.in as rendered and the meshes: the stage reads nothing else.
std::string LiggghtsEngine::consolidation_inputs(const Scene& s) const {
  const Numerics n = derive(s);
  TemplateValues values = liggghts_values(s, n, n.plate_z);
  values.insert(extra_.begin(), extra_.end());
  const std::string input = std::string(kConsolidationStage) + ".in";
  const SceneMeshes meshes = scene_meshes(s, n.plate_z);
  return render_template(liggghts_templates().at(input), values, input) + meshes.wall_stl +
         meshes.top_stl;
}

// consolidate.in's write_restart; shear.in's sheared.restart is not started from.
std::string LiggghtsEngine::restart_file(const std::string& stage) const {
  return stage == kConsolidationStage ? "consolidated.restart" : "";
}

ContractTables LiggghtsEngine::assemble(const StageContext& ctx, const nlohmann::json& facts) {
  return assemble_liggghts_outputs(ctx, facts, derive(ctx.scene));
}

}  // namespace iwb::dem
