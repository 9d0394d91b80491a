#pragma once
// The normal direction of an interface test as one linear row per increment (CONVENTIONS.md,
// STYLE.md after MTest's constraints):   a d(sigma_n) + b d(eps_n) = c
// with sigma_n compression positive (kPa) and eps_n opening positive. CNL, CNS, CV and a
// prescribed normal strain are four instances; shear is always strain-controlled.
#include <string>
#include <vector>

namespace iwb::driver {

struct NormalControlRow {
  double a = 1.0;
  double b = 0.0;
  double c = 0.0;
};

enum class BoundaryKind { kCNL, kCNS, kCV };

struct BoundaryCondition {
  BoundaryKind kind = BoundaryKind::kCNL;
  double K_kPa = 0.0;  // CNS stiffness per unit normal strain: d sigma_n = K d eps_n

  // The row for a shear increment; `d_sigma_n` is the prescribed change of sigma_n (CNL stages).
  NormalControlRow row(double d_sigma_n = 0.0) const;
  std::string describe() const;
};

// A boundary whose CNS stiffness is given per mm of normal displacement, as the DEM and the test
// files state it: K per unit strain = K_per_mm d_s (CONVENTIONS.md), the one place that says so.
BoundaryCondition with_stiffness_per_mm(BoundaryKind kind, double K_kPa_per_mm, double d_s_mm);

const char* to_string(BoundaryKind k);
// "CNL", "CNS", "CV" (any case); InputError naming `where` otherwise.
BoundaryKind parse_boundary_kind(const std::string& text, const std::string& where);
// The names parse_boundary_kind takes (in any case): CNL, CNS, CV.
std::vector<std::string> boundary_kind_names();

}  // namespace iwb::driver
