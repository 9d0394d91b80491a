#include "models/declaration.hpp"

#include <fmt/core.h>

namespace iwb::models {

std::vector<std::string> StateLayout::names() const {
  std::vector<std::string> out;
  out.reserve(components.size());
  for (const auto& c : components) out.push_back(c.name);
  return out;
}

std::optional<RoughnessScheme> RoughnessSupport::scheme_named(const std::string& name) const {
  for (const auto s : schemes)
    if (name == to_string(s)) return s;
  return std::nullopt;
}

std::string RoughnessSupport::scheme_names(const std::string& separator) const {
  std::string out;
  for (const auto s : schemes)
    out += fmt::format("{}\"{}\"", out.empty() ? "" : separator, to_string(s));
  return out;
}

const InitialInputSpec* find_initial_input(const std::vector<InitialInputSpec>& inputs,
                                           const std::string& key) {
  for (const auto& in : inputs)
    if (in.key == key) return &in;
  return nullptr;
}

}  // namespace iwb::models
