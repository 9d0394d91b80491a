#include "dem/scene/scene.hpp"

#include <fmt/core.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <numeric>
#include <optional>

#include "common/errors.hpp"
#include "common/input_file.hpp"
#include "common/physical_limits.hpp"
#include "dem/scene/scene_keys.hpp"
#include "dem/scene/shear_start.hpp"
#include "io/run_directory.hpp"
#include "io/toml_reader.hpp"
#include "walls/measured_surface.hpp"
#include "walls/random_surface.hpp"

namespace iwb::dem {

namespace {

constexpr double kMm = 1e-3;
constexpr double kMinBoxLengthInDmax = 10.0;      // DEM.md: box length at least 10 d_max
constexpr double kMinWidthInDmax = 3.0;           // periodic images must not touch
constexpr double kRecommendedHeightInD50 = 20.0;  // DEM.md: ~7 d50 gives no band
constexpr double kMinFreeHeightInD50 = 5.0;       // below the plate's clamp: a band is 5-10 d50
constexpr double kMaxCapillaryNumber =
    400.0;  // u* of every capillary table (dem-scripts/yade/capillary)

void require(bool ok, const std::string& message) {
  if (!ok) throw InputError(message);
}

using io::DeclaredTable;

DeclaredTable declared_table(io::TableReader t, const std::string& name) {
  return DeclaredTable(std::move(t), scene_keys(), name);
}

std::vector<SizeClass> read_sizes(DeclaredTable& t, double d50) {
  const auto ratios = t.numbers("d_over_d50");
  const auto fractions = t.numbers("mass_fraction");
  if (ratios.empty()) {
    require(fractions.empty(), t.where("mass_fraction") + " needs d_over_d50 beside it");
    return {{d50, 1.0}};
  }
  require(ratios.size() == fractions.size(),
          fmt::format("{}: d_over_d50 has {} entries and mass_fraction {}; they must match",
                      t.where(), ratios.size(), fractions.size()));
  const double sum = std::accumulate(fractions.begin(), fractions.end(), 0.0);
  require(std::abs(sum - 1.0) < 1e-6,
          fmt::format("{}: mass_fraction sums to {:g}; it must sum to 1", t.where(), sum));
  std::vector<SizeClass> sizes;
  for (std::size_t i = 0; i < ratios.size(); ++i) {
    require(ratios[i] > 0.0 && fractions[i] > 0.0,
            fmt::format("{}: size class {} (d_over_d50 = {:g}, mass_fraction = {:g}) must be > 0",
                        t.where(), i, ratios[i], fractions[i]));
    sizes.push_back({ratios[i] * d50, fractions[i]});
  }
  return sizes;
}

Particles read_particles(DeclaredTable t) {
  Particles p{};
  p.d50_m = t.number("d50_mm") * kMm;
  p.sizes = read_sizes(t, p.d50_m);
  p.density_kg_m3 = t.number("density_kg_m3");
  p.youngs_modulus_Pa = t.number("youngs_modulus_Pa");
  p.poisson = t.number("poisson");
  p.friction = t.number("friction");
  p.rolling_friction = t.number("rolling_friction");
  p.rolling_model = t.text("rolling_model");
  p.restitution = t.number("restitution");
  p.suction_Pa = t.number("suction_kPa") * 1e3;
  p.surface_tension_N_m = t.number("surface_tension_N_m");
  // the capillary tables (dem-scripts/yade/capillary) reach u* = s R / gamma = 400 (600 for the
  // radius ratios up to 1.25), for the largest grain radius of a pair
  const double u_max = p.suction_Pa * 0.5 * p.d_max() / p.surface_tension_N_m;
  require(u_max <= kMaxCapillaryNumber,
          fmt::format("{} = {:g} gives s R_max / gamma = {:.4g} for the largest grains; the "
                      "capillary tables reach {:g} "
                      "(at most {:.3g} kPa here)",
                      t.where("suction_kPa"), p.suction_Pa / 1e3, u_max, kMaxCapillaryNumber,
                      kMaxCapillaryNumber * p.surface_tension_N_m / (0.5 * p.d_max()) / 1e3));
  t.finish();
  return p;
}

// A random self-affine surface over the box (src/walls/random_surface.hpp), its lowest point on the
// wall's base plane.
RoughnessProfile read_random_surface(DeclaredTable& t, const Scene& s) {
  const double d50 = s.particles.d50_m;
  walls::RandomSurfaceSpec spec;
  spec.rms_height_m = t.number("rms_height_d50") * d50;
  spec.correlation_length_m = t.number("correlation_length_d50") * d50;
  spec.hurst = t.number("hurst");
  spec.seed = std::uint64_t(t.whole_number("surface_seed"));
  auto map = std::make_shared<const walls::HeightMap>(
      walls::random_surface(spec, s.length_m, s.width_m, t.number("grid_d50") * d50));
  return {ProfileKind::kRandom, 0.0, map->max(), map};
}

// A measured surface from a file relative to the scene's (src/walls/measured_surface.hpp).
RoughnessProfile read_measured_surface(DeclaredTable& t, Scene& s) {
  walls::MeasuredSurfaceSpec spec;
  const std::string file = t.path("file");
  spec.path = (std::filesystem::path(s.source).parent_path() / file).lexically_normal().string();
  spec.layout =
      t.text("layout") == "map" ? walls::MeasuredLayout::kMap : walls::MeasuredLayout::kLine;
  if (spec.layout == walls::MeasuredLayout::kMap) spec.spacing_m = t.number("spacing_mm") * kMm;
  spec.offset_m = t.number("offset_mm") * kMm;
  spec.scale = t.number("height_scale");
  spec.resample_m = t.number("resample_d50") * s.particles.d50_m;
  try {
    auto m = walls::measured_surface(spec, s.length_m, s.width_m, s.particles.d50_m);
    for (auto& w : m.warnings) s.warnings.push_back(t.where("file") + ": " + w);
    auto map = std::make_shared<const walls::HeightMap>(std::move(m.map));
    return {ProfileKind::kFile, 0.0,
            map->max(),         map,
            spec.path,          io::sha256_hex(io::read_file(spec.path)),
            m.window_r_max_m};
  } catch (const InputError& e) {
    throw InputError(fmt::format("{} = \"{}\": {}", t.where("file"), file, e.what()));
  }
}

// `extra` reads keys a table holds besides the profile (the plate's clamp) before it is finished.
RoughnessProfile read_profile(DeclaredTable t, Scene& s,
                              const std::function<void(DeclaredTable&)>& extra = {}) {
  const double d50 = s.particles.d50_m;
  RoughnessProfile r;
  const std::string kind = t.text("profile");
  if (kind == "sawtooth" || kind == "sinusoid") {
    r.kind = kind == "sawtooth" ? ProfileKind::kSawtooth : ProfileKind::kSinusoid;
    r.pitch_m = t.number("pitch_d50") * d50;
    r.height_m = t.number("height_d50") * d50;
  } else if (kind == "glued") {
    r.kind = ProfileKind::kGlued;
    r.height_m = t.number("sphere_d50") * d50;
    r.pitch_m = t.number("spacing_d50") * d50;
  } else if (kind == "random") {
    r = read_random_surface(t, s);
  } else if (kind == "file") {
    r = read_measured_surface(t, s);
  }
  if (extra) extra(t);
  t.finish();
  return r;
}

// The particles a box holds at the estimated solid fraction (when [specimen] particles is not
// given), refused above the limit of an explicit count: a height of 1e9 d50 must not start an
// engine.
int derived_particle_count(DeclaredTable& spec, const Scene& s) {
  const double n = s.solid_fraction_estimate * s.length_m * s.width_m * s.height_m /
                   s.particles.mean_particle_volume_m3();
  const double d50 = s.particles.d50_m;
  require(
      n >= 1.0 && n <= kMaxParticles,
      fmt::format(
          "{}: length_d50 x width_d50 x height_d50 = {:g} x {:g} x {:g} at solid fraction {:g} "
          "holds {:.4g} particles; allowed 1 to {:g} (set a smaller box or [specimen] particles)",
          spec.where(), s.length_m / d50, s.width_m / d50, s.height_m / d50,
          s.solid_fraction_estimate, n, kMaxParticles));
  return int(std::lround(n));
}

// The wall's and plate's asperities (R_max: a sawtooth's height, a glued sphere, a map's highest
// point) must leave a specimen between them: together at most half its height (issue 60: a 10 m
// measured profile under an 8 d50 specimen reached LIGGGHTS and failed there, or never
// consolidated).
constexpr double kMaxAsperityShareOfHeight = 0.5;

void check_asperities(const Scene& s, const std::string& file) {
  const double d50 = s.particles.d50_m;
  const double wall = s.wall.max_height_m(), plate = s.plate.max_height_m();
  const double total = wall + plate;
  require(total <= kMaxAsperityShareOfHeight * s.height_m + 1e-12,
          fmt::format("{}: the wall's asperities ({:.4g} d50 high) and the plate's ({:.4g} d50) "
                      "take {:.3g} of the specimen's height {:g} d50; allowed at most {:g} (a "
                      "lower wall or plate: height_d50, rms_height_d50, height_scale, "
                      "sphere_d50; or a taller specimen: specimen.height_d50)",
                      file, wall / d50, plate / d50, total / s.height_m, s.height_m / d50,
                      kMaxAsperityShareOfHeight));
}

void check_geometry(Scene& s, const std::string& file) {
  const double dmax = s.particles.d_max();
  require(
      s.length_m >= kMinBoxLengthInDmax * dmax - 1e-12,
      fmt::format(
          "{}: key 'specimen.length_d50' = {:g} gives a box of {:g} mm, shorter than {:g} d_max "
          "= {:g} mm",
          file, s.length_m / s.particles.d50_m, s.length_m / kMm, kMinBoxLengthInDmax,
          kMinBoxLengthInDmax * dmax / kMm));
  require(s.width_m >= kMinWidthInDmax * dmax - 1e-12,
          fmt::format("{}: key 'specimen.width_d50' = {:g} gives {:g} mm, narrower than {:g} d_max",
                      file, s.width_m / s.particles.d50_m, s.width_m / kMm, kMinWidthInDmax));
  for (const auto& [name, prof] : {std::pair{"wall", &s.wall}, std::pair{"plate", &s.plate}}) {
    if (prof->kind == ProfileKind::kFlat || prof->areal())
      continue;  // an areal map is made to tile the box
    const std::string key = prof->kind == ProfileKind::kGlued ? "spacing_d50" : "pitch_d50";
    // glued spheres sit on a square grid: the spacing must divide the width too
    std::vector<std::pair<const char*, double>> sides = {{"length", s.length_m}};
    if (prof->kind == ProfileKind::kGlued) sides.push_back({"width", s.width_m});
    for (const auto& [side, size] : sides) {
      const double n = size / prof->pitch_m;
      require(std::abs(n - std::round(n)) < 1e-9 * n,
              fmt::format("{}: key '{}.{}' = {:g} does not divide the box {} {:g} d50 "
                          "(a periodic wall needs a whole number of periods; {:.4g} here)",
                          file, name, key, prof->pitch_m / s.particles.d50_m, side,
                          size / s.particles.d50_m, n));
    }
  }
  check_asperities(s, file);
  if (s.height_m < kRecommendedHeightInD50 * s.particles.d50_m)
    s.warnings.push_back(
        fmt::format("{}: specimen height {:g} d50 is below {:g} d50; no shear band can "
                    "form (DEM.md), fine for checking the boundary conditions",
                    file, s.height_m / s.particles.d50_m, kRecommendedHeightInD50));
}

// [shear] ramp_transits: the wall's speed ramps from 0 over that many round trips 2 H / c_s of a
// shear wave (c_s: effective-medium estimate at sigma_n); 0 starts at full speed. Cycles start at
// full speed, so only 0 is accepted with them. A ramp longer than the test is allowed with a
// warning.
void read_ramp(DeclaredTable& t, Scene& s) {
  Shear& sh = s.shear;
  sh.ramp_transits =
      t.optional_number("ramp_transits").value_or(sh.cyclic() ? 0.0 : kDefaultRampTransits);
  require(!sh.cyclic() || sh.ramp_transits == 0.0,
          fmt::format("{} = {:g}: cyclic shear starts at full speed; allowed 0 with 'cycles'",
                      t.where("ramp_transits"), sh.ramp_transits));
  sh.shear_wave_speed_m_s = effective_medium_shear_wave_speed(
      s.particles.youngs_modulus_Pa, s.particles.poisson, s.particles.density_kg_m3,
      s.boundary.sigma_n_Pa, s.solid_fraction_estimate);
  sh.ramp_s = ramp_time_s(sh.ramp_transits, s.height_m, sh.shear_wave_speed_m_s);
  if (sh.ramp_s > 0.0 && sh.ramp_displacement_m() >= sh.displacement_m)  // allowed, but say so
    s.warnings.push_back(fmt::format(
        "{} = {:g} ramps the wall over {:.4g} mm, more than displacement_mm = {:g}: "
        "the wall never reaches its speed (below {:.4g} it does)",
        t.where("ramp_transits"), sh.ramp_transits, sh.ramp_displacement_m() / kMm,
        sh.displacement_m / kMm, sh.ramp_transits * sh.displacement_m / sh.ramp_displacement_m()));
}

void read_specimen(DeclaredTable spec, Scene& s) {
  const double d50 = s.particles.d50_m;
  s.length_m = spec.number("length_d50") * d50;
  s.width_m = spec.number("width_d50") * d50;
  s.height_m = spec.number("height_d50") * d50;
  s.solid_fraction_estimate = spec.number("solid_fraction_estimate");
  s.consolidation.friction = spec.number("consolidation_friction");
  s.consolidation.rolling_friction =
      spec.optional_number("consolidation_rolling_friction").value_or(s.particles.rolling_friction);
  const auto given = spec.optional_whole_number("particles");
  s.particle_count = given ? *given : derived_particle_count(spec, s);
  spec.finish();
}

void read_walls(io::TableReader& top, Scene& s) {
  const double d50 = s.particles.d50_m;
  s.wall = read_profile(declared_table(top.required_table("wall"), "wall"), s);
  s.plate =
      read_profile(declared_table(top.required_table("plate"), "plate"), s, [&](DeclaredTable& t) {
        s.plate_clamp_m = t.number("clamp_d50") * d50;
        // the band needs room below the clamped grains (DEM.md: at ~7 d50 no band forms)
        require(s.plate_clamp_m == 0.0 || s.plate_clamp_m <= s.height_m - kMinFreeHeightInD50 * d50,
                fmt::format("{} = {:g} leaves {:g} d50 of the {:g} d50 specimen free to shear; "
                            "allowed: at least {:g} d50",
                            t.where("clamp_d50"), s.plate_clamp_m / d50,
                            (s.height_m - s.plate_clamp_m) / d50, s.height_m / d50,
                            kMinFreeHeightInD50));
      });
}

void read_boundary(DeclaredTable bc, Scene& s) {
  s.boundary.kind = driver::parse_boundary_kind(bc.text("type"), bc.where("type"));
  s.boundary.sigma_n_Pa = bc.number("sigma_n_kPa") * 1e3;
  if (s.boundary.kind == driver::BoundaryKind::kCNS)
    s.boundary.K_Pa_per_m = bc.number("K_kPa_per_mm") * 1e3 / kMm;
  bc.finish();
}

// Cycles stay within the specimen: from +A to -A the wall travels 2A, at most the box's length, so
// that each reversal shears back over grains the half cycle before has met (a periodic box would
// run any travel, but beyond its length a "cycle" no longer reverses one specimen's contacts).
void read_travel(DeclaredTable& sh, const Scene& s, Shear& shear) {
  if (sh.one_of({"displacement_mm", "amplitude_mm"}) == "displacement_mm") {
    require(!sh.has("post_cyclic_mm"),
            fmt::format("{} follows cycles; allowed only with amplitude_mm and cycles "
                        "(monotonic shear: displacement_mm alone)",
                        sh.where("post_cyclic_mm")));
    shear.displacement_m = sh.number("displacement_mm") * kMm;
  } else {
    shear.amplitude_m = sh.number("amplitude_mm") * kMm;
    require(2.0 * shear.amplitude_m <= s.length_m * (1.0 + 1e-12),
            fmt::format("{} = {:g}: a cycle from +A to -A travels {:g} mm, beyond the specimen's "
                        "length of {:g} mm; allowed up to half of it, {:g} mm",
                        sh.where("amplitude_mm"), shear.amplitude_m / kMm,
                        2.0 * shear.amplitude_m / kMm, s.length_m / kMm, 0.5 * s.length_m / kMm));
    shear.cycles = sh.whole_number("cycles");
    shear.post_cyclic_m = sh.number("post_cyclic_mm") * kMm;
  }
}

// The wall's speed, given or from the inertial number I = gamma_dot d50 sqrt(rho / sigma_n) with
// gamma_dot ~ v / H (DEM.md, conservative: the whole specimen as the band); either way I at most
// the declared bound of inertial_number.
void read_speed(DeclaredTable& sh, Scene& s) {
  const double d50 = s.particles.d50_m;
  const double sqrt_rho_over_sigma = std::sqrt(s.particles.density_kg_m3 / s.boundary.sigma_n_Pa);
  if (sh.one_of({"velocity_mm_s", "inertial_number"}) == "velocity_mm_s")
    s.shear.velocity_m_s = sh.number("velocity_mm_s") * kMm;
  else
    s.shear.velocity_m_s = sh.number("inertial_number") * s.height_m / (d50 * sqrt_rho_over_sigma);
  s.shear.inertial_number = s.shear.velocity_m_s / s.height_m * d50 * sqrt_rho_over_sigma;
  const double max_i = io::declared(scene_keys(), "shear", "inertial_number").range.upper;
  require(s.shear.inertial_number <= max_i * (1.0 + 1e-12),
          fmt::format(
              "{} = {:g} shears at an inertial number of {:.3g}; allowed up to {:g} (a granular "
              "gas beyond; DEM.md asks for I < 1e-3): below {:.4g} mm/s here",
              sh.where("velocity_mm_s"), s.shear.velocity_m_s / kMm, s.shear.inertial_number, max_i,
              max_i * s.shear.velocity_m_s / s.shear.inertial_number / kMm));
}

void read_shear(DeclaredTable sh, Scene& s) {
  read_travel(sh, s, s.shear);
  read_speed(sh, s);
  read_ramp(sh, s);
  sh.finish();
}

// An optional table's keys take their declared defaults whether the table is there or not.
template <typename Read>
void read_optional(io::TableReader& top, const std::string& name, Read read) {
  static const toml::table kEmpty;
  auto t = top.table(name);
  DeclaredTable table = declared_table(t ? *t : io::TableReader(kEmpty, top.file(), name), name);
  read(table);
  table.finish();
}

void read_settings(io::TableReader& top, Scene& s) {
  read_optional(top, "consolidation", [&](DeclaredTable& c) {
    auto& co = s.consolidation;
    co.sigma_tolerance = c.number("sigma_tolerance");
    co.plate_tolerance_d50 = c.number("plate_tolerance_d50");
    co.kinetic_energy_J = c.number("kinetic_energy_J");
    co.windows_required = c.whole_number("windows_required");
    co.max_windows = c.whole_number("max_windows");
    co.window_steps = c.whole_number("window_steps");
  });
  const double height_d50 = s.height_m / s.particles.d50_m;
  read_optional(top, "output", [&](DeclaredTable& o) {
    // A spacing beyond the travel would leave the time series with its first row only.
    s.outputs.timeseries_every_m =
        o.number("timeseries_every_mm", non_negative(s.shear.travel_m() / kMm)) * kMm;
    s.outputs.profile_windows = o.whole_number("profile_windows");
    s.outputs.profile_bin_d50 = o.number("profile_bin_d50", non_negative(height_d50));
    s.outputs.vtk_every_m = o.number("vtk_every_mm") * kMm;
  });
  read_optional(top, "coarse_graining", [&](DeclaredTable& cg) {
    s.coarse_graining.enabled = cg.flag("enabled");
    // wider than the specimen's half height, the kernel would average the band away
    s.coarse_graining.width_d50 = cg.number("width_d50", non_negative(0.5 * height_d50));
  });
  const double loop_number =
      servo_loop_number(s.particles.youngs_modulus_Pa, s.boundary.sigma_n_Pa);
  read_optional(top, "servo", [&](DeclaredTable& sv) {
    s.servo.vel_max_m_s = sv.number("vel_max_m_s");
    s.servo.kp = sv.optional_number("kp").value_or(default_consolidation_servo_gain(loop_number));
    s.servo.kp_shear =
        sv.optional_number("kp_shear").value_or(default_shear_servo_gain(loop_number));
  });
  read_optional(top, "numerics",
                [&](DeclaredTable& nu) { s.dt_fraction = nu.number("dt_fraction"); });
}

// A measured wall's file and what tiling did to its R_n.
nlohmann::json file_record(const RoughnessProfile& p, double d50) {
  return {{"file", p.file},
          {"sha256", p.file_sha256},
          {"R_n_untiled", p.untiled_r_max_m / d50},
          {"R_n_tiled", p.normalized_roughness(d50)}};
}

nlohmann::json resolved_values(const Scene& s) {
  const double d50 = s.particles.d50_m;
  nlohmann::json out = {
      {"particles",
       {{"d50_mm", d50 / kMm},
        {"d_max_mm", s.particles.d_max() / kMm},
        {"density_kg_m3", s.particles.density_kg_m3},
        {"youngs_modulus_Pa", s.particles.youngs_modulus_Pa},
        {"poisson", s.particles.poisson},
        {"friction", s.particles.friction},
        {"rolling_friction", s.particles.rolling_friction},
        {"rolling_model", s.particles.rolling_model},
        {"suction_kPa", s.particles.suction_Pa / 1e3},
        {"surface_tension_N_m", s.particles.surface_tension_N_m},
        {"restitution", s.particles.restitution},
        {"count_requested", s.particle_count}}},
      {"specimen",
       {{"length_mm", s.length_m / kMm},
        {"width_mm", s.width_m / kMm},
        {"height_mm", s.height_m / kMm},
        {"consolidation_friction", s.consolidation.friction},
        {"consolidation_rolling_friction", s.consolidation.rolling_friction}}},
      {"wall", {{"profile", s.wall.describe()}, {"R_n", s.wall.normalized_roughness(d50)}}},
      {"plate",
       {{"profile", s.plate.describe()},
        {"R_n", s.plate.normalized_roughness(d50)},
        {"clamp_mm", s.plate_clamp_m / kMm}}},
      {"boundary",
       {{"type", driver::to_string(s.boundary.kind)},
        {"sigma_n_kPa", s.boundary.sigma_n_Pa / 1e3},
        {"K_kPa_per_mm", s.boundary.K_Pa_per_m * kMm / 1e3}}},
      {"shear",
       {{"velocity_mm_s", s.shear.velocity_m_s / kMm},
        {"displacement_mm", s.shear.displacement_m / kMm},
        {"amplitude_mm", s.shear.amplitude_m / kMm},
        {"cycles", s.shear.cycles},
        {"post_cyclic_mm", s.shear.post_cyclic_m / kMm},
        {"travel_mm", s.shear.travel_m() / kMm},
        {"inertial_number", s.shear.inertial_number},
        {"ramp_transits", s.shear.ramp_transits},
        {"shear_wave_speed_estimate_m_s", s.shear.shear_wave_speed_m_s},
        {"ramp_ms", s.shear.ramp_s * 1e3},
        {"ramp_displacement_mm", s.shear.ramp_displacement_m() / kMm}}},
      {"stiffness_level", s.stiffness_level()},
      {"numerics", {{"dt_fraction", s.dt_fraction}}},
      {"seed", s.seed}};
  if (s.wall.kind == ProfileKind::kFile)
    out["wall_file"] = file_record(s.wall, d50);  // only where there is one
  return out;
}

}  // namespace

double Particles::d_max() const {
  double d = 0.0;
  for (const auto& c : sizes) d = std::max(d, c.diameter_m);
  return d;
}

double Particles::d_min() const {
  double d = INFINITY;
  for (const auto& c : sizes) d = std::min(d, c.diameter_m);
  return d;
}

double Particles::mean_particle_volume_m3() const {
  // number fraction of class i ~ mass fraction / particle volume
  double number = 0.0, volume = 0.0;
  for (const auto& c : sizes) {
    const double v = M_PI / 6.0 * std::pow(c.diameter_m, 3);
    number += c.mass_fraction / v;
    volume += c.mass_fraction;
  }
  return volume / number;
}

double Shear::displacement_at(double t) const {
  if (!cyclic()) {
    if (t < ramp_s) return 0.5 * velocity_m_s * t * t / ramp_s;  // v t^2 / (2 T) while ramping
    return velocity_m_s * (t - 0.5 * ramp_s);
  }
  const double travelled = velocity_m_s * t;
  if (travelled >= cycles_travel_m())
    return travelled - cycles_travel_m();        // the post-cyclic shear
  const double phase = travelled / amplitude_m;  // in quarter cycles
  return amplitude_m * (std::abs(std::fmod(phase + 3.0, 4.0) - 2.0) - 1.0);
}

double Shear::speed_at(double t) const {
  if (cyclic() || t >= ramp_s) return velocity_m_s;
  return velocity_m_s * t / ramp_s;
}

double Shear::duration_s() const {
  const double d = travel_m();
  if (cyclic()) return d / velocity_m_s;
  if (d >= ramp_displacement_m()) return d / velocity_m_s + 0.5 * ramp_s;
  return std::sqrt(2.0 * ramp_s * d / velocity_m_s);  // the whole travel within the ramp
}

double servo_loop_number(double youngs_modulus_Pa, double sigma_n_Pa, double plate_factor) {
  constexpr double kTunedModulusPa = 1e8, kTunedStressPa = 50e3;
  return std::pow(youngs_modulus_Pa / kTunedModulusPa, 1.0 / 6.0) *
         std::pow(kTunedStressPa / sigma_n_Pa, 0.75) * plate_factor;
}

double default_shear_servo_gain(double loop_number) {
  constexpr double kTunedGain = 2.0;
  return kTunedGain / std::max(1.0, loop_number);
}

double default_consolidation_servo_gain(double loop_number) {
  constexpr double kTunedGain = 1.0, kMaxLoopGain = 2.0;
  return std::min(kTunedGain, kMaxLoopGain / loop_number);
}

double Scene::stiffness_level() const {
  const auto& p = particles;
  return std::pow(p.youngs_modulus_Pa / ((1.0 - p.poisson * p.poisson) * boundary.sigma_n_Pa),
                  2.0 / 3.0);
}

Scene parse_scene(const std::string& text, const std::string& source) {
  const auto root = io::parse_toml_text(text, source);
  io::TableReader reader(root, source);
  DeclaredTable top = declared_table(reader, "");
  Scene s;
  s.source = source;
  s.name = std::filesystem::path(source).stem().string();
  s.description = top.text("description");
  s.seed = top.whole_number("seed");
  io::TableReader& tables = top.reader();
  s.particles = read_particles(declared_table(tables.required_table("particles"), "particles"));
  read_specimen(declared_table(tables.required_table("specimen"), "specimen"), s);
  read_walls(tables, s);
  check_geometry(s, source);
  read_boundary(declared_table(tables.required_table("boundary"), "boundary"), s);
  read_shear(declared_table(tables.required_table("shear"), "shear"), s);
  read_settings(tables, s);
  if (auto rq = tables.table("requirements")) s.requirements = read_requirements(*rq);
  top.finish();
  s.resolved = resolved_values(s);
  return s;
}

std::string scene_sha256(const Scene& s, const std::string& text) {
  std::string files;
  for (const auto* p : {&s.wall, &s.plate})
    if (p->kind == ProfileKind::kFile) files += "\n" + p->file_sha256;
  return io::sha256_hex(text + files);
}

Scene load_scene(const std::string& path) {
  if (const auto why = unreadable_input_file(path); !why.empty())
    throw InputError(fmt::format("{}: {}", path, why));
  return parse_scene(io::read_file(path), path);
}

}  // namespace iwb::dem
