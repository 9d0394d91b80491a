#include "models/hypoplastic/intergranular_strain.hpp"

#include <fmt/core.h>

#include "common/errors.hpp"

namespace iwb::models {

// Upper bounds far beyond published sets (m_R 2-8, m_T 1-5, beta_r 0.05-0.5, chi 1-10): only a
// units mistake or a typo is refused. The calibration boxes (issue 34) span those sets with a
// margin: R from 1e-5 to 1e-3 (published 1e-5-2e-4; a DEM packing's elastic range may differ),
// R and beta_r fitted logarithmically (decades apart between sets).
constexpr CalibrationBox kRBox{1e-5, 1e-3, true};
constexpr CalibrationBox kMRBox{1.5, 10.0, false};
constexpr CalibrationBox kMTBox{1.0, 10.0, false};
constexpr CalibrationBox kBetaRBox{0.02, 2.0, true};
constexpr CalibrationBox kChiBox{0.5, 15.0, false};
constexpr double kMaxStiffnessFactor = 100.0;
constexpr double kMaxExponent = 100.0;

const ParameterTable& IntergranularStrainParameters::table() {
  static const ParameterTable t{"intergranular_strain",
                                {
                                    {"R",
                                     "-",
                                     {0.0, true},
                                     {0.01, false},
                                     "size R of the elastic range, max ||delta|| (eq. 5.43)",
                                     "eq. 5.43",
                                     ParameterRole::kMaterial,
                                     kRBox},
                                    {"m_R",
                                     "-",
                                     {1.0, false},
                                     {kMaxStiffnessFactor, false},
                                     "stiffness factor m_R after a 180 deg reversal",
                                     "eq. 5.44",
                                     ParameterRole::kMaterial,
                                     kMRBox},
                                    {"m_T",
                                     "-",
                                     {1.0, false},
                                     {kMaxStiffnessFactor, false},
                                     "stiffness factor m_T after a 90 deg turn",
                                     "eq. 5.44",
                                     ParameterRole::kMaterial,
                                     kMTBox},
                                    {"beta_r",
                                     "-",
                                     {0.0, true},
                                     {kMaxExponent, false},
                                     "evolution exponent beta_r of delta (eq. 5.46)",
                                     "eq. 5.46",
                                     ParameterRole::kMaterial,
                                     kBetaRBox},
                                    {"chi",
                                     "-",
                                     {0.0, true},
                                     {kMaxExponent, false},
                                     "interpolation exponent chi of rho (eq. 5.45)",
                                     "eq. 5.45",
                                     ParameterRole::kMaterial,
                                     kChiBox},
                                },
                                {},
                                {{"m_T", "m_R", "a reversal is the stiffest change of direction"}}};
  return t;
}

IntergranularStrainParameters IntergranularStrainParameters::from(const ParameterValues& v,
                                                                  const std::string& source) {
  validate(table(), v, source);  // bounds and m_T <= m_R (the table's at_most)
  return {v.at("R"), v.at("m_R"), v.at("m_T"), v.at("beta_r"), v.at("chi")};
}

std::array<double, 3> seed_initial_intergranular_strain(double R) {
  return {0.0, R / std::sqrt(3.0), R / std::sqrt(3.0)};
}

std::array<double, 3> compression_intergranular_strain(double R) {
  return {-R, 0.0, 0.0};
}

}  // namespace iwb::models
