#include "dem/scene.hpp"

#include <cmath>
#include <filesystem>
#include <fmt/core.h>
#include <functional>
#include <numeric>

#include "common/errors.hpp"
#include "common/physical_limits.hpp"
#include "dem/shear_start.hpp"
#include "io/run_directory.hpp"
#include "io/toml_reader.hpp"

namespace iwb::dem {

namespace {

constexpr double kMm = 1e-3;
constexpr double kMinBoxLengthInDmax = 10.0;    // DEM.md: box length at least 10 d_max
constexpr double kMinWidthInDmax = 3.0;         // periodic images must not touch
constexpr double kRecommendedHeightInD50 = 20.0;  // DEM.md: ~7 d50 gives no band
constexpr double kMinFreeHeightInD50 = 5.0;       // below the plate's clamp: a band is 5-10 d50
constexpr double kMaxSuctionKPa = 1e4;
constexpr double kMaxCapillaryNumber = 400.0;     // u* of every capillary table (dem-scripts/yade/capillary)
constexpr double kDefaultDtFraction = 0.15;  // of the Rayleigh time: the usual DEM choice
constexpr double kMaxDtFraction = 0.5;       // beyond this Hertz contacts lose energy balance

// Physical ranges of scene values: each bound lies far outside what an interface-shear scene uses
// and inside what the engines can take, so a typo or a units mistake (kPa for Pa, a missing
// exponent) is refused with its key before an engine starts instead of failing inside it.
constexpr double kMaxD50Mm = 100.0;                // cobbles; a box of them is metres long
constexpr double kMaxDensityKgM3 = 1e5;            // 4x osmium: room for density scaling
constexpr double kMaxYoungsModulusPa = 1.2e12;     // diamond
constexpr double kMaxFriction = 10.0;              // a coefficient, not an angle in degrees
constexpr double kMaxSolidFraction = 0.75;         // densest sphere packing 0.7405
constexpr double kMaxLengthD50 = 1e5;              // the particle count bounds the box anyway
constexpr double kMaxParticles = 1e8;              // as for an explicit [specimen] particles
constexpr double kMaxCnsStiffnessKPaPerMm = 1e7;   // stiffer than the grains: use CV
constexpr double kMaxTravelMm = 1e4;               // 10 m of wall travel
// I = gamma_dot d50 sqrt(rho/sigma_n) above 1 is a granular gas, not a sheared layer (DEM.md asks
// for I < 1e-3; the tradeoff doubles I, so up to 1 is allowed).
constexpr double kMaxInertialNumber = 1.0;
constexpr double kMaxServoSpeedMS = 100.0;
constexpr double kMaxServoGain = 1e3;

void require(bool ok, const std::string& message) {
  if (!ok) throw InputError(message);
}

std::string range_error(io::TableReader& t, const std::string& key, double v, const std::string& allowed) {
  return fmt::format("{} = {:g} is out of range; allowed {}", t.where(key), v, allowed);
}

std::vector<double> numbers(io::TableReader& t, const std::string& key) {
  std::vector<double> out;
  const toml::node* n = t.node(key);
  if (n == nullptr) return out;
  const auto* arr = n->as_array();
  require(arr != nullptr, fmt::format("{} = {} should be an array of numbers", t.where(key), io::describe(*n)));
  for (const auto& x : *arr) {
    const auto v = x.value<double>();
    require(v.has_value(), fmt::format("{} has a non-number {}", t.where(key), io::describe(x)));
    require(std::isfinite(*v), fmt::format("{} has {}, not a finite number", t.where(key), io::describe(x)));
    out.push_back(*v);
  }
  return out;
}

Particles read_particles(io::TableReader t) {
  Particles p{};
  p.d50_m = t.positive("d50_mm", kMaxD50Mm) * kMm;
  const auto ratios = numbers(t, "d_over_d50");
  const auto fractions = numbers(t, "mass_fraction");
  if (ratios.empty()) {
    require(fractions.empty(), t.where("mass_fraction") + " needs d_over_d50 beside it");
    p.sizes = {{p.d50_m, 1.0}};
  } else {
    require(ratios.size() == fractions.size(),
            fmt::format("{}: d_over_d50 has {} entries and mass_fraction {}; they must match",
                        t.where(), ratios.size(), fractions.size()));
    const double sum = std::accumulate(fractions.begin(), fractions.end(), 0.0);
    require(std::abs(sum - 1.0) < 1e-6, fmt::format("{}: mass_fraction sums to {:g}; it must sum to 1",
                                                    t.where(), sum));
    for (std::size_t i = 0; i < ratios.size(); ++i) {
      require(ratios[i] > 0.0 && fractions[i] > 0.0,
              fmt::format("{}: size class {} (d_over_d50 = {:g}, mass_fraction = {:g}) must be > 0",
                          t.where(), i, ratios[i], fractions[i]));
      p.sizes.push_back({ratios[i] * p.d50_m, fractions[i]});
    }
  }
  p.density_kg_m3 = t.positive("density_kg_m3", kMaxDensityKgM3);
  p.youngs_modulus_Pa = t.positive("youngs_modulus_Pa", kMaxYoungsModulusPa);
  p.poisson = t.number_in("poisson", {0.0, 0.5, false, true});
  p.friction = t.number_in("friction", non_negative(kMaxFriction));
  p.rolling_friction = t.optional_number_in("rolling_friction", non_negative(kMaxFriction)).value_or(0.0);
  p.rolling_model = t.optional_text("rolling_model").value_or("cdt");
  require(p.rolling_model == "cdt" || p.rolling_model == "epsd2",
          fmt::format("{} = \"{}\"; allowed \"cdt\" or \"epsd2\"", t.where("rolling_model"), p.rolling_model));
  p.restitution = t.optional_number_in("restitution", closed(0.0, 1.0)).value_or(0.5);
  p.suction_Pa = t.optional_number_in("suction_kPa", non_negative(kMaxSuctionKPa)).value_or(0.0) * 1e3;
  p.surface_tension_N_m = t.optional_number_in("surface_tension_N_m", {0.0, 1.0, true, false}).value_or(0.0728);
  // the capillary tables (dem-scripts/yade/capillary) reach u* = s R / gamma = 400 (600 for the
  // radius ratios up to 1.25), for the largest grain radius of a pair
  const double u_max = p.suction_Pa * 0.5 * p.d_max() / p.surface_tension_N_m;
  require(u_max <= kMaxCapillaryNumber,
          fmt::format("{} = {:g} gives s R_max / gamma = {:.4g} for the largest grains; the capillary tables reach {:g} "
                      "(at most {:.3g} kPa here)", t.where("suction_kPa"), p.suction_Pa / 1e3, u_max, kMaxCapillaryNumber,
                      kMaxCapillaryNumber * p.surface_tension_N_m / (0.5 * p.d_max()) / 1e3));
  t.finish();
  return p;
}

// `extra` reads keys a table holds besides the profile (the plate's clamp) before it is finished.
RoughnessProfile read_profile(io::TableReader t, double d50, const std::function<void(io::TableReader&)>& extra = {}) {
  RoughnessProfile r;
  const std::string kind = t.text("profile");
  if (kind == "flat") {
    r.kind = ProfileKind::kFlat;
  } else if (kind == "sawtooth" || kind == "sinusoid") {
    r.kind = kind == "sawtooth" ? ProfileKind::kSawtooth : ProfileKind::kSinusoid;
    r.pitch_m = t.positive("pitch_d50", kMaxLengthD50) * d50;
    r.height_m = t.positive("height_d50", kMaxLengthD50) * d50;
  } else if (kind == "glued") {
    r.kind = ProfileKind::kGlued;
    r.height_m = t.positive("sphere_d50", kMaxLengthD50) * d50;
    r.pitch_m = t.positive("spacing_d50", kMaxLengthD50) * d50;
  } else {
    throw InputError(fmt::format("{} = \"{}\"; allowed \"flat\", \"sawtooth\", \"sinusoid\", \"glued\"",
                                 t.where("profile"), kind));
  }
  if (extra) extra(t);
  t.finish();
  return r;
}

// The particles a box holds at the estimated solid fraction (when [specimen] particles is not
// given), refused above the limit of an explicit count: a height of 1e9 d50 must not start an engine.
int derived_particle_count(io::TableReader& spec, const Scene& s) {
  const double n = s.solid_fraction_estimate * s.length_m * s.width_m * s.height_m /
                   s.particles.mean_particle_volume_m3();
  const double d50 = s.particles.d50_m;
  require(n >= 1.0 && n <= kMaxParticles,
          fmt::format("{}: length_d50 x width_d50 x height_d50 = {:g} x {:g} x {:g} at solid fraction {:g} "
                      "holds {:.4g} particles; allowed 1 to {:g} (set a smaller box or [specimen] particles)",
                      spec.where(), s.length_m / d50, s.width_m / d50, s.height_m / d50,
                      s.solid_fraction_estimate, n, kMaxParticles));
  return int(std::lround(n));
}

void check_geometry(Scene& s, const std::string& file) {
  const double dmax = s.particles.d_max();
  require(s.length_m >= kMinBoxLengthInDmax * dmax - 1e-12,
          fmt::format("{}: key 'specimen.length_d50' = {:g} gives a box of {:g} mm, shorter than {:g} d_max "
                      "= {:g} mm", file, s.length_m / s.particles.d50_m, s.length_m / kMm,
                      kMinBoxLengthInDmax, kMinBoxLengthInDmax * dmax / kMm));
  require(s.width_m >= kMinWidthInDmax * dmax - 1e-12,
          fmt::format("{}: key 'specimen.width_d50' = {:g} gives {:g} mm, narrower than {:g} d_max",
                      file, s.width_m / s.particles.d50_m, s.width_m / kMm, kMinWidthInDmax));
  require(s.plate.kind != ProfileKind::kGlued,
          fmt::format("{}: key 'plate.profile' = \"glued\": the servo plate is a mesh and cannot carry "
                      "glued spheres; use a sawtooth", file));
  for (const auto& [name, prof] : {std::pair{"wall", &s.wall}, std::pair{"plate", &s.plate}}) {
    if (prof->kind == ProfileKind::kFlat) continue;
    const std::string key = prof->kind == ProfileKind::kGlued ? "spacing_d50" : "pitch_d50";
    // glued spheres sit on a square grid: the spacing must divide the width too
    std::vector<std::pair<const char*, double>> sides = {{"length", s.length_m}};
    if (prof->kind == ProfileKind::kGlued) sides.push_back({"width", s.width_m});
    for (const auto& [side, size] : sides) {
      const double n = size / prof->pitch_m;
      require(std::abs(n - std::round(n)) < 1e-9 * n,
              fmt::format("{}: key '{}.{}' = {:g} does not divide the box {} {:g} d50 "
                          "(a periodic wall needs a whole number of periods; {:.4g} here)",
                          file, name, key, prof->pitch_m / s.particles.d50_m, side, size / s.particles.d50_m, n));
    }
  }
  if (s.height_m < kRecommendedHeightInD50 * s.particles.d50_m)
    s.warnings.push_back(fmt::format("{}: specimen height {:g} d50 is below {:g} d50; no shear band can "
                                     "form (DEM.md), fine for checking the boundary conditions",
                                     file, s.height_m / s.particles.d50_m, kRecommendedHeightInD50));
}

// [shear] ramp_transits: the wall's speed ramps from 0 over that many round trips 2 H / c_s of a
// shear wave (c_s: effective-medium estimate at sigma_n); 0 starts at full speed. Cycles start at
// full speed, so only 0 is accepted with them. A ramp longer than the test is allowed with a warning.
void read_ramp(io::TableReader& t, Scene& s) {
  const auto given = t.optional_number("ramp_transits");
  Shear& sh = s.shear;
  sh.ramp_transits = given.value_or(sh.cyclic() ? 0.0 : kDefaultRampTransits);
  require(std::isfinite(sh.ramp_transits) && sh.ramp_transits >= 0.0,
          range_error(t, "ramp_transits", sh.ramp_transits, "[0, inf) (0: the wall starts at full speed)"));
  require(!sh.cyclic() || sh.ramp_transits == 0.0,
          fmt::format("{} = {:g}: cyclic shear starts at full speed; allowed 0 with 'cycles'",
                      t.where("ramp_transits"), sh.ramp_transits));
  sh.shear_wave_speed_m_s =
      effective_medium_shear_wave_speed(s.particles, s.boundary.sigma_n_Pa, s.solid_fraction_estimate);
  sh.ramp_s = ramp_time_s(sh.ramp_transits, s.height_m, sh.shear_wave_speed_m_s);
  if (sh.ramp_s > 0.0 && sh.ramp_displacement_m() >= sh.displacement_m)  // allowed, but say so
    s.warnings.push_back(fmt::format("{} = {:g} ramps the wall over {:.4g} mm, more than displacement_mm = {:g}: "
                                     "the wall never reaches its speed (below {:.4g} it does)",
                                     t.where("ramp_transits"), sh.ramp_transits, sh.ramp_displacement_m() / kMm,
                                     sh.displacement_m / kMm,
                                     sh.ramp_transits * sh.displacement_m / sh.ramp_displacement_m()));
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

double RoughnessProfile::surface_at(double x) const {
  if (kind == ProfileKind::kFlat) return 0.0;
  const double u = x - pitch_m * std::floor(x / pitch_m);  // position within one period
  switch (kind) {
    case ProfileKind::kSawtooth:
      return height_m * (u < 0.5 * pitch_m ? u : pitch_m - u) / (0.5 * pitch_m);
    case ProfileKind::kSinusoid:
      return 0.5 * height_m * (1.0 - std::cos(2.0 * M_PI * u / pitch_m));
    case ProfileKind::kGlued: {  // spheres centred at pitch/2 (+- pitch for overlapping ones)
      const double r = 0.5 * height_m;
      double z = 0.0;
      for (double c : {-0.5 * pitch_m, 0.5 * pitch_m, 1.5 * pitch_m}) {
        const double dx = u - c;
        if (std::abs(dx) <= r) z = std::max(z, r + std::sqrt(r * r - dx * dx));
      }
      return z;
    }
    case ProfileKind::kFlat:
      break;
  }
  return 0.0;
}

double RoughnessProfile::normalized_roughness(double d50) const {
  if (kind == ProfileKind::kFlat) return 0.0;
  if (kind == ProfileKind::kGlued) {
    // R_max over a sliding gauge window of length d50 on the sampled profile (Uesugi & Kishida)
    constexpr int kSamples = 4000;
    const double dx = pitch_m / kSamples;
    const int window = std::max(1, int(std::lround(d50 / dx)));
    double r_max = 0.0;
    for (int i = 0; i < kSamples; ++i) {
      double lo = INFINITY, hi = -INFINITY;
      for (int j = 0; j <= window; ++j) {
        const double z = surface_at((i + j) * dx);
        lo = std::min(lo, z), hi = std::max(hi, z);
      }
      r_max = std::max(r_max, hi - lo);
    }
    return r_max / d50;
  }
  const double half = 0.5 * pitch_m;  // a rise from valley to peak spans half a pitch
  if (d50 >= half) return height_m / d50;
  if (kind == ProfileKind::kSawtooth) return height_m * (d50 / half) / d50;
  return height_m * std::sin(M_PI * d50 / pitch_m) / d50;  // sinusoid: steepest window
}

double RoughnessProfile::mean_height_m() const {
  if (kind != ProfileKind::kGlued) return 0.5 * height_m;
  constexpr int kSamples = 2000;
  double sum = 0.0;
  for (int i = 0; i < kSamples; ++i) sum += surface_at((i + 0.5) * pitch_m / kSamples);
  return sum / kSamples;
}

std::string RoughnessProfile::describe() const {
  if (kind == ProfileKind::kFlat) return "flat";
  if (kind == ProfileKind::kGlued)
    return fmt::format("glued spheres of {:g} mm at {:g} mm spacing", height_m / kMm, pitch_m / kMm);
  return fmt::format("{} pitch {:g} mm, R_max {:g} mm", to_string(kind), pitch_m / kMm, height_m / kMm);
}

double Shear::displacement_at(double t) const {
  if (!cyclic()) {
    if (t < ramp_s) return 0.5 * velocity_m_s * t * t / ramp_s;  // v t^2 / (2 T) while ramping
    return velocity_m_s * (t - 0.5 * ramp_s);
  }
  const double travelled = velocity_m_s * t;
  if (travelled >= cycles_travel_m()) return travelled - cycles_travel_m();  // the post-cyclic shear
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

double servo_loop_number(double youngs_modulus_Pa, double sigma_n_Pa) {
  constexpr double kTunedModulusPa = 1e8, kTunedStressPa = 50e3;
  return std::pow(youngs_modulus_Pa / kTunedModulusPa, 1.0 / 6.0) *
         std::pow(kTunedStressPa / sigma_n_Pa, 2.0 / 3.0);
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
  return std::pow(p.youngs_modulus_Pa / ((1.0 - p.poisson * p.poisson) * boundary.sigma_n_Pa), 2.0 / 3.0);
}

const char* to_string(ProfileKind k) {
  switch (k) {
    case ProfileKind::kFlat: return "flat";
    case ProfileKind::kSawtooth: return "sawtooth";
    case ProfileKind::kSinusoid: return "sinusoid";
    case ProfileKind::kGlued: return "glued";
  }
  return "?";
}

Scene parse_scene(const std::string& text, const std::string& source) {
  const auto root = io::parse_toml_text(text, source);
  io::TableReader top(root, source);
  Scene s;
  s.source = source;
  s.name = std::filesystem::path(source).stem().string();
  s.description = top.optional_text("description").value_or("");
  s.seed = top.optional_count("seed").value_or(1);

  s.particles = read_particles(top.required_table("particles"));
  const double d50 = s.particles.d50_m;

  auto spec = top.required_table("specimen");
  s.length_m = spec.positive("length_d50", kMaxLengthD50) * d50;
  s.width_m = spec.positive("width_d50", kMaxLengthD50) * d50;
  s.height_m = spec.positive("height_d50", kMaxLengthD50) * d50;
  s.solid_fraction_estimate = spec.optional_positive("solid_fraction_estimate", kMaxSolidFraction).value_or(0.58);
  const double consolidation_friction =
      spec.optional_number_in("consolidation_friction", non_negative(kMaxFriction)).value_or(0.1);
  s.particle_count = spec.optional_count("particles").value_or(derived_particle_count(spec, s));
  spec.finish();

  s.wall = read_profile(top.required_table("wall"), d50);
  s.plate = read_profile(top.required_table("plate"), d50, [&](io::TableReader& t) {
    s.plate_clamp_m = t.optional_number_in("clamp_d50", non_negative(kMaxLengthD50)).value_or(0.0) * d50;
    // the band needs room below the clamped grains (DEM.md: at ~7 d50 no band forms)
    require(s.plate_clamp_m == 0.0 || s.plate_clamp_m <= s.height_m - kMinFreeHeightInD50 * d50,
            fmt::format("{} = {:g} leaves {:g} d50 of the {:g} d50 specimen free to shear; allowed: at least {:g} d50",
                        t.where("clamp_d50"), s.plate_clamp_m / d50, (s.height_m - s.plate_clamp_m) / d50,
                        s.height_m / d50, kMinFreeHeightInD50));
  });
  check_geometry(s, source);

  auto bc = top.required_table("boundary");
  s.boundary.kind = driver::parse_boundary_kind(bc.text("type"), bc.where("type"));
  s.boundary.sigma_n_Pa = bc.positive("sigma_n_kPa", kMaxStressKPa) * 1e3;
  if (s.boundary.kind == driver::BoundaryKind::kCNS)
    s.boundary.K_Pa_per_m = bc.positive("K_kPa_per_mm", kMaxCnsStiffnessKPaPerMm) * 1e3 / kMm;
  bc.finish();

  auto sh = top.required_table("shear");
  if (sh.one_of({"displacement_mm", "amplitude_mm"}) == "displacement_mm") {
    require(!sh.has("post_cyclic_mm"), fmt::format("{} follows cycles; allowed only with amplitude_mm and cycles "
                                                   "(monotonic shear: displacement_mm alone)",
                                                   sh.where("post_cyclic_mm")));
    s.shear.displacement_m = sh.positive("displacement_mm", kMaxTravelMm) * kMm;
  } else {
    s.shear.amplitude_m = sh.positive("amplitude_mm", kMaxTravelMm) * kMm;
    s.shear.cycles = sh.count("cycles");
    s.shear.post_cyclic_m = sh.optional_number_in("post_cyclic_mm", non_negative(kMaxTravelMm)).value_or(0.0) * kMm;
  }
  const double rho = s.particles.density_kg_m3;
  const double sqrt_rho_over_sigma = std::sqrt(rho / s.boundary.sigma_n_Pa);
  if (sh.one_of({"velocity_mm_s", "inertial_number"}) == "velocity_mm_s") {
    s.shear.velocity_m_s = sh.positive("velocity_mm_s") * kMm;
  } else {
    // I = gamma_dot d50 sqrt(rho / sigma_n) with gamma_dot ~ v / H (DEM.md, conservative: the
    // whole specimen as the band).
    s.shear.velocity_m_s =
        sh.positive("inertial_number", kMaxInertialNumber) * s.height_m / (d50 * sqrt_rho_over_sigma);
  }
  s.shear.inertial_number = s.shear.velocity_m_s / s.height_m * d50 * sqrt_rho_over_sigma;
  require(s.shear.inertial_number <= kMaxInertialNumber * (1.0 + 1e-12),
          fmt::format("{} = {:g} shears at an inertial number of {:.3g}; allowed up to {:g} (a granular "
                      "gas beyond; DEM.md asks for I < 1e-3): below {:.4g} mm/s here",
                      sh.where("velocity_mm_s"), s.shear.velocity_m_s / kMm, s.shear.inertial_number,
                      kMaxInertialNumber, kMaxInertialNumber * s.shear.velocity_m_s / s.shear.inertial_number / kMm));
  read_ramp(sh, s);
  sh.finish();

  s.consolidation.friction = consolidation_friction;
  s.consolidation.sigma_tolerance = 0.02;
  s.consolidation.plate_tolerance_d50 = 1e-3;
  s.consolidation.kinetic_energy_J = 1e-6;
  s.consolidation.windows_required = 3;
  s.consolidation.max_windows = 60;
  s.consolidation.window_steps = 2000;
  if (auto c = top.table("consolidation")) {
    s.consolidation.sigma_tolerance = c->optional_positive("sigma_tolerance", 1.0).value_or(0.02);
    s.consolidation.plate_tolerance_d50 = c->optional_positive("plate_tolerance_d50", 1.0).value_or(1e-3);
    s.consolidation.kinetic_energy_J = c->optional_positive("kinetic_energy_J", 1e3).value_or(1e-6);
    s.consolidation.windows_required = c->optional_count("windows_required").value_or(3);
    s.consolidation.max_windows = c->optional_count("max_windows").value_or(60);
    s.consolidation.window_steps = c->optional_count("window_steps").value_or(2000);
    c->finish();
  }

  s.outputs = {0.01 * kMm, 4, 0.25, 0.5 * kMm};
  if (auto o = top.table("output")) {
    // A spacing beyond the travel would leave the time series with its first row only.
    const double travel_mm = s.shear.travel_m() / kMm;
    s.outputs.timeseries_every_m = o->optional_positive("timeseries_every_mm", travel_mm).value_or(0.01) * kMm;
    s.outputs.profile_windows = o->optional_count("profile_windows").value_or(4);
    s.outputs.profile_bin_d50 = o->optional_positive("profile_bin_d50", s.height_m / d50).value_or(0.25);
    s.outputs.vtk_every_m = o->optional_positive("vtk_every_mm", kMaxTravelMm).value_or(0.5) * kMm;
    o->finish();
  }
  if (auto cg = top.table("coarse_graining")) {
    s.coarse_graining.enabled = cg->optional_flag("enabled").value_or(true);
    // wider than the specimen's half height, the kernel would average the band away
    s.coarse_graining.width_d50 = cg->optional_positive("width_d50", 0.5 * s.height_m / d50).value_or(0.5);
    cg->finish();
  }

  const double loop_number = servo_loop_number(s.particles.youngs_modulus_Pa, s.boundary.sigma_n_Pa);
  const double kp = default_consolidation_servo_gain(loop_number);
  const double kp_shear = default_shear_servo_gain(loop_number);
  s.servo = {0.3, kp, kp_shear};
  if (auto sv = top.table("servo")) {
    s.servo.vel_max_m_s = sv->optional_positive("vel_max_m_s", kMaxServoSpeedMS).value_or(0.3);
    s.servo.kp = sv->optional_positive("kp", kMaxServoGain).value_or(kp);
    s.servo.kp_shear = sv->optional_positive("kp_shear", kMaxServoGain).value_or(kp_shear);
    sv->finish();
  }
  if (auto nu = top.table("numerics")) {
    s.dt_fraction = nu->optional_positive("dt_fraction", kMaxDtFraction).value_or(kDefaultDtFraction);
    nu->finish();
  }
  if (auto rq = top.table("requirements")) s.requirements = read_requirements(*rq);
  top.finish();

  s.resolved = {
      {"particles", {{"d50_mm", d50 / kMm}, {"d_max_mm", s.particles.d_max() / kMm},
                     {"density_kg_m3", rho}, {"youngs_modulus_Pa", s.particles.youngs_modulus_Pa},
                     {"poisson", s.particles.poisson}, {"friction", s.particles.friction},
                     {"rolling_friction", s.particles.rolling_friction}, {"rolling_model", s.particles.rolling_model},
                     {"suction_kPa", s.particles.suction_Pa / 1e3}, {"surface_tension_N_m", s.particles.surface_tension_N_m},
                     {"restitution", s.particles.restitution}, {"count_requested", s.particle_count}}},
      {"specimen", {{"length_mm", s.length_m / kMm}, {"width_mm", s.width_m / kMm},
                    {"height_mm", s.height_m / kMm}, {"consolidation_friction", consolidation_friction}}},
      {"wall", {{"profile", s.wall.describe()}, {"R_n", s.wall.normalized_roughness(d50)}}},
      {"plate", {{"profile", s.plate.describe()}, {"R_n", s.plate.normalized_roughness(d50)},
                 {"clamp_mm", s.plate_clamp_m / kMm}}},
      {"boundary", {{"type", driver::to_string(s.boundary.kind)}, {"sigma_n_kPa", s.boundary.sigma_n_Pa / 1e3},
                    {"K_kPa_per_mm", s.boundary.K_Pa_per_m * kMm / 1e3}}},
      {"shear", {{"velocity_mm_s", s.shear.velocity_m_s / kMm}, {"displacement_mm", s.shear.displacement_m / kMm},
                 {"amplitude_mm", s.shear.amplitude_m / kMm}, {"cycles", s.shear.cycles},
                 {"post_cyclic_mm", s.shear.post_cyclic_m / kMm},
                 {"travel_mm", s.shear.travel_m() / kMm}, {"inertial_number", s.shear.inertial_number},
                 {"ramp_transits", s.shear.ramp_transits},
                 {"shear_wave_speed_estimate_m_s", s.shear.shear_wave_speed_m_s},
                 {"ramp_ms", s.shear.ramp_s * 1e3},
                 {"ramp_displacement_mm", s.shear.ramp_displacement_m() / kMm}}},
      {"stiffness_level", s.stiffness_level()},
      {"numerics", {{"dt_fraction", s.dt_fraction}}},
      {"seed", s.seed}};
  return s;
}

Scene load_scene(const std::string& path) {
  if (!std::filesystem::is_regular_file(path)) throw InputError(fmt::format("{}: no such file", path));
  return parse_scene(io::read_file(path), path);
}

}  // namespace iwb::dem
