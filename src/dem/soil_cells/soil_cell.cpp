#include "dem/soil_cells/soil_cell.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "common/errors.hpp"
#include "dem/analysis/summary.hpp"
#include "dem/engines/engines.hpp"
#include "dem/engines/liggghts/liggghts_engine.hpp"
#include "dem/engines/liggghts/periodic_cell_engine.hpp"
#include "dem/engines/yade/yade_engine.hpp"
#include "dem/engines/yade/yade_periodic_cell.hpp"
#include "io/directory_lock.hpp"
#include "io/json_file.hpp"
#include "io/run_directory.hpp"
#include "io/toml_override.hpp"
#include "io/toml_reader.hpp"

namespace iwb::dem {

namespace fs = std::filesystem;
using soil_test::SoilTest;
using soil_test::SoilTestKind;

namespace {

constexpr double kOedometerStartKPa = 10.0;
constexpr double kSimpleShearStartKPa = 50.0;
constexpr double kTimeseriesRows = 200.0;  // simple shear: rows over the whole travel
// cyclic shear: rows a quarter cycle, enough for the secant stiffness at 10 % of the amplitude
constexpr double kRowsPerQuarterCycle = 40.0;
constexpr int kVtkSnapshots = 4;
constexpr int kProfileWindows = 4;
// The periodic cell says when its shear stops being homogeneous, if it does: a profile every
// tenth of the travel.
constexpr int kPeriodicProfileWindows = 10;
constexpr double kGravity = 9.81;  // m/s2, as in the templates

bool oedometer(const SoilCellSpec& c) {
  return c.test == SoilTestKind::kOedometer;
}
bool cyclic(const SoilCellSpec& c) {
  return c.test == SoilTestKind::kCyclicShear;
}
bool periodic(const SoilCellSpec& c) {
  return c.cell == CellKind::kPeriodic;
}

// What the periodic cell does not do (yet): refused before anything is written.
void check_cell(const SoilCellSpec& c) {
  if (!periodic(c)) return;
  if (oedometer(c))
    throw InputError(
        "--cell periodic: the oedometer keeps its plates (the periodic cell shears; an oedometer "
        "has no band to avoid)");
}

double preparation_friction(SoilDensity d, const Scene& scene) {
  switch (d) {
    case SoilDensity::kDense:
      return kDenseConsolidationFriction;
    case SoilDensity::kLoose:
      return kLooseConsolidationFriction;
    case SoilDensity::kAsScene:
      return scene.consolidation.friction;
  }
  return scene.consolidation.friction;
}

// The standard densities roll as the grains do; as-scene keeps the interface specimen's.
double preparation_rolling_friction(SoilDensity d, const Scene& scene) {
  return d == SoilDensity::kAsScene ? scene.consolidation.rolling_friction
                                    : scene.particles.rolling_friction;
}

// Height between the mean surfaces of wall and plate, with the plate's reference at z (m): the
// same as the interface runs' specimen height (contract_outputs.cpp).
double cell_height(const Scene& s, double zplate) {
  return zplate - s.plate.mean_height_m() - s.wall.mean_height_m();
}

// Mean overlap / d50 of a Hertz contact carrying the cell's mean contact force: p = sum(f l)/(3V)
// with branch length l ~ d50 over N Z / 2 contacts gives f = 6 p V / (N Z d50); for two d50
// spheres F = (4/3) E* sqrt(d50/4) delta^1.5 with E* = E / (2 (1 - nu^2)). An estimate (sizes
// and contact forces vary), to say how far the grains' softness reaches into the results.
double mean_overlap_over_d50(double p_Pa, double volume, double particles, double coordination,
                             const Particles& g) {
  if (!(coordination > 0.0) || !(p_Pa > 0.0)) return 0.0;
  const double f = 6.0 * p_Pa * volume / (particles * coordination * g.d50_m);
  const double e_star = g.youngs_modulus_Pa / (2.0 * (1.0 - g.poisson * g.poisson));
  const double delta = std::pow(f / (4.0 / 3.0 * e_star * std::sqrt(0.25 * g.d50_m)), 2.0 / 3.0);
  return delta / g.d50_m;
}

// Stresses from the grains' summed stress x volume (stress/atom: compression negative), kPa.
struct TensorStress {
  double zz, h, mean;
};
TensorStress tensor_stress(double sxx, double syy, double szz, double volume) {
  return {-szz / volume / 1e3, -0.5 * (sxx + syy) / volume / 1e3,
          -(sxx + syy + szz) / (3.0 * volume) / 1e3};
}

// One level: the target force ramps linearly over the first run (LIGGGHTS's ramp() spans a run)
// and is held during the second; then the row.
std::string level_block(int k, int n, double from_Pa, double to_Pa, long ramp, long hold) {
  return fmt::format(
      "# level {k} of {n}: sigma_v -> {to:.6g} Pa\n"
      "print \"IWB_LEVEL {k} {n} {to:.10g}\"\n"
      "variable Ftarget equal v_area*ramp({from:.10g},{to:.10g})\n"
      "run {ramp}\n"
      "variable Ftarget equal v_area*{to:.10g}\n"
      "run {hold}\n"
      "print \"IWB_ROW oedometer {k} ${{r1}} ${{r2}} ${{r3}} ${{r4}} ${{r5}} ${{r6}} ${{r7}} "
      "${{r8}} ${{r9}}\"\n",
      fmt::arg("k", k), fmt::arg("n", n), fmt::arg("from", from_Pa), fmt::arg("to", to_Pa),
      fmt::arg("ramp", ramp), fmt::arg("hold", hold));
}

// The oedometer's stress program for LIGGGHTS: its levels written into oedometer.in.
TemplateValues liggghts_oedometer(const Scene& cell, const SoilCellSpec& c) {
  const long steps = long(c.level_windows) * cell.consolidation.window_steps;
  const auto levels = oedometer_levels_kPa(c);
  std::string program;
  for (std::size_t k = 1; k < levels.size(); ++k)
    program += level_block(int(k), int(levels.size() - 1), levels[k - 1] * 1e3, levels[k] * 1e3,
                           steps, steps);
  // ave/time: every 10 steps over the last half of each window (oedometer.in)
  const long repeat = std::max(1L, cell.consolidation.window_steps / 20L);
  // The plate must follow the ramp up to sigma_max, where the servo's loop number is smallest:
  // a gain chosen at the first level (the consolidation's) fell 6 % short of 160 kPa on the smoke
  // cell. The low levels' faster loop may chatter; their rows average over half a window.
  const double top_Pa = *std::max_element(levels.begin(), levels.end()) * 1e3;
  const double kp =
      std::max(cell.servo.kp, default_consolidation_servo_gain(servo_loop_number(
                                  cell.particles.youngs_modulus_Pa, top_Pa, kCellPlateLoopFactor)));
  return {{"oedometer_levels", program},
          {"servo_kp_oedometer", fmt::format("{:g}", kp)},
          {"ramp_steps", std::to_string(steps)},
          {"hold_steps", std::to_string(steps)},
          {"avg_repeat", std::to_string(repeat)}};
}

// The same program for YADE (interface_shear.py's oedometer stage): levels, ramp and hold steps,
// rows averaged every 10 steps over the last half window, as LIGGGHTS's ave/time; the servo counts
// the cell's grain layers (one per d50 of height) in series with the plate's contacts.
nlohmann::json yade_oedometer(const Scene& cell, const SoilCellSpec& c) {
  const long steps = long(c.level_windows) * cell.consolidation.window_steps;
  nlohmann::json levels = nlohmann::json::array();
  for (const double kPa : oedometer_levels_kPa(c)) levels.push_back(kPa * 1e3);
  return {{"oedometer",
           {{"levels_Pa", levels},
            {"ramp_steps", steps},
            {"hold_steps", steps},
            {"avg_every", 10},
            {"avg_steps", cell.consolidation.window_steps / 2},
            {"layers", c.height_d50}}}};
}

std::unique_ptr<Engine> cell_engine(const Scene& cell, const SoilCellSpec& c) {
  if (periodic(c) && c.engine == "yade") return std::make_unique<YadePeriodicCell>();
  if (periodic(c)) return std::make_unique<LiggghtsPeriodicCell>();
  if (!oedometer(c)) return make_engine(c.engine);
  const std::vector<std::string> stages{"consolidate", "oedometer"};
  if (c.engine == "yade") return std::make_unique<YadeEngine>(stages, yade_oedometer(cell, c));
  if (c.engine == "liggghts")
    return std::make_unique<LiggghtsEngine>(stages, liggghts_oedometer(cell, c));
  return make_engine(c.engine);  // names the engines available
}

SoilTest oedometer_result(const Scene& cell, const nlohmann::json& facts) {
  SoilTest t;
  t.kind = SoilTestKind::kOedometer;
  const double particles = facts.at("consolidate").at("particles").get<double>();
  const auto& rows = facts.at("oedometer").at("rows").at("oedometer");
  double h0 = 0.0;
  std::vector<double> sigma_h, k0, coordination, overlap;
  for (const auto& r : rows) {
    const double h = cell_height(cell, r[3].get<double>()), volume = cell.area_m2() * h;
    if (t.rows() == 0) h0 = h;
    const auto ts =
        tensor_stress(r[5].get<double>(), r[6].get<double>(), r[7].get<double>(), volume);
    // The bottom wall's stress less half the grains' weight: the mid-height vertical stress. (The
    // plate's own force output, f_P[3], reported twice the grains' load through a whole run after
    // the restart on LIGGGHTS 3.8.0 while the wall and the stress tensor agreed: it is not used.)
    const double half_weight =
        0.5 * cell.particles.density_kg_m3 * kGravity * r[4].get<double>() / cell.area_m2();
    t.control.push_back((r[1].get<double>() - half_weight) / 1e3);
    t.eps_v.push_back(1.0 - h / h0);
    t.e.push_back(volume / r[4].get<double>() - 1.0);
    sigma_h.push_back(ts.h);
    k0.push_back(ts.h / ts.zz);
    coordination.push_back(r[8].get<double>());
    overlap.push_back(mean_overlap_over_d50(ts.mean * 1e3, volume, particles, r[8].get<double>(),
                                            cell.particles));
  }
  if (t.rows() == 0) throw InputError("oedometer: the engine reported no rows");
  t.sigma0_kPa = t.control.front();
  t.e0 = t.e.front();
  t.K0 = k0.front();
  t.extra_columns = {{"sigma_h_kPa", sigma_h},
                     {"K0", k0},
                     {"coordination", coordination},
                     {"overlap_mean_over_d50_estimate", overlap}};
  return t;
}

// R^2 of a straight line through vx/v_wall against height in each profile window (by the window's
// wall travel, mm): 1 for the homogeneous shear a simple-shear cell should have, lower where shear
// localises.
std::vector<std::pair<double, double>> profile_linearity(const io::CsvTable& profiles) {
  std::map<double, std::vector<std::pair<double, double>>> windows;
  for (const auto& r : profiles.rows) windows[r[0]].emplace_back(r[1], r[2]);
  std::vector<std::pair<double, double>> out;
  for (const auto& [u, p] : windows) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0, syy = 0;
    const double n = double(p.size());
    for (const auto& [x, y] : p) sx += x, sy += y, sxx += x * x, sxy += x * y, syy += y * y;
    const double cov = sxy - sx * sy / n, vx = sxx - sx * sx / n, vy = syy - sy * sy / n;
    out.emplace_back(u, vx > 0.0 && vy > 0.0 ? cov * cov / (vx * vy) : 0.0);
  }
  return out;
}

nlohmann::json linearity_json(const io::CsvTable& profiles) {
  const auto by_window = profile_linearity(profiles);
  nlohmann::json windows = nlohmann::json::array();
  double lowest = by_window.empty() ? 0.0 : 1.0;
  for (const auto& [u, r2] : by_window) {
    windows.push_back({{"u_x_mm_window", u}, {"r2", r2}});
    lowest = std::min(lowest, r2);
  }
  return {{"profile_linearity_r2", by_window.empty() ? 0.0 : by_window.back().second},
          {"profile_linearity_r2_by_window", windows},
          {"profile_linearity_r2_lowest", lowest},
          {"homogeneous", !by_window.empty() && lowest >= soil_test::kHomogeneousCellR2},
          {"homogeneous_r2_threshold", soil_test::kHomogeneousCellR2},
          {"homogeneous_rule", fmt::format("R^2 of vx/v_wall against height at least {:g} in every "
                                           "profile window",
                                           soil_test::kHomogeneousCellR2)}};
}

// The cell's summary (manifest cell_summary): the interface summary's quantities of its series,
// and how homogeneously it sheared.
nlohmann::json cell_summary(const Scene& cell, const io::CsvTable& timeseries,
                            const io::CsvTable& profiles, bool periodic_cell) {
  auto summary = to_json(summarize(cell, timeseries, profiles));
  summary.update(linearity_json(profiles));
  summary["definitions"]["element_until_gamma"] =
      "a periodic cell's gamma up to which it sheared as an element (calibration's "
      "element_until_gamma): 0 throughout (or not a periodic cell), -1 not from the first window";
  if (periodic_cell)  // no wall, no plate: what the interface summary reads at them is not there
    for (const char* key :
         {"wall_slip", "wall_share_of_velocity_drop", "far_field_speed", "wall_band_d50",
          "plate_band_d50", "band_thickness_d50", "band_thickness_erfc_fit_d50"})
      summary.erase(key);
  return summary;
}

SoilTest simple_shear_result(const Scene& cell, const ContractTables& tables,
                             const nlohmann::json& facts, SoilTestKind kind) {
  SoilTest t;
  t.kind = kind;
  t.boundary = cell.boundary.kind;
  const auto& sh = facts.at("shear");
  const double h0 = cell_height(cell, sh.at("z0_m").get<double>());
  const auto ts = tensor_stress(sh.value("stress_volume_xx_Pa_m3", 0.0),
                                sh.value("stress_volume_yy_Pa_m3", 0.0),
                                sh.value("stress_volume_zz_Pa_m3", 0.0), cell.area_m2() * h0);
  const auto& ts_table = tables.timeseries;
  const auto col = [&](const char* name) { return ts_table.values(name, "timeseries"); };
  const auto ux = col("u_x_mm"), un = col("u_n_mm"), sn = col("sigma_n_kPa"), tau = col("tau_kPa"),
             e = col("e_specimen"), plate = col("sigma_plate_kPa");
  std::vector<double> ux_out, un_out, plate_out;
  for (std::size_t i = 0; i < ux.size(); ++i) {
    const double gamma = ux[i] * 1e-3 / h0;
    // the contract: gamma increases (monotonic) or moves every row (cyclic)
    if (!t.control.empty() && (kind == SoilTestKind::kCyclicShear ? gamma == t.control.back()
                                                                  : !(gamma > t.control.back())))
      continue;
    t.control.push_back(gamma);
    t.tau_kPa.push_back(tau[i]);
    t.sigma_n_kPa.push_back(sn[i]);
    t.e.push_back(e[i]);
    ux_out.push_back(ux[i]), un_out.push_back(un[i]), plate_out.push_back(plate[i]);
  }
  if (t.rows() == 0) throw InputError("simple shear: the engine reported no rows");
  t.sigma0_kPa = cell.boundary.sigma_n_Pa / 1e3;
  t.e0 = t.e.front();
  if (ts.zz > 0.0 && ts.h > 0.0) t.K0 = ts.h / ts.zz;
  t.extra_columns = {{"u_x_mm", ux_out}, {"u_n_mm", un_out}, {"sigma_plate_kPa", plate_out}};
  return t;
}

nlohmann::json fresh_manifest(const std::string& text, const std::string& source,
                              const std::string& cell_text, const Scene& cell,
                              const SoilCellSpec& c, Engine& engine, const RunOptions& opt) {
  return {
      {"kind", "soiltest"},
      {"test", soil_test::to_string(c.test)},
      {"source", "dem:" + engine.name()},
      {"workbench", {{"name", "iwb"}, {"version", IWB_VERSION}}},
      {"engine",
       {{"name", engine.name()}, {"version", engine.version()}, {"processes", opt.processes}}},
      {"command_line", opt.command_line},
      {"scene", {{"source", source}, {"sha256", io::sha256_hex(text)}, {"text", text}}},
      {"cell_scene",
       {{"sha256", io::sha256_hex(cell_text)}, {"text", cell_text}, {"resolved", cell.resolved}}},
      {"density", to_string(c.density)},
      {"cell", to_string(c.cell)},
      {"consolidation_friction", cell.consolidation.friction},
      {"seed", cell.seed},
      {"numerics", engine.numerics(cell)},
      {"stiffness_level", cell.stiffness_level()},
      {"warnings", cell.warnings},
      {"stages", nlohmann::json::object()},
      {"started", io::utc_timestamp()},
      {"status", "running"}};
}

}  // namespace

CellKind parse_cell_kind(const std::string& text, const std::string& where) {
  if (text == "plates") return CellKind::kPlates;
  if (text == "periodic") return CellKind::kPeriodic;
  throw InputError(fmt::format("{} = '{}': allowed plates or periodic", where, text));
}

const char* to_string(CellKind k) {
  return k == CellKind::kPeriodic ? "periodic" : "plates";
}

SoilDensity parse_soil_density(const std::string& text, const std::string& where) {
  if (text == "dense") return SoilDensity::kDense;
  if (text == "loose") return SoilDensity::kLoose;
  if (text == "as-scene") return SoilDensity::kAsScene;
  throw InputError(fmt::format("{} = '{}': allowed dense, loose or as-scene", where, text));
}

const char* to_string(SoilDensity d) {
  switch (d) {
    case SoilDensity::kDense:
      return "dense";
    case SoilDensity::kLoose:
      return "loose";
    case SoilDensity::kAsScene:
      return "as-scene";
  }
  return "?";
}

double SoilCellSpec::initial_stress_kPa() const {
  if (sigma0_kPa > 0.0) return sigma0_kPa;
  return test == SoilTestKind::kOedometer ? kOedometerStartKPa : kSimpleShearStartKPa;
}

std::vector<double> oedometer_levels_kPa(const SoilCellSpec& c) {
  const double s0 = c.initial_stress_kPa();
  if (!(c.sigma_max_kPa > s0))
    throw InputError(fmt::format("--sigma-max = {:g} kPa: must exceed the first level, {:g} kPa",
                                 c.sigma_max_kPa, s0));
  std::vector<double> out{s0};
  for (int k = 1; k <= c.load_levels; ++k)
    out.push_back(s0 * std::pow(c.sigma_max_kPa / s0, double(k) / c.load_levels));
  for (int k = 1; k <= c.unload_levels; ++k)
    out.push_back(c.sigma_max_kPa * std::pow(s0 / c.sigma_max_kPa, double(k) / c.unload_levels));
  return out;
}

namespace {

// The cell's plates carry a higher loop gain than the scene's plate (kCellPlateLoopFactor): the
// gains the scene states are kept, the defaults follow the cell's own loop number.
void set_cell_servo_gains(toml::table& root, const Scene& base, const SoilCellSpec& c,
                          const std::string& source) {
  const double loop = servo_loop_number(base.particles.youngs_modulus_Pa,
                                        c.initial_stress_kPa() * 1e3, kCellPlateLoopFactor);
  if (!root.at_path("servo.kp"))
    io::set_dotted(root, "servo.kp", default_consolidation_servo_gain(loop), source);
  if (!root.at_path("servo.kp_shear"))
    io::set_dotted(root, "servo.kp_shear", default_shear_servo_gain(loop), source);
}

}  // namespace

std::string cell_scene_text(const std::string& text, const std::string& source,
                            const SoilCellSpec& c) {
  check_cell(c);
  const Scene base = parse_scene(text, source);  // the scene must be valid as given
  toml::table root = io::parse_toml_text(text, source);
  for (const char* table : {"specimen", "wall", "plate", "boundary", "shear", "output"})
    root.erase(table);
  const double d50_mm = base.particles.d50_m * 1e3;
  const double amplitude_mm = c.gamma_amplitude * c.height_d50 * d50_mm;
  const double travel_mm = oedometer(c) ? d50_mm
                           : cyclic(c)  ? 4.0 * amplitude_mm * c.cycles
                                        : c.gamma * c.height_d50 * d50_mm;
  const double row_mm =
      cyclic(c) ? amplitude_mm / kRowsPerQuarterCycle : travel_mm / kTimeseriesRows;
  const std::string what = oedometer(c)
                               ? "oedometer"
                               : fmt::format("{} shear {}", cyclic(c) ? "cyclic" : "simple",
                                             driver::to_string(c.boundary));
  const auto set = [&](const std::string& key, const io::TomlValue& v) {
    io::set_dotted(root, key, v, source);
  };
  set("description",
      fmt::format("soil cell ({}, {}) of {}: {:g} x {:g} x {:g} d50 {}", what, to_string(c.density),
                  source, c.length_d50, c.width_d50, c.height_d50,
                  periodic(c)
                      ? "fully periodic, sheared by the box's tilt ([wall] and [plate] unused)"
                      : "between rough plates"));
  set("specimen.length_d50", c.length_d50);
  set("specimen.width_d50", c.width_d50);
  set("specimen.height_d50", c.height_d50);
  set("specimen.consolidation_friction", preparation_friction(c.density, base));
  set("specimen.consolidation_rolling_friction", preparation_rolling_friction(c.density, base));
  for (const std::string side : {"wall", "plate"}) {
    // the periodic cell has neither: flat, of no height, they keep the height the box's own
    set(side + ".profile", std::string(periodic(c) ? "flat" : "sawtooth"));
    if (periodic(c)) continue;
    set(side + ".pitch_d50", kCellPitchD50);
    set(side + ".height_d50", kCellRidgeD50);
  }
  set("boundary.type", std::string(oedometer(c) ? "CNL" : driver::to_string(c.boundary)));
  set("boundary.sigma_n_kPa", c.initial_stress_kPa());
  set_cell_servo_gains(root, base, c, source);
  set("shear.inertial_number", c.inertial_number);
  if (cyclic(c)) {
    set("shear.amplitude_mm", amplitude_mm);
    set("shear.cycles", std::int64_t(c.cycles));
  } else {
    set("shear.displacement_mm", travel_mm);  // the oedometer does not shear: a placeholder
  }
  set("output.timeseries_every_mm", row_mm);
  set("output.profile_windows",
      std::int64_t(periodic(c) ? kPeriodicProfileWindows : kProfileWindows));
  set("output.profile_bin_d50", 0.5);
  set("output.vtk_every_mm", travel_mm / kVtkSnapshots);
  return fmt::format(
      "# Soil cell derived by `iwb dem soiltest` from {}: its particles, seed and\n"
      "# consolidation with the cell's geometry and loading "
      "(src/dem/soil_cells/soil_cell.hpp).\n{}",
      source, io::serialise(root));
}

namespace {

// The cell's keys its options set (dem soiltest --length ...): a cell they make invalid is
// refused naming the option, not a key of the scene the user would look for in vain (issue 60).
struct OptionKey {
  const char* key;
  const char* option;
  double SoilCellSpec::*value;
};
constexpr OptionKey kOptionKeys[] = {
    {"specimen.length_d50", "--length", &SoilCellSpec::length_d50},
    {"specimen.width_d50", "--width", &SoilCellSpec::width_d50},
    {"specimen.height_d50", "--height", &SoilCellSpec::height_d50}};

Scene parse_cell_scene(const std::string& cell_text, const std::string& source,
                       const SoilCellSpec& c) {
  try {
    return parse_scene(cell_text, source + " (soil cell)");
  } catch (const InputError& e) {
    const std::string message = e.what();
    for (const auto& k : kOptionKeys)
      if (message.find(fmt::format("key '{}'", k.key)) != std::string::npos)
        throw InputError(
            fmt::format("{} {:g}: {} (the cell's key is set by {}, not read from the scene)",
                        k.option, c.*k.value, message, k.option));
    throw;
  }
}

}  // namespace

RunOutcome run_soil_test(const std::string& text, const std::string& source, const SoilCellSpec& c,
                         const RunOptions& opt) {
  const std::string cell_text = cell_scene_text(text, source, c);
  const Scene cell = parse_cell_scene(cell_text, source, c);
  const auto engine_ptr = cell_engine(cell, c);
  Engine& engine = *engine_ptr;
  RunOutcome out;
  const auto run = run_stages(
      cell, cell_text, engine, opt, "soiltest",
      [&] { return fresh_manifest(text, source, cell_text, cell, c, engine, opt); }, out,
      "/cell_scene/sha256");
  if (!run || run->complete_before) return out;
  auto& m = out.manifest;
  try {
    SoilTest t;
    if (oedometer(c)) {
      t = oedometer_result(cell, run->facts);
    } else {
      const ContractTables tables = engine.assemble(run->ctx, run->facts);
      t = simple_shear_result(cell, tables, run->facts, c.test);
      io::write_atomically(opt.out / "profiles.csv", tables.profiles.to_csv());
      m["cell_summary"] = cell_summary(cell, tables.timeseries, tables.profiles, periodic(c));
      m["engine_facts"] = tables.facts;
      m["gamma_reached"] = t.control.back();
      m["cell_summary"]["element_until_gamma"] = soil_test::element_until_gamma(m);
      m["files"] = periodic(c)
                       ? nlohmann::json{"timeseries.csv", "profiles.csv"}
                       : nlohmann::json{"timeseries.csv", "profiles.csv", "vtk/particles.pvd",
                                        "vtk/contacts.pvd", "vtk/walls.pvd"};
    }
    t.name = opt.out.string();
    t.source = "dem:" + engine.name();
    m["particle_count"] = run->facts.value("/consolidate/particles"_json_pointer, 0);
    m["finished"] = io::utc_timestamp();
    soil_test::write_soil_test_files(t, opt.out, m);
    soil_test::read_soil_test(opt.out);  // what calibrate will read: the contract must hold
    m = nlohmann::json::parse(io::read_file(opt.out / "manifest.json"));
    out.status = "complete";
  } catch (const std::exception& e) {
    out.status = fmt::format("failed: {}", e.what());
    m["status"] = out.status;
    io::write_manifest(opt.out, m);
  }
  return out;
}

// The summary's keys derived from the time series alone (src/dem/analysis/summary.cpp to_json): the
// rest come from the profiles.
constexpr const char* kSeriesSummaryKeys[] = {"peak_friction",
                                              "u_x_at_peak_mm",
                                              "dilation_mm",
                                              "dilatancy_angle_deg",
                                              "sigma_n_mean_kPa",
                                              "sigma_n_max_relative_deviation",
                                              "residual_friction",
                                              "residual_is",
                                              "residual_test",
                                              "residual_drift_over_last_fifth",
                                              "dilatancy_rate_at_peak",
                                              "end_of_path_friction",
                                              "last_cycle_mean_friction",
                                              "cyclic",
                                              "definitions"};

nlohmann::json resummarize_cell(const fs::path& dir) {
  const fs::path manifest = dir / "manifest.json";
  if (!fs::exists(manifest))
    throw InputError(fmt::format("{}: not a run directory (no manifest.json)", dir.string()));
  const auto lock = io::DirectoryLock::take(dir, "iwb dem summary");
  auto m = io::read_json_file(manifest);
  const auto status = io::json_field<std::string>(m, "/status", manifest);
  if (status != "complete" || !m.contains("cell_summary"))
    throw InputError(
        fmt::format("{}: a soil test whose status is '{}'{}; only complete simple "
                    "shear cells are summarised",
                    manifest.string(), status,
                    m.contains("cell_summary") ? "" : " and without a cell_summary"));
  const Scene cell = parse_scene(io::json_field<std::string>(m, "/cell_scene/text", manifest),
                                 manifest.string() + ": /cell_scene/text");
  const auto ts = io::read_csv_table(dir / "timeseries.csv");
  for (const char* column : {"u_x_mm", "u_n_mm", "sigma_n_kPa", "tau_kPa"})
    if (ts.column(column) < 0)
      throw InputError(
          fmt::format("{}: no column '{}'", (dir / "timeseries.csv").string(), column));
  // cells run before the periodic one existed record no "cell": they had plates
  const bool periodic_cell = m.value("cell", std::string("plates")) == "periodic";
  const bool profiles_kept = fs::exists(dir / "profiles.csv");
  auto fresh = cell_summary(
      cell, ts, profiles_kept ? io::read_csv_table(dir / "profiles.csv") : io::CsvTable{},
      periodic_cell);
  if (!profiles_kept) {  // cells committed without profiles.csv: what it gave stays as written
    auto kept = m["cell_summary"];
    for (const char* key : kSeriesSummaryKeys)
      if (fresh.contains(key))
        kept[key] = fresh[key];
      else
        kept.erase(key);
    fresh = kept;
  }
  m["cell_summary"] = fresh;
  m["cell_summary"]["element_until_gamma"] = soil_test::element_until_gamma(m);
  io::write_atomically(manifest, m.dump(2) + "\n");
  return m["cell_summary"];
}

}  // namespace iwb::dem
