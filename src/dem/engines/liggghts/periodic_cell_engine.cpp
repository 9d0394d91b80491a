#include "dem/engines/liggghts/periodic_cell_engine.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/errors.hpp"
#include "common/template.hpp"
#include "dem/engines/contract_outputs.hpp"
#include "dem/engines/liggghts/liggghts_engine.hpp"
#include "dem/engines/stage_follower.hpp"
#include "dem/scene/numerics.hpp"
#include "dem/scene/periodic_cell.hpp"
#include "io/run_directory.hpp"

namespace iwb::dem {

namespace fs = std::filesystem;

namespace {

std::string gp(double x) {
  return fmt::format("{:.10g}", x);
}

// The profile's bin as a share of the box height: a whole number of bins of about profile_bin_d50
// in the target height, so that the bins tile the box. A hair wider than 1/n: ave/spatial makes
// ceil(1/delta) bins, 13 for a delta printed as 0.08333333333.
double bin_share(const Scene& s) {
  const double d = s.outputs.profile_bin_d50 * s.particles.d50_m;
  return (1.0 + 1e-9) / double(std::max(1L, std::lround(s.height_m / d)));
}

// The box's motion while shearing: its tilt at the wall's speed (monotonic) or following the
// wall's displacement (cycles, whose tilt never reaches the flip at half the length), the height
// servo-controlled (CNL) or held (CV). One fix deform: LIGGGHTS allows no second.
std::string box_motion(const Scene& s) {
  const std::string tilt = s.shear.cyclic() ? "xz variable v_ux v_vw"
                                            : fmt::format("xz vel {}", gp(s.shear.velocity_m_s));
  const std::string height =
      s.boundary.kind == driver::BoundaryKind::kCV ? "" : " z variable v_dZ v_vz";
  return fmt::format("fix def all deform 1 {}{} remap v", tilt, height);
}

TemplateValues periodic_values(const Scene& s, const Numerics& n, double z0) {
  TemplateValues v = liggghts_values(s, n, z0);
  const double margin = 0.5 * s.particles.d_max();
  const double lz = periodic_insertion_height(s, margin);
  const PeriodicServoGains k = periodic_servo_gains(s, n.dt);
  // a sample every 10 steps through the second half of the window (n.profile_every is a
  // multiple of 10: dem/scene/numerics.cpp; ave/spatial wants the window a multiple of the period)
  const long sample_every = 10, samples = std::max(1L, n.profile_every / (2 * sample_every));
  const TemplateValues periodic = {
      {"Lz_insert", gp(lz)},
      {"ins_margin", gp(margin)},
      {"ins_x_hi", gp(s.length_m - margin)},
      {"ins_y_hi", gp(s.width_m - margin)},
      {"ins_z_hi", gp(lz - margin)},
      {"kz_consolidation", gp(k.consolidation)},
      {"kz_shear", gp(k.shear)},
      {"bin_reduced", fmt::format("{:.15g}", bin_share(s))},
      {"box_motion", box_motion(s)},
      {"profile_samples", std::to_string(samples)},
      {"profile_sample_every", std::to_string(sample_every)},
  };
  for (const auto& [key, value] : periodic) v[key] = value;
  return v;
}

// fix ave/spatial blocks in reduced units: a header "step bins", then per bin: bin, z / lz,
// count, vx, mean particle volume, mean s_zz*V, mean s_xz*V (stress/atom, compression negative;
// s_xz is positive for a growing tilt). A bin is 1/bins of the box, whose height at that step is
// z0 + u_n of the nearest row of the time series.
ProfileBlocks periodic_profile_blocks(const fs::path& raw, const Scene& s, const Numerics& n,
                                      const io::CsvTable& timeseries, long step0, double z0) {
  const auto height_at = [&](long step) {
    const double t = double(step - step0) * n.dt;
    double u_n_mm = 0.0, gap = 1e300;
    for (const auto& r : timeseries.rows)  // t_s, u_x_mm, u_n_mm, ...
      if (std::abs(r[0] - t) < gap) gap = std::abs(r[0] - t), u_n_mm = r[2];
    return z0 + u_n_mm * 1e-3;
  };
  ProfileBlocks blocks;
  std::ifstream in(raw);
  if (!in) throw std::runtime_error(fmt::format("{}: missing engine output", raw.string()));
  long step = -1;
  double height = z0, share = 1.0;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream is(line);
    std::vector<double> v;
    for (double x; is >> x;) v.push_back(x);
    if (v.size() == 2) step = long(v[0]), height = height_at(step), share = 1.0 / v[1];
    if (v.size() < 7) continue;
    const double bin_volume = share * s.area_m2() * height;
    blocks[step].push_back({v[1] * height / n.d50, v[2], v[3], v[2] * v[4] / bin_volume,
                            -v[2] * v[5] / bin_volume, v[2] * v[6] / bin_volume});
  }
  return blocks;
}

}  // namespace

std::string liggghts_tri_path() {
  std::error_code ec;
  const fs::path here = fs::read_symlink("/proc/self/exe", ec).parent_path() / "liggghts_tri";
  if (!ec && fs::exists(here)) return here.string();
  if (fs::exists(IWB_LIGGGHTS_TRI)) return IWB_LIGGGHTS_TRI;
  throw InputError(fmt::format(
      "the periodic cell needs liggghts_tri (LIGGGHTS with the triclinic fix), found neither next "
      "to iwb ({}) nor where the build put it ({}): build it with `cmake --build build --target "
      "liggghts_tri`",
      here.string(), IWB_LIGGGHTS_TRI));
}

std::string LiggghtsPeriodicCell::version() const {
  return LiggghtsEngine().version() + " via liggghts_tri (upstream's triclinic fix applied)";
}

nlohmann::json LiggghtsPeriodicCell::numerics(const Scene& s) const {
  nlohmann::json j = LiggghtsEngine().numerics(s);
  const PeriodicServoGains k = periodic_servo_gains(s, derive(s).dt);
  j["cell"] = "fully periodic, sheared by the box's tilt (Lees-Edwards), no walls, no gravity";
  j["contact_law"] =
      fmt::format("pair gran hertz, tangential history, rolling_friction {}; no walls",
                  s.particles.rolling_model);
  j["servo"] = {{"vel_max_m_s", s.servo.vel_max_m_s},
                {"height_gain_consolidation_m_s_per_Pa", k.consolidation},
                {"height_gain_shear_m_s_per_Pa", k.shear}};
  return j;
}

StageResult LiggghtsPeriodicCell::run_stage(const std::string& stage, const StageContext& ctx,
                                            const nlohmann::json& facts) {
  const Scene& s = ctx.scene;
  const Numerics n = derive(s);
  const std::string input = "periodic_" + stage + ".in";
  const TemplateValues values =
      periodic_values(s, n, facts.value("/consolidate/zplate_m"_json_pointer, s.height_m));
  io::write_atomically(ctx.work_dir / input,
                       render_template(liggghts_templates().at(input), values, input));
  return run_followed_stage(liggghts_command(input, ctx.processes, liggghts_tri_path()), stage, ctx,
                            read_liggghts_loop_time);
}

std::string LiggghtsPeriodicCell::consolidation_inputs(const Scene& s) const {
  const std::string input = "periodic_consolidate.in";
  return render_template(liggghts_templates().at(input), periodic_values(s, derive(s), s.height_m),
                         input);
}

std::string LiggghtsPeriodicCell::restart_file(const std::string& stage) const {
  return stage == kConsolidationStage ? "consolidated.restart" : "";
}

ContractTables LiggghtsPeriodicCell::assemble(const StageContext& ctx,
                                              const nlohmann::json& facts) {
  const long step0 = facts.at("shear").at("step0").get<long>();
  const double z0 = facts.at("shear").at("z0_m").get<double>();
  const Scene& s = ctx.scene;
  const Numerics n = derive(s);
  ContractTables out;
  out.timeseries = timeseries_table(s, n, ctx.work_dir / "timeseries.raw", z0);
  // the whole cell is the band
  band_is_the_cell(out.timeseries);
  out.profiles = profile_table(
      s, n, periodic_profile_blocks(ctx.work_dir / "profiles.raw", s, n, out.timeseries, step0, z0),
      step0);
  out.facts = plate_facts(s, out.timeseries);
  out.facts["timestep_s"] = n.dt;
  out.facts["shear_start_step"] = step0;
  return out;
}

}  // namespace iwb::dem
