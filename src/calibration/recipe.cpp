#include "calibration/recipe.hpp"

#include <fmt/core.h>

#include "common/errors.hpp"

namespace iwb::calibration {

const CalibrationRecipe* find_recipe(const std::string& name) {
  // every family's recipes, from its folder (models/<family>/calibration_recipe.cpp, collected by
  // the generated registered_recipes.cpp)
  static const std::vector<const CalibrationRecipe*> recipes = known_recipes();
  if (name.empty()) return nullptr;
  std::string names;
  for (const auto* r : recipes) {
    if (r->name == name) return r;
    names += (names.empty() ? "" : ", ") + r->name;
  }
  throw InputError(fmt::format("calibration recipe '{}': no such recipe (known: {})", name, names));
}

void apply_ties(const std::vector<FactorTie>& ties, models::ParameterValues& values) {
  for (const auto& t : ties) values[t.key] = t.factor * values.at(t.of);
}

}  // namespace iwb::calibration
