#pragma once
// A DEM interface-shear scene (../shared/spec/DEM.md): a granular layer between a rough wall under
// test (bottom, sheared in +x) and a loading plate (top, servo-controlled or held), periodic in x
// and y. Read from TOML (schema: data/scenes/README.md), SI inside, validated before any engine
// starts: every error names the file, the key and the value.
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "dem/scene/requirements.hpp"
#include "driver/control.hpp"  // BoundaryKind: the same CNL/CNS/CV in DEM and continuum
#include "walls/profile.hpp"

namespace iwb::dem {

struct SizeClass {
  double diameter_m;
  double mass_fraction;
};

struct Particles {
  double d50_m;
  std::vector<SizeClass> sizes;  // mass fractions sum to 1
  double density_kg_m3;
  double youngs_modulus_Pa;
  double poisson;
  double friction;          // sliding friction during the test
  double rolling_friction;  // rolling resistance coefficient mu_r
  // LIGGGHTS's rolling resistance: "cdt" (a constant torque mu_r R* F_n against any relative
  // rolling, rigid-plastic) or "epsd2" (Iwashita & Oda's elastic-plastic spring, k_r = k_t R*^2,
  // capped at the same torque). YADE's law is elastic-plastic either way (dem-scripts/README.md).
  std::string rolling_model = "cdt";
  double restitution;
  // Liquid bridges (issue 19; YADE only, Law2_ScGeom_CapillaryPhys_Capillarity): the matric
  // suction every pendular bridge holds (Pa; 0: dry) and the liquid's surface tension (N/m).
  double suction_Pa = 0.0;
  double surface_tension_N_m = 0.0728;  // water at 20 deg C

  bool wet() const { return suction_Pa > 0.0; }

  double d_max() const;
  double d_min() const;
  double mean_particle_volume_m3() const;  // number-weighted, from the mass fractions
};

// The walls' surfaces live in src/walls/ (line profiles, glued spheres, areal height maps).
using walls::ProfileKind;
using walls::RoughnessProfile;
using walls::to_string;

struct Boundary {
  driver::BoundaryKind kind = driver::BoundaryKind::kCNL;
  double sigma_n_Pa = 0.0;  // CNL target; CNS and CV: sigma_n0 of the consolidation
  double K_Pa_per_m = 0.0;  // CNS: d sigma_n = K d u_n
};

struct Shear {
  double velocity_m_s = 0.0;     // wall velocity (given, or from the inertial number)
  double inertial_number = 0.0;  // target I = gamma_dot d50 sqrt(rho/sigma_n), gamma_dot ~ v/H
  double displacement_m = 0.0;   // monotonic: total displacement
  double amplitude_m = 0.0;      // cyclic: 0 -> +A -> -A -> 0, `cycles` times
  int cycles = 0;
  // Cyclic: a monotonic shear in +x at the same speed after the last cycle (the post-cyclic
  // strength and dilation of issue 34); 0: none.
  double post_cyclic_m = 0.0;

  // Monotonic shear starts with a linear ramp of the wall's speed from 0 to v over ramp_s
  // (src/dem/scene/shear_start.hpp says why); 0 is an instant start, and cycles always start
  // instantly.
  double ramp_transits = 0.0;         // ramp_s in round trips 2 H / c_s of a shear wave
  double shear_wave_speed_m_s = 0.0;  // effective-medium estimate c_s at sigma_n
  double ramp_s = 0.0;

  bool cyclic() const { return cycles > 0; }
  double cycles_travel_m() const { return 4.0 * amplitude_m * cycles; }  // 0 when monotonic
  double travel_m() const { return cyclic() ? cycles_travel_m() + post_cyclic_m : displacement_m; }
  double ramp_displacement_m() const { return 0.5 * velocity_m_s * ramp_s; }
  // The wall's displacement t seconds after shear starts (a triangle wave when cyclic, then the
  // post-cyclic shear from 0).
  double displacement_at(double t) const;
  // The wall's speed t seconds after shear starts (v after the ramp; cycles: |v|).
  double speed_at(double t) const;
  // Time after which the wall has travelled travel_m().
  double duration_s() const;
};

struct Consolidation {
  double friction;             // particle friction while consolidating (low: dense)
  double rolling_friction;     // rolling resistance while consolidating (may collapse at test)
  double sigma_tolerance;      // relative
  double plate_tolerance_d50;  // plate movement per window, in d50
  double kinetic_energy_J;     // largest kinetic energy of an accepted window
  int windows_required;
  int max_windows;
  int window_steps;
};

struct Outputs {
  double timeseries_every_m;
  int profile_windows;
  double profile_bin_d50;
  double vtk_every_m;
};

// The continuum fields coarse-grained from every snapshot after the run (src/coarse_graining):
// off for campaigns that need only the wall's forces.
struct CoarseGraining {
  bool enabled = true;
  double width_d50 = 0.5;  // the Gaussian's standard deviation (Weinhart et al. 2012: ~ d/2)
};

// The plate servo: plate speed = vel_max * kp * e, e the relative force error (measured on
// LIGGGHTS 3.8.0: kp 0.01 at vel_max 0.1 moved a free plate at 1e-3 m/s).
struct Servo {
  double vel_max_m_s;
  double kp;        // while consolidating
  double kp_shear;  // while shearing
};

// The servo's loop gain per step, relative to the scenes its gains were tuned on (E = 1e8 Pa,
// sigma_n = 50 kPa: kp_shear 2 holds, 3 oscillates). The servo moves the plate by v dt a step with
// v = vel_max kp (F - F_target) / F_target, and the contacts under the plate answer that velocity
// within the same step through their damping: the loop oscillates with a period of two steps once
// kp vel_max (C_z + K_z dt / 2) exceeds about F_target, C_z and K_z the plate's vertical damping
// and stiffness summed over its contacts, normal and tangential (so a test friction, which brings
// the tangential terms in, can tip a loop that consolidated quietly). Measured on LIGGGHTS 3.8.0
// soil cells of the truth's grains (kp scanned for the threshold; the sum above predicts it within
// 8 %): the critical kp falls with stress as sigma^(-0.74..-0.78), does not change with the
// specimen's height (6, 12, 20 d50) and is 1.43 times lower under the soil cell's plates (1 d50
// ridges, 1.42 contacts per d50^2) than under the interface scenes' (0.98 per d50^2):
//   loop number = (E / 1e8 Pa)^(1/6) (50 kPa / sigma_n)^(3/4) plate_factor,
// plate_factor 1 for the interface scenes' plates (the E exponent is the Hertz estimate, untested).
double servo_loop_number(double youngs_modulus_Pa, double sigma_n_Pa, double plate_factor = 1.0);

// The shear-stage gain when the scene gives none: 2 divided by the loop number where that exceeds
// 1, so stiffer grains or a lower stress do not push the loop past its tuned gain. Measured (smoke
// scene, E 4.2e9, loop number 1.86): kp 2 makes the plate's force oscillate with an SD of 19.7 kPa
// about 50, the default 1.07 holds it within 0.3 kPa.
double default_shear_servo_gain(double loop_number);

// The consolidation gain when the scene gives none: 1, or 2 divided by the loop number where that
// is smaller (the same ceiling of 2 on kp times the loop number as the shear stage's). Measured
// (dense 1084-grain soil cell, E 6.9e8, 10 kPa, loop number 4.0): kp 1 makes the plate's force
// jump between -1 and +8.5 kPa window to window about its 10 kPa target; kp 0.5 holds it within
// 1 %. Every consolidation accepted before this rule had a loop number of at most 2.9 (kp 1 then
// holds), and below 2 the rule leaves kp at 1.
double default_consolidation_servo_gain(double loop_number);

struct Scene {
  std::string source;  // file it came from
  std::string name;
  std::string description;
  int seed = 1;
  Particles particles;
  double length_m, width_m, height_m;  // box in x, y; target specimen height
  int particle_count = 0;              // requested
  double solid_fraction_estimate;      // used to derive particle_count when not given
  RoughnessProfile wall, plate;
  // [plate] clamp_d50: while shearing, the grains whose centres lie within this depth below the
  // plate's teeth are held in x and y and do not rotate; they follow the plate normal to it, as the
  // upper frame of a direct interface shear test holds its soil. 0: none. With epsd2 rolling
  // resistance a band could form at the plate as well as at the wall (data/convergence/README.md).
  double plate_clamp_m = 0.0;
  Boundary boundary;
  Shear shear;
  Consolidation consolidation;
  Outputs outputs;
  CoarseGraining coarse_graining;
  Servo servo;
  double dt_fraction =
      0.15;  // [numerics]: timestep as a fraction of the smallest grain's Rayleigh time
  Requirements requirements;  // [requirements]: empty when the scene states none
  nlohmann::json resolved;    // every value after defaults and conversions, for the manifest
  std::vector<std::string> warnings;

  double area_m2() const { return length_m * width_m; }
  // Stiffness level kappa = (E / ((1 - nu^2) sigma_n))^(2/3) (DEM.md manifest field).
  double stiffness_level() const;
};

Scene load_scene(const std::string& path);

// The shipped scenes embedded in the binary ("default.toml", "smoke.toml"; generated at build).
const std::map<std::string, std::string>& embedded_scenes();
Scene parse_scene(const std::string& text, const std::string& source);

// The sha256 that decides whether a complete run is this scene's (resume, sweeps, crosscheck): of
// the text, followed by the sha256 of every wall file it names, so that a changed measurement is
// another scene. sha256(text) for a scene that names no file.
std::string scene_sha256(const Scene& scene, const std::string& text);

}  // namespace iwb::dem
