#include "calibration/recipe.hpp"

#include <fmt/core.h>

#include "calibration/herle_gudehus_recipe.hpp"
#include "common/errors.hpp"

namespace iwb::calibration {

namespace {

// The recipes model declarations may name: one line per model family that has one.
std::vector<const CalibrationRecipe*> known_recipes() {
  return {&herle_gudehus_recipe()};
}

}  // namespace

const CalibrationRecipe* find_recipe(const std::string& name) {
  if (name.empty()) return nullptr;
  std::string names;
  for (const auto* r : known_recipes()) {
    if (r->name == name) return r;
    names += (names.empty() ? "" : ", ") + r->name;
  }
  throw InputError(fmt::format("calibration recipe '{}': no such recipe (known: {})", name, names));
}

void apply_ties(const std::vector<FactorTie>& ties, models::ParameterValues& values) {
  for (const auto& t : ties) values[t.key] = t.factor * values.at(t.of);
}

}  // namespace iwb::calibration
