#pragma once
// The quantities of a displacement-controlled cyclic interface test, cycle by cycle (issue 34,
// item 2), from the path's rows alone: a DEM run's time series and a model's replay of it along
// the same u_x are measured by one definition. The wall follows 0 -> +A -> -A -> 0 `cycles` times,
// then optionally a monotonic (post-cyclic) shear in +x from 0 (src/dem/scene/scene.hpp, Shear).
//
// Where a row is: the travelled distance s (the sum of |du_x|, v t for a wall at constant speed)
// is given with the rows, not summed over them: a reversal falls between two output rows, and the
// net du_x between them may have either sign (0.99873 -> 1 -> 0.9999), so neither summing |du_x|
// nor counting sign changes places the rows after a reversal right. Values at a given s are
// interpolated linearly between the rows on either side.
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

namespace iwb::cycles {

// Rows in time order, in the contract's units (mm, kPa). e_band: the band's void ratio per row,
// or empty where it is not known (a model's replay).
struct Path {
  std::vector<double> travel_mm;  // non-decreasing
  std::vector<double> u_x_mm, u_n_mm, sigma_n_kPa, tau_kPa;
  std::vector<double> e_band;
};

struct Program {
  double amplitude_mm = 0.0;
  int cycles = 0;
  double post_cyclic_mm = 0.0;
  double cycles_travel_mm() const { return 4.0 * amplitude_mm * cycles; }
};

// The response just after a reversal of the wall at u_x = +A or -A.
struct Reversal {
  double u_x_mm = 0.0;
  double tau_kPa = 0.0;  // at the reversal
  // Secant shear stiffness over f A after the reversal, f = 0.1 and 0.5: the change of tau in the
  // wall's new direction over f A (positive when tau follows the wall): how stiffly the interface
  // answers a reversal (intergranular strain's claim, seed 5.7.5).
  double secant_10_kPa_per_mm = 0.0, secant_50_kPa_per_mm = 0.0;
  std::optional<double> e_band;  // the band's void ratio at the reversal
};

struct Cycle {
  int number = 0;
  // the largest tau/sigma_n towards +A and the largest -tau/sigma_n towards -A
  double peak_friction_positive = 0.0, peak_friction_negative = 0.0;
  // the mean of |tau|/sigma_n over the cycle's rows: the cycle's own level of friction, to which a
  // cyclic run's end state is compared (issue 59: not a monotonic residual)
  double mean_friction = 0.0;
  double sigma_n_end_kPa = 0.0;
  double sigma_n_ratio = 0.0;     // sigma_n at the cycle's end over sigma_n0 (CNS, CV: degradation)
  double u_n_end_mm = 0.0;        // accumulated u_n (dilation positive)
  double u_n_increment_mm = 0.0;  // over this cycle (ratcheting)
  // the loop's area, the integral of tau du_x over the cycle: the work the wall does on the
  // soil per unit area (kPa mm = J/m^2)
  double dissipated_energy_J_m2 = 0.0;
  std::optional<double> e_band_end;  // the band's void ratio at the cycle's end (u_x = 0)
  Reversal at_plus, at_minus;
};

struct PostCyclic {
  double peak_friction = 0.0;  // max tau/sigma_n after the cycles
  double u_x_at_peak_mm = 0.0;
  double final_friction = 0.0;  // mean over the stage's last fifth
  double u_n_change_mm = 0.0;   // u_n at the end minus at the cycles' end
};

struct CyclicQuantities {
  double sigma_n0_kPa = 0.0;  // at the first row
  std::vector<Cycle> cycles;  // the complete cycles the rows reach
  std::optional<PostCyclic> post_cyclic;
};

// The travel of a wall moving at a constant speed (a cyclic program has no ramp) at each time t,
// counted from the first: v (t - t_0).
std::vector<double> travel_at_speed(const std::vector<double>& t_s, double speed_mm_s);

// InputError when the rows are fewer than 2, the series differ in length, the travel decreases or
// the program is not cyclic. A cycle counts when the rows reach its end within 1.5 row spacings
// (the last row of a run lands on its end only up to the output's spacing); those they do not
// reach are left out.
CyclicQuantities cyclic_quantities(const Path& path, const Program& program);

nlohmann::json to_json(const CyclicQuantities& q);

}  // namespace iwb::cycles
