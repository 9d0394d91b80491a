#include "models/declaration.hpp"

namespace iwb::models {

std::vector<std::string> StateLayout::names() const {
  std::vector<std::string> out;
  out.reserve(components.size());
  for (const auto& c : components) out.push_back(c.name);
  return out;
}

const InitialInputSpec* find_initial_input(const std::vector<InitialInputSpec>& inputs, const std::string& key) {
  for (const auto& in : inputs)
    if (in.key == key) return &in;
  return nullptr;
}

}  // namespace iwb::models
