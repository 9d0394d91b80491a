#include "models/declaration.hpp"

namespace iwb::models {

std::vector<std::string> StateLayout::names() const {
  std::vector<std::string> out;
  out.reserve(components.size());
  for (const auto& c : components) out.push_back(c.name);
  return out;
}

}  // namespace iwb::models
