#pragma once
// The start of monotonic shear (issue 14). A wall that starts at full speed v in one timestep sends
// a shear wave through the specimen; until it has come back from the plate (t = 2 H / c_s) the wall
// carries only the wave's stress rho c_s v, and each further round trip adds another step: a flat
// start and a staircase in tau(u_x) that belong to the start-up, not to the interface. The wall's
// speed therefore ramps linearly from 0 to v over a time T of a few round trips
// (dem-scripts/README.md has the measurements).
// It reads no scene: scene.cpp derives the ramp from it (dem/scene/ramp_numerics.hpp records it).

namespace iwb::dem {

// Coordination number of the effective-medium estimate: a dense random packing (the consolidated
// smoke specimen has 5.7).
inline constexpr double kEffectiveMediumCoordination = 6.0;

// Default ramp in round trips 2 H / c_s. After a linear ramp of length T, a mode of period P rings
// with the instant start's amplitude times |sin(pi T / P)| / (pi T / P) <= P / (pi T); the
// specimen's fundamental period (held at the plate, moved at the wall) is P = 2 H / c_s. Four
// round trips leave at most 8 % of the start-up step while c_s is only an estimate (~20 %); the
// ramp covers v T / 2 = 4 H v / c_s of travel, twice the flat start it removes.
inline constexpr double kDefaultRampTransits = 4.0;

// Shear-wave speed of a packing of Hertz-Mindlin spheres under a pressure p (Pa), by
// effective-medium theory with Mindlin's no-slip contacts (Mavko, Mukerji & Dvorkin, The Rock
// Physics Handbook, 2009, sec. 5.4, "Hertz-Mindlin"):
//   G_eff = (5 - 4 nu) / (5 (2 - nu)) [3 Z^2 (1 - phi)^2 G^2 p / (2 pi^2 (1 - nu)^2)]^(1/3)
//   c_s = sqrt(G_eff / ((1 - phi) rho))
// with G = E / (2 (1 + nu)) of the grains, phi the porosity, Z the coordination number;
// independent of the grain size.
// The grains' Young's modulus (Pa), Poisson's ratio and density (kg/m^3).
double effective_medium_shear_wave_speed(double youngs_modulus_Pa, double poisson,
                                         double density_kg_m3, double pressure_Pa,
                                         double solid_fraction,
                                         double coordination = kEffectiveMediumCoordination);

// The ramp time T = transits x 2 H / c_s (s).
double ramp_time_s(double transits, double height_m, double shear_wave_speed_m_s);

}  // namespace iwb::dem
