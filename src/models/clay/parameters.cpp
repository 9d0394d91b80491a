#include "models/clay/parameters.hpp"

#include <fmt/core.h>

#include <cmath>

#include "common/errors.hpp"

namespace iwb::models {

// Upper bounds far beyond published clays (lambda* 0.05-0.3, kappa* 0.005-0.05, N 0.7-2):
// only a units mistake or a typo is refused.
constexpr double kMaxSlope = 2.0;
constexpr double kMaxN = 10.0;

const ParameterTable& ClayParameters::table() {
  static const ParameterTable t{
      "hypoplastic_clay",
      {
          {"lambda_star",
           "-",
           {0.0, true},
           {kMaxSlope, false},
           "slope lambda* of the isotropic normal compression line, ln(1+e) against ln p",
           "eq. 6.7",
           ParameterRole::kMaterial,
           CalibrationBox{0.01, 0.5, false}},
          {"kappa_star",
           "-",
           {0.0, true},
           {kMaxSlope, false},
           "slope kappa* of the isotropic unloading line, ln(1+e) against ln p",
           "eq. 6.9",
           ParameterRole::kMaterial,
           CalibrationBox{0.001, 0.1, false}},
          {"nu",
           "-",
           {0.0, true},
           {0.5, true},
           "ratio nu of shear to bulk stiffness (eq. 6.6)",
           "eq. 6.6",
           ParameterRole::kMaterial,
           CalibrationBox{0.05, 0.45, false}},
          {"phi_c_deg",
           "deg",
           {0.0, true},
           {90.0, true},
           "critical state friction angle phi_c (HCC: M = 6 sin phi_c / (3 - sin phi_c))",
           "eq. 6.10",
           ParameterRole::kCriticalFrictionAngle,
           CalibrationBox{10.0, 40.0, false}},
          {"N",
           "-",
           {0.0, true},
           {kMaxN, false},
           "ln(1+e) on the normal compression line at p = 1 kPa",
           "eq. 6.7, ERRATA 15",
           ParameterRole::kMaterial,
           CalibrationBox{0.5, 3.0, false}},
      }};
  return t;
}

ClayParameters ClayParameters::from(const ParameterValues& v, const std::string& source) {
  validate(table(), v, source);
  require_below(v, "kappa_star", "lambda_star", source,
                "unloading is stiffer than normal compression");
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
