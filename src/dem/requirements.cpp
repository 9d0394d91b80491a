#include "dem/requirements.hpp"

#include <fmt/core.h>

#include "common/errors.hpp"

namespace iwb::dem {

const std::vector<Qoi>& quantities_of_interest() {
  static const std::vector<Qoi> q = {
      {"peak_friction", "peak tau/sigma_n"},
      {"residual_friction", "residual tau/sigma_n (last fifth)"},
      {"dilation_rate", "dilation rate du_n/du_x (last fifth)"},
      {"band_thickness", "wall band thickness / d50"},
  };
  return q;
}

namespace {

std::string known_keys() {
  std::string s;
  for (const auto& q : quantities_of_interest()) s += (s.empty() ? "" : ", ") + std::string(q.key);
  return s;
}

}  // namespace

Requirements read_requirements(io::TableReader t) {
  Requirements r;
  for (const auto& q : quantities_of_interest()) {
    const toml::node* n = t.node(q.key);
    if (n == nullptr) continue;
    if (const auto s = n->value<std::string>()) {
      if (*s != "not needed")
        throw InputError(
            fmt::format("{} = {}: a tolerance is a number in (0, 1] (0.05 = 5 %) or \"not needed\"",
                        t.where(q.key), io::describe(*n)));
      r[q.key] = std::nullopt;
      continue;
    }
    const auto v = n->value<double>();
    if (!v || !(*v > 0.0 && *v <= 1.0))
      throw InputError(
          fmt::format("{} = {}: a tolerance is a number in (0, 1] (0.05 = 5 %) or \"not needed\"",
                      t.where(q.key), io::describe(*n)));
    r[q.key] = *v;
  }
  try {
    t.finish();
  } catch (const InputError& e) {
    throw InputError(fmt::format("{} (the quantities of interest are {})", e.what(), known_keys()));
  }
  return r;
}

}  // namespace iwb::dem
