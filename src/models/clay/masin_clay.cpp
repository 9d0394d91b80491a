#include "models/clay/masin_clay.hpp"

#include <fmt/core.h>

#include "common/errors.hpp"

namespace iwb::models {

// As the other clay tables: bounds far beyond published clays refuse only units mistakes.
constexpr double kMaxSlope = 2.0;
constexpr double kMaxN = 10.0;
constexpr double kMaxR = 10.0;  // Masin (2005): r ~ 0.1-0.7

const ParameterTable& MasinClayParameters::table() {
  static const ParameterTable t{
      "clay_hypoplasticity",
      {
          {"phi_c_deg",
           "deg",
           {0.0, true},
           {90.0, true},
           "critical state friction angle phi_c",
           "eqs. 6.35, 6.38",
           ParameterRole::kCriticalFrictionAngle,
           CalibrationBox{10.0, 40.0, false}},
          {"lambda_star",
           "-",
           {0.0, true},
           {kMaxSlope, false},
           "slope lambda* of the isotropic normal compression line, ln(1+e) against ln p",
           "eq. 6.43",
           ParameterRole::kMaterial,
           CalibrationBox{0.01, 0.5, false}},
          {"kappa_star",
           "-",
           {0.0, true},
           {kMaxSlope, false},
           "slope kappa* of the isotropic unloading line, ln(1+e) against ln p",
           "eq. 6.36",
           ParameterRole::kMaterial,
           CalibrationBox{0.001, 0.1, false}},
          {"N",
           "-",
           {0.0, true},
           {kMaxN, false},
           "ln(1+e) on the isotropic normal compression line at p = 1 kPa",
           "eq. 6.43",
           ParameterRole::kMaterial,
           CalibrationBox{0.5, 3.0, false}},
          {"r",
           "-",
           {0.0, true},
           {kMaxR, false},
           "ratio of bulk to shear stiffness at the isotropic state",
           "eq. 6.34",
           ParameterRole::kMaterial,
           CalibrationBox{0.05, 1.0, false}},
      }};
  return t;
}

MasinClayParameters MasinClayParameters::from(const ParameterValues& v, const std::string& source) {
  validate(table(), v, source);
  require_below(v, "kappa_star", "lambda_star", source,
                "unloading is stiffer than normal compression");
  return {v.at("phi_c_deg") * M_PI / 180.0, v.at("lambda_star"), v.at("kappa_star"), v.at("N"),
          v.at("r")};
}

MasinClayConstants make_masin_clay_constants(const MasinClayParameters& p, const Roughness& r) {
  MasinClayConstants c{p, 0.0, 0.0, 0.0};
  c.p.phi_c = p.phi_c * r.kappa_r;  // 6.22, 6.26: the critical state
  if (r.scheme == RoughnessScheme::kStutzMasin)
    c.p.r = p.r * r.kappa_r;  // 6.24: the shear stiffness
  const double s = std::sin(c.p.phi_c);
  c.a = std::sqrt(3.0) * (3.0 - s) / (2.0 * std::sqrt(2.0) * s);  // 6.35, ERRATA 14
  c.k = std::sqrt(3.0) * c.a / (3.0 + c.a * c.a);                 // 6.38, ERRATA 14
  c.sin2_phi = s * s;
  return c;
}

std::string MasinClayLaw::domain_violation(const StressInvariants& s, double, const Constants&) {
  if (!(s.F_m < 1.0))
    return fmt::format(
        "stress outside Matsuoka-Nakai's cone (F_m = {:.6g}): tension in a direction", s.F_m);
  return {};
}

std::vector<NamedValue> MasinClayLaw::diagnostics(const StressInvariants& s, double e,
                                                  const Constants& c) {
  return {{"mean_stress_kPa", s.mean_stress},
          {"p_e_kPa", std::exp((c.p.N - std::log(1.0 + e)) / c.p.lambda_star)},
          {"F_m", s.F_m}};
}

}  // namespace iwb::models
