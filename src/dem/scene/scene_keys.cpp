#include "dem/scene/scene_keys.hpp"

#include "common/physical_limits.hpp"
#include "dem/scene/requirements.hpp"

namespace iwb::dem {

namespace {

using io::KeyDeclaration;
using io::KeyKind;
using io::Need;

// Physical ranges of scene values: each bound lies far outside what an interface-shear scene uses
// and inside what the engines can take, so a typo or a units mistake (kPa for Pa, a missing
// exponent) is refused with its key before an engine starts instead of failing inside it.
constexpr double kMaxD50Mm = 100.0;             // cobbles; a box of them is metres long
constexpr double kMaxDensityKgM3 = 1e5;         // 4x osmium: room for density scaling
constexpr double kMaxYoungsModulusPa = 1.2e12;  // diamond
constexpr double kMaxFriction = 10.0;           // a coefficient, not an angle in degrees
constexpr double kMaxSolidFraction = 0.75;      // densest sphere packing 0.7405
constexpr double kMaxLengthD50 = 1e5;           // the particle count bounds the box anyway
constexpr double kMaxRmsHeightD50 = 100.0;      // a surface far rougher than any wall in the seed
constexpr double kMaxSuctionKPa = 1e4;
constexpr double kMaxCnsStiffnessKPaPerMm = 1e7;  // stiffer than the grains: use CV
constexpr double kMaxTravelMm = 1e4;              // 10 m of wall travel
// I = gamma_dot d50 sqrt(rho/sigma_n) above 1 is a granular gas, not a sheared layer (DEM.md asks
// for I < 1e-3; the tradeoff doubles I, so up to 1 is allowed).
constexpr double kMaxInertialNumber = 1.0;
constexpr double kMaxServoSpeedMS = 100.0;
constexpr double kMaxServoGain = 1e3;
constexpr double kMaxDtFraction = 0.5;  // beyond this Hertz contacts lose energy balance

// A wall's or the plate's profile keys (the plate adds its clamp). The plate is a mesh moved by
// the servo and cannot carry glued spheres.
std::vector<KeyDeclaration> profile_keys(const std::string& table, const std::string& what,
                                         bool glued) {
  std::vector<KeyDeclaration> rows = {
      {.table = table,
       .key = "profile",
       .kind = KeyKind::kText,
       .choices = {"flat", "sawtooth", "sinusoid"},
       .need = Need::kRequired,
       .limit = glued ? "" : "not glued: the servo plate is a mesh and cannot carry glued spheres",
       .meaning = what},
      {.table = table,
       .key = "pitch_d50",
       .range = positive(kMaxLengthD50),
       .need = Need::kConditional,
       .when = "sawtooth, sinusoid",
       .limit = "divides length_d50",
       .meaning = "the profile's period along x (ridges along y)"},
      {.table = table,
       .key = "height_d50",
       .range = positive(kMaxLengthD50),
       .need = Need::kConditional,
       .when = "sawtooth, sinusoid",
       .meaning = "peak-to-valley height R_max; R_n = R_max(L = d50)/d50 goes to the manifest"},
  };
  const std::vector<KeyDeclaration> random = {
      {.table = table,
       .key = "rms_height_d50",
       .range = positive(kMaxRmsHeightD50),
       .need = Need::kConditional,
       .when = "random",
       .meaning = "the random surface's RMS height R_q"},
      {.table = table,
       .key = "correlation_length_d50",
       .range = positive(kMaxLengthD50),
       .need = Need::kConditional,
       .when = "random",
       .meaning = "roll-off length xi: the spectrum is flat above wavelength 2 pi xi and falls as "
                  "q^-2(1+H) below"},
      {.table = table,
       .key = "hurst",
       .range = {0.0, 1.0, true, false},
       .value = 0.8,
       .limit = "only with random",
       .meaning = "the random surface's Hurst exponent H"},
      {.table = table,
       .key = "grid_d50",
       .range = positive(1.0),
       .value = 0.25,
       .limit = "only with random",
       .meaning = "the random surface's grid spacing (its mesh's edges); no finer feature is made"},
      {.table = table,
       .key = "surface_seed",
       .kind = KeyKind::kWholeNumber,
       .value = 1.0,
       .limit = "only with random",
       .meaning = "the random surface's stream; the scene's seed does not change the wall"},
  };
  const std::vector<KeyDeclaration> measured = {
      {.table = table,
       .key = "file",
       .kind = KeyKind::kPath,
       .need = Need::kConditional,
       .when = "file",
       .meaning = "a measured surface: a line profile CSV (x_mm,z_mm) or a height map CSV "
                  "(note below)"},
      {.table = table,
       .key = "layout",
       .kind = KeyKind::kText,
       .choices = {"line", "map"},
       .value = std::string("line"),
       .limit = "only with file",
       .meaning = "line: x_mm,z_mm rows extruded along y; map: rows of heights in mm along x"},
      {.table = table,
       .key = "spacing_mm",
       .unit = "mm",
       .range = positive(kMaxLengthD50),
       .need = Need::kConditional,
       .when = "file, map",
       .meaning = "the height map's grid spacing in x and y"},
      {.table = table,
       .key = "offset_mm",
       .unit = "mm",
       .range = non_negative(),
       .value = 0.0,
       .limit = "only with file",
       .meaning = "where along x the box's window of the measurement starts"},
      {.table = table,
       .key = "height_scale",
       .range = positive(1e3),
       .value = 1.0,
       .limit = "only with file",
       .meaning = "the measured heights multiplied by this (0.5: half as rough)"},
      {.table = table,
       .key = "resample_d50",
       .range = non_negative(1.0),
       .value = 0.05,
       .limit = "only with file",
       .meaning = "finer samples averaged over cells of this size (no finer feature is felt; the "
                  "sensor's noise goes); "
                  "0: as measured"},
  };
  rows[0].choices.insert(rows[0].choices.end(), {"random", "file"});
  rows.insert(rows.end(), random.begin(), random.end());
  rows.insert(rows.end(), measured.begin(), measured.end());
  if (!glued) return rows;
  rows[0].choices.insert(rows[0].choices.end() - 2, "glued");
  const std::vector<KeyDeclaration> spheres = {
      {.table = table,
       .key = "sphere_d50",
       .range = positive(kMaxLengthD50),
       .need = Need::kConditional,
       .when = "glued",
       .meaning = "diameter of the glued spheres"},
      {.table = table,
       .key = "spacing_d50",
       .range = positive(kMaxLengthD50),
       .need = Need::kConditional,
       .when = "glued",
       .limit = "divides length_d50 and width_d50",
       .meaning = "centre spacing of the glued spheres (touching spheres: R_n 0.5)"},
  };
  rows.insert(rows.end(), spheres.begin(), spheres.end());
  return rows;
}

std::vector<KeyDeclaration> requirement_keys() {
  std::vector<KeyDeclaration> rows;
  for (const auto* list : requirement_lists())
    for (const auto& q : *list)
      rows.push_back({.table = "requirements",
                      .key = q.key,
                      .kind = KeyKind::kTolerance,
                      .default_note = "none (iwb compare's own)",
                      .meaning = std::string("relative tolerance of the ") + q.label});
  return rows;
}

io::KeyDeclarations declare() {
  io::KeyDeclarations rows = {
      {.key = "description",
       .kind = KeyKind::kText,
       .value = std::string(),
       .meaning = "free text"},
      {.key = "seed",
       .kind = KeyKind::kWholeNumber,
       .value = 1.0,
       .meaning = "the seed of every random stream"},

      {.table = "particles",
       .key = "d50_mm",
       .unit = "mm",
       .range = positive(kMaxD50Mm),
       .need = Need::kRequired,
       .meaning = "median grain diameter"},
      {.table = "particles",
       .key = "d_over_d50",
       .kind = KeyKind::kNumberList,
       .default_note = "one size",
       .limit = "each > 0, as many as mass_fraction",
       .meaning = "a discrete size distribution: the diameters in d50"},
      {.table = "particles",
       .key = "mass_fraction",
       .kind = KeyKind::kNumberList,
       .default_note = "one size",
       .limit = "each > 0, summing to 1",
       .meaning = "the mass fraction of each diameter"},
      {.table = "particles",
       .key = "density_kg_m3",
       .unit = "kg/m^3",
       .range = positive(kMaxDensityKgM3),
       .need = Need::kRequired,
       .meaning = "grain density"},
      {.table = "particles",
       .key = "youngs_modulus_Pa",
       .unit = "Pa",
       .range = positive(kMaxYoungsModulusPa),
       .need = Need::kRequired,
       .meaning = "grain Young's modulus (Hertz-Mindlin)"},
      {.table = "particles",
       .key = "poisson",
       .range = {0.0, 0.5, false, true},
       .need = Need::kRequired,
       .meaning = "grain Poisson's ratio"},
      {.table = "particles",
       .key = "friction",
       .range = non_negative(kMaxFriction),
       .need = Need::kRequired,
       .meaning = "sliding friction during the test (grains and walls alike)"},
      {.table = "particles",
       .key = "rolling_friction",
       .range = non_negative(kMaxFriction),
       .value = 0.0,
       .meaning = "rolling resistance coefficient mu_r"},
      {.table = "particles",
       .key = "rolling_model",
       .kind = KeyKind::kText,
       .choices = {"cdt", "epsd2"},
       .value = std::string("cdt"),
       .meaning = "LIGGGHTS's rolling resistance (note below)"},
      {.table = "particles",
       .key = "restitution",
       .range = closed(0.0, 1.0),
       .value = 0.5,
       .meaning = "coefficient of restitution"},
      {.table = "particles",
       .key = "suction_kPa",
       .unit = "kPa",
       .range = non_negative(kMaxSuctionKPa),
       .value = 0.0,
       .limit = "s R_max / gamma at most 400",
       .meaning =
           "matric suction of pendular liquid bridges between grains; YADE only (note below)"},
      {.table = "particles",
       .key = "surface_tension_N_m",
       .unit = "N/m",
       .range = {0.0, 1.0, true, false},
       .value = 0.0728,
       .meaning = "the liquid's surface tension (water at 20 deg C)"},

      {.table = "specimen",
       .key = "length_d50",
       .range = positive(kMaxLengthD50),
       .need = Need::kRequired,
       .limit = "at least 10 d_max",
       .meaning = "periodic box in x (the shear direction)"},
      {.table = "specimen",
       .key = "width_d50",
       .range = positive(kMaxLengthD50),
       .need = Need::kRequired,
       .limit = "at least 3 d_max",
       .meaning = "periodic box in y"},
      {.table = "specimen",
       .key = "height_d50",
       .range = positive(kMaxLengthD50),
       .need = Need::kRequired,
       .meaning = "target specimen height; below 20 d50 a warning says no band can form"},
      {.table = "specimen",
       .key = "solid_fraction_estimate",
       .range = positive(kMaxSolidFraction),
       .value = 0.58,
       .meaning = "with the box, the particle count when `particles` is not given"},
      {.table = "specimen",
       .key = "particles",
       .kind = KeyKind::kWholeNumber,
       .default_note = "derived from the box (within the range)",
       .meaning = "particles requested; a run that inserts fewer fails"},
      {.table = "specimen",
       .key = "consolidation_friction",
       .range = non_negative(kMaxFriction),
       .value = 0.1,
       .meaning = "friction while consolidating (low: dense, high: loose)"},
      // Friction alone saturates: 1, 3 and 10 leave the truth's specimen at e ~0.81, its core
      // below the critical void ratio. Rolling resistance holds looser arches while the grains
      // come together, which collapse when the test's contacts take over unless those resist
      // rolling as much; the shear waits for the specimen to settle (data/grains/README.md).
      {.table = "specimen",
       .key = "consolidation_rolling_friction",
       .range = non_negative(kMaxFriction),
       .default_note = "the grains' rolling_friction",
       .limit = "LIGGGHTS only, unless equal to the grains' rolling_friction",
       .meaning = "rolling resistance while consolidating (a packing looser than the test's "
                  "contacts hold settles before the shear starts)"},
  };
  for (auto r : profile_keys("wall",
                             "the wall under test (bottom, sheared in +x); glued: a square layer "
                             "of fixed spheres on a flat base, moving with it; random: a periodic "
                             "self-affine Gaussian surface (areal); file: a measured one",
                             true))
    rows.push_back(r);
  for (auto r :
       profile_keys("plate", "the loading plate (top); make it rougher than the wall", false))
    rows.push_back(r);
  const io::KeyDeclarations rest = {
      {.table = "plate",
       .key = "clamp_d50",
       .range = non_negative(kMaxLengthD50),
       .value = 0.0,
       .limit = "at most height_d50 - 5",
       .meaning = "while shearing, grains this deep below the plate's teeth are held in x and y "
                  "(note below)"},

      {.table = "boundary",
       .key = "type",
       .kind = KeyKind::kText,
       .choices = {"CNL", "CNS", "CV"},
       .need = Need::kRequired,
       .meaning = "normal boundary condition during shear"},
      {.table = "boundary",
       .key = "sigma_n_kPa",
       .unit = "kPa",
       .range = positive(kMaxStressKPa),
       .need = Need::kRequired,
       .meaning = "consolidation stress; the CNL target during shear"},
      {.table = "boundary",
       .key = "K_kPa_per_mm",
       .unit = "kPa/mm",
       .range = positive(kMaxCnsStiffnessKPaPerMm),
       .need = Need::kConditional,
       .when = "CNS",
       .meaning = "d sigma_n = K d u_n (dilation raises the normal stress)"},

      {.table = "shear",
       .key = "velocity_mm_s",
       .unit = "mm/s",
       .range = positive(),
       .need = Need::kConditional,
       .when = "one of velocity_mm_s, inertial_number",
       .limit = "its inertial number at most 1",
       .meaning = "wall speed"},
      {.table = "shear",
       .key = "inertial_number",
       .range = positive(kMaxInertialNumber),
       .need = Need::kConditional,
       .when = "one of velocity_mm_s, inertial_number",
       .meaning =
           "target I = gamma_dot d50 sqrt(rho/sigma_n), gamma_dot = v/H (DEM.md asks I < 1e-3)"},
      {.table = "shear",
       .key = "displacement_mm",
       .unit = "mm",
       .range = positive(kMaxTravelMm),
       .need = Need::kConditional,
       .when = "one of displacement_mm, amplitude_mm",
       .meaning = "monotonic shear: the total wall displacement"},
      {.table = "shear",
       .key = "amplitude_mm",
       .unit = "mm",
       .range = positive(kMaxTravelMm),
       .need = Need::kConditional,
       .when = "one of displacement_mm, amplitude_mm",
       .meaning = "cyclic shear 0 -> +A -> -A -> 0, `cycles` times (summary.json's `cyclic`)"},
      {.table = "shear",
       .key = "cycles",
       .kind = KeyKind::kWholeNumber,
       .need = Need::kConditional,
       .when = "with amplitude_mm",
       .meaning = "the number of cycles"},
      {.table = "shear",
       .key = "post_cyclic_mm",
       .unit = "mm",
       .range = non_negative(kMaxTravelMm),
       .value = 0.0,
       .limit = "only with cycles",
       .meaning = "a monotonic shear in +x from u_x = 0 after the last cycle, at the same speed"},
      {.table = "shear",
       .key = "ramp_transits",
       .range = non_negative(),
       .default_note = "4 (cycles: 0)",
       .limit = "0 with cycles",
       .meaning = "the start-up ramp of the wall's speed (note below)"},

      {.table = "consolidation",
       .key = "sigma_tolerance",
       .range = positive(1.0),
       .value = 0.02,
       .meaning = "accepted relative error of the plate's stress"},
      {.table = "consolidation",
       .key = "plate_tolerance_d50",
       .range = positive(1.0),
       .value = 1e-3,
       .meaning = "accepted plate movement per window"},
      {.table = "consolidation",
       .key = "kinetic_energy_J",
       .unit = "J",
       .range = positive(1e3),
       .value = 1e-6,
       .meaning = "accepted kinetic energy of a window"},
      {.table = "consolidation",
       .key = "windows_required",
       .kind = KeyKind::kWholeNumber,
       .value = 3.0,
       .meaning = "consecutive accepted windows that end the consolidation"},
      {.table = "consolidation",
       .key = "max_windows",
       .kind = KeyKind::kWholeNumber,
       .value = 60.0,
       .meaning = "windows before the run fails \"servo did not converge\""},
      {.table = "consolidation",
       .key = "window_steps",
       .kind = KeyKind::kWholeNumber,
       .value = 2000.0,
       .meaning = "timesteps per window"},

      {.table = "output",
       .key = "timeseries_every_mm",
       .unit = "mm",
       .range = positive(),
       .value = 0.01,
       .limit = "at most the travel",
       .meaning = "time-series spacing in wall travel"},
      {.table = "output",
       .key = "profile_windows",
       .kind = KeyKind::kWholeNumber,
       .value = 4.0,
       .meaning = "windows of travel over which the profiles are averaged"},
      {.table = "output",
       .key = "profile_bin_d50",
       .range = positive(),
       .value = 0.25,
       .limit = "at most height_d50",
       .meaning = "profile bin height"},
      {.table = "output",
       .key = "vtk_every_mm",
       .unit = "mm",
       .range = positive(kMaxTravelMm),
       .value = 0.5,
       .meaning = "snapshot spacing in wall travel"},

      {.table = "coarse_graining",
       .key = "enabled",
       .kind = KeyKind::kFlag,
       .value = true,
       .meaning =
           "the continuum fields of every snapshot, computed when the run completes (note below)"},
      {.table = "coarse_graining",
       .key = "width_d50",
       .range = positive(),
       .value = 0.5,
       .limit = "at most height_d50 / 2",
       .meaning = "the Gaussian kernel's standard deviation"},

      {.table = "servo",
       .key = "vel_max_m_s",
       .unit = "m/s",
       .range = positive(kMaxServoSpeedMS),
       .value = 0.3,
       .meaning = "plate speed = vel_max kp (relative force error)"},
      {.table = "servo",
       .key = "kp",
       .range = positive(kMaxServoGain),
       .default_note = "min(1, 2/Λ)",
       .meaning = "the servo's gain while consolidating (Λ: note below)"},
      {.table = "servo",
       .key = "kp_shear",
       .range = positive(kMaxServoGain),
       .default_note = "2/max(1, Λ)",
       .meaning = "the servo's gain while shearing"},

      {.table = "numerics",
       .key = "dt_fraction",
       .range = positive(kMaxDtFraction),
       .value = 0.15,
       .meaning = "timestep over the smallest grain's Rayleigh time (both engines)"},
  };
  rows.insert(rows.end(), rest.begin(), rest.end());
  for (auto r : requirement_keys()) rows.push_back(r);
  return rows;
}

}  // namespace

const io::KeyDeclarations& scene_keys() {
  static const io::KeyDeclarations rows = declare();
  return rows;
}

}  // namespace iwb::dem
