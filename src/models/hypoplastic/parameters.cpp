#include "models/hypoplastic/parameters.hpp"

#include <fmt/core.h>

#include <cmath>

#include "common/errors.hpp"
#include "common/physical_limits.hpp"

namespace iwb::models {

// Upper bounds: far beyond every published set (h_s 1e3-1e8 kPa, void ratios below 2, alpha
// 0.1-0.35, beta 1-3), so only a units mistake or a typo is refused (1e300 kPa reached the rate).
constexpr double kMaxHardnessKPa = 1e9;
constexpr double kMaxExponent = 10.0;

const ParameterTable& HypoplasticParameters::table() {
  static const ParameterTable t{"hypoplastic",
                                {
                                    {"phi_c_deg",
                                     "deg",
                                     {0.0, true},
                                     {90.0, true},
                                     "critical state friction angle phi_c",
                                     "eq. 5.15",
                                     ParameterRole::kCriticalFrictionAngle,
                                     CalibrationBox{15.0, 50.0, false}},
                                    {"hs_kPa",
                                     "kPa",
                                     {0.0, true},
                                     {kMaxHardnessKPa, false},
                                     "granular hardness h_s",
                                     "eq. 5.13",
                                     ParameterRole::kMaterial,
                                     CalibrationBox{1e4, 1e8, true}},
                                    {"n",
                                     "-",
                                     {0.0, true},
                                     {1.0, true},
                                     "exponent n of the compression law (eq. 5.13)",
                                     "eq. 5.13",
                                     ParameterRole::kMaterial,
                                     CalibrationBox{0.1, 0.9, false}},
                                    {"ed0",
                                     "-",
                                     {0.0, true},
                                     {kMaxVoidRatio, false},
                                     "minimum void ratio e_d0 at p = 0",
                                     "eq. 5.13",
                                     ParameterRole::kMaterial,
                                     CalibrationBox{0.2, 1.5, false}},
                                    {"ec0",
                                     "-",
                                     {0.0, true},
                                     {kMaxVoidRatio, false},
                                     "critical void ratio e_c0 at p = 0",
                                     "eq. 5.13",
                                     ParameterRole::kMaterial,
                                     CalibrationBox{0.3, 2.0, false}},
                                    {"ei0",
                                     "-",
                                     {0.0, true},
                                     {kMaxVoidRatio, false},
                                     "maximum void ratio e_i0 at p = 0",
                                     "eq. 5.13",
                                     ParameterRole::kMaterial,
                                     CalibrationBox{0.4, 2.5, false}},
                                    {"alpha",
                                     "-",
                                     {0.0, false},
                                     {kMaxExponent, false},
                                     "pyknotropy exponent alpha (eq. 5.14)",
                                     "eq. 5.14",
                                     ParameterRole::kMaterial,
                                     CalibrationBox{0.01, 1.0, false}},
                                    {"beta",
                                     "-",
                                     {0.0, false},
                                     {kMaxExponent, false},
                                     "stiffness exponent beta (eq. 5.12)",
                                     "eq. 5.12",
                                     ParameterRole::kMaterial,
                                     CalibrationBox{0.1, 5.0, false}},
                                }};
  return t;
}

HypoplasticParameters HypoplasticParameters::from(const ParameterValues& v,
                                                  const std::string& source) {
  validate(table(), v, source);
  const double ed0 = v.at("ed0"), ec0 = v.at("ec0"), ei0 = v.at("ei0");
  if (!(ed0 < ec0 && ec0 < ei0))
    throw InputError(fmt::format(
        "{}: void ratios must satisfy ed0 < ec0 < ei0; got ed0 = {:g}, ec0 = {:g}, ei0 = {:g}",
        source, ed0, ec0, ei0));
  require_admissible(v.at("phi_c_deg") * M_PI / 180.0, ed0, ec0, ei0, v.at("alpha"), source);
  return {v.at("phi_c_deg") * M_PI / 180.0,
          v.at("hs_kPa"),
          v.at("n"),
          ed0,
          ec0,
          ei0,
          v.at("alpha"),
          v.at("beta")};
}

void require_admissible(double phi_c, double ed0, double ec0, double ei0, double alpha,
                        const std::string& source) {
  const double s = std::sin(phi_c);
  const double a = std::sqrt(3.0) * (3.0 - s) / (2.0 * std::sqrt(2.0) * s);  // eq. 5.15
  const double ratio = (ei0 - ed0) / (ec0 - ed0);  // f_d at e_i is ratio^alpha
  const double margin = 3.0 + a * a - std::sqrt(3.0) * a * std::pow(ratio, alpha);
  if (margin > 0.0) return;
  const double largest_alpha = std::log((3.0 + a * a) / (std::sqrt(3.0) * a)) / std::log(ratio);
  throw InputError(
      fmt::format("{}: alpha = {:g} with ed0 = {:g}, ec0 = {:g}, ei0 = {:g} and phi_c_deg = {:g} "
                  "is inadmissible: von "
                  "Wolffersdorff's condition 3 + a^2 - sqrt(3) a ((ei0 - ed0)/(ec0 - ed0))^alpha > "
                  "0 gives {:.4g} (a = {:.4g}, "
                  "eq. 5.15); with these void ratios and phi_c alpha must lie below {:.4g}",
                  source, alpha, ed0, ec0, ei0, phi_c * 180.0 / M_PI, margin, a, largest_alpha));
}

}  // namespace iwb::models
