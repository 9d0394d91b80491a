#pragma once
// Declarative parameter tables (STYLE.md, after MFront's @Parameter/@PhysicalBounds): each model
// declares the keys users write, their units, bounds and meaning once; loading validates against
// that declaration and every message names the source, the key, the value and the allowed range.
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace iwb::models {

struct Bound {
  double value;
  bool open;  // true: the bound itself is excluded
};

struct ParameterSpec {
  std::string key;   // as written in parameter files, unit in the key where it has one
  std::string unit;  // "kPa", "deg", "-"
  Bound lower;
  Bound upper;
  std::string doc;

  bool admits(double v) const;
  std::string range() const;  // "(0, 90) deg"
};

struct ParameterTable {
  std::string name;  // TOML table the values live in, e.g. "hypoplastic"
  std::vector<ParameterSpec> entries;
  const ParameterSpec* find(const std::string& key) const;
};

using ParameterValues = std::map<std::string, double>;

inline constexpr double kUnbounded = std::numeric_limits<double>::infinity();

// Throws InputError naming `source` (file and table), the key, the value and the allowed range
// for a missing key, an unknown key or a value out of bounds.
void validate(const ParameterTable& table, const ParameterValues& values,
              const std::string& source);

}  // namespace iwb::models
