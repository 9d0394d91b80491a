#pragma once
// The critical-state keys both clay tables declare ([hypoplastic_clay] of Masin's 2005 model and
// HCC, [clay_hypoplasticity] of Masin & Khalili's): written once, each table naming its own
// equations (issue 58). Upper bounds far beyond published clays (lambda* 0.05-0.3, kappa*
// 0.005-0.05, N 0.7-2) refuse only a units mistake or a typo.
#include <string>

#include "models/parameters.hpp"

namespace iwb::models::clay_keys {

inline constexpr double kMaxSlope = 2.0;
inline constexpr double kMaxN = 10.0;

inline ParameterSpec lambda_star(const std::string& equation) {
  return {"lambda_star",
          "-",
          {0.0, true},
          {kMaxSlope, false},
          "slope lambda* of the isotropic normal compression line, ln(1+e) against ln p",
          equation,
          ParameterRole::kMaterial,
          CalibrationBox{0.01, 0.5, false}};
}

inline ParameterSpec kappa_star(const std::string& equation) {
  return {"kappa_star",
          "-",
          {0.0, true},
          {kMaxSlope, false},
          "slope kappa* of the isotropic unloading line, ln(1+e) against ln p",
          equation,
          ParameterRole::kMaterial,
          CalibrationBox{0.001, 0.1, false}};
}

inline ParameterSpec phi_c_deg(const std::string& doc, const std::string& equation) {
  return {"phi_c_deg",
          "deg",
          {0.0, true},
          {90.0, true},
          doc,
          equation,
          ParameterRole::kCriticalFrictionAngle,
          CalibrationBox{10.0, 40.0, false}};
}

inline ParameterSpec N(const std::string& doc, const std::string& equation) {
  return {"N",
          "-",
          {0.0, true},
          {kMaxN, false},
          doc,
          equation,
          ParameterRole::kMaterial,
          CalibrationBox{0.5, 3.0, false}};
}

// Unloading must be stiffer than normal compression: kappa* < lambda*.
inline void require_slopes_ordered(const ParameterValues& v, const std::string& source) {
  require_below(v, "kappa_star", "lambda_star", source,
                "unloading is stiffer than normal compression");
}

}  // namespace iwb::models::clay_keys
