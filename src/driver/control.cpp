#include "driver/control.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cctype>

#include "common/errors.hpp"

namespace iwb::driver {

NormalControlRow BoundaryCondition::row(double d_sigma_n) const {
  switch (kind) {
    case BoundaryKind::kCNL:
      return {1.0, 0.0, d_sigma_n};
    case BoundaryKind::kCNS:  // dilation (eps_n > 0) raises sigma_n
      return {1.0, -K_kPa, 0.0};
    case BoundaryKind::kCV:
      return {0.0, 1.0, 0.0};
  }
  return {};
}

BoundaryCondition with_stiffness_per_mm(BoundaryKind kind, double K_kPa_per_mm, double d_s_mm) {
  return {kind, K_kPa_per_mm * d_s_mm};
}

std::string BoundaryCondition::describe() const {
  if (kind == BoundaryKind::kCNS) return fmt::format("CNS, K = {:g} kPa per unit strain", K_kPa);
  return to_string(kind);
}

const char* to_string(BoundaryKind k) {
  switch (k) {
    case BoundaryKind::kCNL:
      return "CNL";
    case BoundaryKind::kCNS:
      return "CNS";
    case BoundaryKind::kCV:
      return "CV";
  }
  return "?";
}

std::vector<std::string> boundary_kind_names() {
  return {to_string(BoundaryKind::kCNL), to_string(BoundaryKind::kCNS),
          to_string(BoundaryKind::kCV)};
}

BoundaryKind parse_boundary_kind(const std::string& text, const std::string& where) {
  std::string up = text;
  std::transform(up.begin(), up.end(), up.begin(),
                 [](unsigned char ch) { return std::toupper(ch); });
  if (up == "CNL") return BoundaryKind::kCNL;
  if (up == "CNS") return BoundaryKind::kCNS;
  if (up == "CV") return BoundaryKind::kCV;
  throw InputError(
      fmt::format("{}: '{}' is not a boundary condition; use CNL, CNS or CV", where, text));
}

}  // namespace iwb::driver
