#pragma once
// The continuum fields of one snapshot on a grid (Goldhirsch 2010; Weinhart et al. 2012), SI,
// stresses compression positive (CONVENTIONS.md):
//   rho = sum m phi, solid fraction nu = sum V phi, momentum p = sum m v phi, V = p / rho;
//   velocity gradient dV_a/dx_b = (dp_a/dx_b - V_a drho/dx_b) / rho, from the kernel's exact
//   gradient (y-averaged: d/dy = 0);
//   contact stress sigma_ab = sum_contacts f_a (r_from - r_to)_b int_branch phi (f on `from`),
//   kinetic stress sum m v_a v_b phi - rho V_a V_b (the fluctuation about the field's V);
//   grain spin Omega_y = sum m omega_y phi / rho and the Cosserat rotation Omega_y - curl_y V / 2,
//   zero where grains roll with the continuum and large in a shear band.
// Where the solid fraction is below kMinSolidFraction (outside the specimen, in the kernel's tail)
// the velocity-derived fields are 0: a ratio of two vanishing sums is noise.
#include <string>
#include <vector>

#include "coarse_graining/grid.hpp"
#include "coarse_graining/particles.hpp"

namespace iwb::coarse_graining {

inline constexpr double kMinSolidFraction = 0.01;

struct Field {
  std::string name;  // with its unit, as in the CSV header and the .vti arrays
  std::vector<double> values;
};

struct FieldSet {
  std::vector<Field> fields;
  const std::vector<double>& operator[](
      const std::string& name) const;  // std::out_of_range if absent
};

FieldSet coarse_grain(const Snapshot& snapshot, const SamplingGrid& grid);

}  // namespace iwb::coarse_graining
