#include "models/clay/parameters.hpp"

#include <fmt/core.h>

#include <cmath>

#include "common/errors.hpp"
#include "models/clay/critical_state_keys.hpp"

namespace iwb::models {

const ParameterTable& ClayParameters::table() {
  static const ParameterTable t{
      "hypoplastic_clay",
      {
          clay_keys::lambda_star("eq. 6.7"),
          clay_keys::kappa_star("eq. 6.9"),
          {"nu",
           "-",
           {0.0, true},
           {0.5, true},
           "ratio nu of shear to bulk stiffness (eq. 6.6)",
           "eq. 6.6",
           ParameterRole::kMaterial,
           CalibrationBox{0.05, 0.45, false}},
          clay_keys::phi_c_deg(
              "critical state friction angle phi_c (HCC: M = 6 sin phi_c / (3 - sin phi_c))",
              "eq. 6.10"),
          clay_keys::N("ln(1+e) on the normal compression line at p = 1 kPa", "eq. 6.7, ERRATA 15"),
      }};
  return t;
}

ClayParameters ClayParameters::from(const ParameterValues& v, const std::string& source) {
  validate(table(), v, source);
  clay_keys::require_slopes_ordered(v, source);
  return {v.at("lambda_star"), v.at("kappa_star"), v.at("nu"), v.at("phi_c_deg") * M_PI / 180.0,
          v.at("N")};
}

double poisson_ratio_on_wall(const ClayParameters& p, const Roughness& r) {
  if (r.scheme != RoughnessScheme::kStutzMasin) return p.nu;
  const double lk = p.lambda_star + p.kappa_star;
  const double r_r =
      r.kappa_r * 4.0 / 3.0 * p.kappa_star / lk * (1.0 + p.nu) / (1.0 - 2.0 * p.nu);     // 6.24
  return (3.0 * r_r * lk - 4.0 * p.kappa_star) / (6.0 * r_r * lk + 4.0 * p.kappa_star);  // 6.25
}

}  // namespace iwb::models
