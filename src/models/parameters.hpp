#pragma once
// Declarative parameter tables (STYLE.md, after MFront's @Parameter/@PhysicalBounds): each model
// declares the keys users write, their units, bounds and meaning once; loading validates against
// that declaration and every message names the source, the key, the value and the allowed range.
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace iwb::models {

struct Bound {
  double value;
  bool open;  // true: the bound itself is excluded
};

// What a parameter is for beyond its bounds: the workbench reads parameters by role, never by key.
enum class ParameterRole {
  kMaterial,               // an ordinary constant of the model
  kCriticalFrictionAngle,  // phi_c: the default K0 = 1 - sin phi_c, kappa_r from a wall angle
  kOption,                 // a switch written as a number
};

// Where `iwb calibrate` may search a parameter: finite, usually narrower than the physical bounds.
struct CalibrationBox {
  double lower, upper;
  bool logarithmic;  // fitted as ln x (h_s)
};

struct ParameterSpec {
  std::string key;   // as written in parameter files, unit in the key where it has one
  std::string unit;  // "kPa", "deg", "-"
  Bound lower;
  Bound upper;
  std::string doc;
  // Appended with defaults so the tables written before the model contract compile unchanged.
  std::string equation = {};  // "eq. 5.13", "Table 6.5"
  ParameterRole role = ParameterRole::kMaterial;
  std::optional<CalibrationBox> calibration = {};

  bool admits(double v) const;
  std::string range() const;  // "(0, 90) deg"
};

struct ParameterTable {
  std::string name;  // TOML table the values live in, e.g. "hypoplastic"
  std::vector<ParameterSpec> entries;
  // Groups of keys of which exactly one is given, the others derived by the model (HCC's M or
  // phi_c_deg, ERRATA 15); read by validate() once a table declares one.
  std::vector<std::vector<std::string>> one_of = {};
  // Pairs that must keep an order: `lower` <= `upper` (the intergranular strain's m_T <= m_R).
  // Read by validate(), and by the calibration, which holds a trial's `lower` at `upper` rather
  // than let the optimiser step into a refusal (a penalty wall the Jacobian cannot cross).
  struct AtMost {
    std::string lower, upper, why;
  };
  std::vector<AtMost> at_most = {};
  const ParameterSpec* find(const std::string& key) const;
};

using ParameterValues = std::map<std::string, double>;

inline constexpr double kUnbounded = std::numeric_limits<double>::infinity();

// Throws InputError naming `source` (file and table), the key, the value and the allowed range
// for a missing key, an unknown key or a value out of bounds.
void validate(const ParameterTable& table, const ParameterValues& values,
              const std::string& source);

// validate's first half: InputError for an unknown key or a missing one, bounds unchecked. For the
// models that have never refused a value outside their bounds (mc, hyperbolic, api_tz), whose
// `iwb assess` samples cross them (hyperbolic's R_f above 1): what a refusal would do to those
// samples is still to be decided (issue 60's report); a missing key must not be "map::at".
void require_keys(const ParameterTable& table, const ParameterValues& values,
                  const std::string& source);

// Warnings for values inside their bounds but outside their calibration box, the range the
// declared soils span (MOOSE's plausibility warning: phi_c_deg = 0.4887, 28 degrees written in
// radians, is admissible and runs to tau/sigma_n = 0.003). Empty when every value is plausible.
std::vector<std::string> implausible_values(const ParameterTable& table,
                                            const ParameterValues& values,
                                            const std::string& source);

// Throws InputError naming `source` unless values[lower] < values[upper]; `why` says what the order
// means ("unloading is stiffer than normal compression").
void require_below(const ParameterValues& values, const std::string& lower,
                   const std::string& upper, const std::string& source, const std::string& why);

}  // namespace iwb::models
