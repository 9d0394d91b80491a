#include "models/parameters.hpp"

#include <fmt/core.h>

#include <cmath>

#include "common/errors.hpp"

namespace iwb::models {

bool ParameterSpec::admits(double v) const {
  if (!std::isfinite(v)) return false;
  const bool above = lower.open ? v > lower.value : v >= lower.value;
  const bool below = upper.open ? v < upper.value : v <= upper.value;
  return above && below;
}

std::string ParameterSpec::range() const {
  const auto end = [](double b) {
    return std::isinf(b) ? std::string("inf") : fmt::format("{:g}", b);
  };
  return fmt::format("{}{}, {}{}{}", lower.open ? "(" : "[", end(lower.value), end(upper.value),
                     upper.open ? ")" : "]", unit == "-" ? "" : " " + unit);
}

const ParameterSpec* ParameterTable::find(const std::string& key) const {
  for (const auto& e : entries)
    if (e.key == key) return &e;
  return nullptr;
}

std::vector<std::string> implausible_values(const ParameterTable& table,
                                            const ParameterValues& values,
                                            const std::string& source) {
  std::vector<std::string> warnings;
  for (const auto& [key, value] : values) {
    const ParameterSpec* spec = table.find(key);
    if (spec == nullptr || !spec->calibration) continue;
    const auto& box = *spec->calibration;
    if (value < box.lower || value > box.upper)
      warnings.push_back(fmt::format(
          "{}: {} = {:g}{} lies outside [{:g}, {:g}], the range calibrated soils span; "
          "a units slip?",
          source, key, value, spec->unit == "-" ? "" : " " + spec->unit, box.lower, box.upper));
  }
  return warnings;
}

namespace {

void refuse_unknown_keys(const ParameterTable& table, const ParameterValues& values,
                         const std::string& source) {
  for (const auto& [key, value] : values) {
    if (table.find(key) == nullptr) {
      std::string known;
      for (const auto& e : table.entries) known += (known.empty() ? "" : ", ") + e.key;
      throw InputError(fmt::format("{}: unknown key '{}' (value {:g}); table [{}] takes: {}",
                                   source, key, value, table.name, known));
    }
  }
}

double required_value(const ParameterSpec& spec, const ParameterValues& values,
                      const std::string& source) {
  const auto it = values.find(spec.key);
  if (it == values.end())
    throw InputError(fmt::format("{}: missing key '{}' ({}, allowed {})", source, spec.key,
                                 spec.doc, spec.range()));
  return it->second;
}

}  // namespace

void require_keys(const ParameterTable& table, const ParameterValues& values,
                  const std::string& source) {
  refuse_unknown_keys(table, values, source);
  for (const auto& spec : table.entries) required_value(spec, values, source);
}

void validate(const ParameterTable& table, const ParameterValues& values,
              const std::string& source) {
  refuse_unknown_keys(table, values, source);
  for (const auto& spec : table.entries)
    if (const double v = required_value(spec, values, source); !spec.admits(v))
      throw InputError(fmt::format("{}: key '{}' = {:g} is out of range; allowed {} ({})", source,
                                   spec.key, v, spec.range(), spec.doc));
  for (const auto& o : table.at_most)
    if (!(values.at(o.lower) <= values.at(o.upper)))
      throw InputError(fmt::format("{}: [{}] must satisfy {} <= {} ({}); got {} = {:g}, {} = {:g}",
                                   source, table.name, o.lower, o.upper, o.why, o.lower,
                                   values.at(o.lower), o.upper, values.at(o.upper)));
}

void require_below(const ParameterValues& values, const std::string& lower,
                   const std::string& upper, const std::string& source, const std::string& why) {
  if (!(values.at(lower) < values.at(upper)))
    throw InputError(fmt::format("{}: {} = {:g} must be below {} = {:g} ({})", source, lower,
                                 values.at(lower), upper, values.at(upper), why));
}

}  // namespace iwb::models
