#pragma once
// A calibration recipe: how a model family's parameter table is estimated before the joint fit,
// declared by the family as data (ModelDeclaration::calibration_recipe names it) rather than
// written into calibrate.cpp, which runs any recipe (src/calibration/README.md). A table without
// one starts at the middle of its calibration boxes.
//   start   the first estimate, from the tests (the loosest e0, say);
//   stages  in order, each setting some keys from some of the tests: a bounded least-squares fit
//           of those keys, or a closed form the family supplies (phi_c from the critical states);
//   ties    parameters that follow another by a factor where the tests cannot identify them
//           (e_i0 = 1.15 e_c0), each factor with its one-sigma spread and its source.
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "calibration/soil_test.hpp"
#include "fitting/least_squares.hpp"
#include "models/parameters.hpp"

namespace iwb::calibration {

// Which of the tests a stage reads.
enum class StageTests {
  kOedometer,
  kCriticalState,  // the simple-shear tests that end at a critical state (ends_at_critical_state)
  kAll,
};

// `key` = factor * `of` where the tests cannot identify `key` (the joint fit then refits the rest
// with every tie holding), and after a closed-form stage sets `of`. The names are as the notes
// write them ("e_i0").
struct FactorTie {
  std::string key, name;
  std::string of, of_name;
  double factor = 1.0;
  double sigma = 0.0;  // one-sigma spread of the factor over its evidence (a systematic sigma)
  std::string source;  // "Herle & Gudehus 1999 factor"
};

// What a closed-form stage reads: every test, and the indices of the stage's own.
struct StageInput {
  const std::vector<SoilTest>& tests;
  const std::vector<std::size_t>& selected;
};

struct RecipeStage {
  std::string label;              // "A": how the notes and the README name it
  std::vector<std::string> keys;  // what the stage sets
  StageTests tests = StageTests::kAll;
  // A closed form: writes `keys` into the values from the selected tests and returns the stage's
  // note. Skipped when every one of its keys is fixed. Empty: the stage is a bounded
  // least-squares fit of the free ones of `keys` on the selected tests.
  std::function<std::string(const StageInput&, models::ParameterValues&)> estimate = {};
  // A fit's note, from the values it reached, the number of tests it read and its result.
  std::function<std::string(const models::ParameterValues&, std::size_t,
                            const fitting::LeastSquaresResult&)>
      fitted = {};
  std::string without_tests;  // the note when the tests hold none of the stage's
  // Run only when the tests include this kind (a second pass that only data of it can settle).
  std::optional<SoilTestKind> only_with = {};
};

struct CalibrationRecipe {
  std::string name;   // as ModelDeclaration::calibration_recipe names it
  std::string table;  // the parameter table it estimates ("hypoplastic")
  std::function<models::ParameterValues(const std::vector<SoilTest>&)> start;
  std::vector<RecipeStage> stages;
  std::vector<FactorTie> ties;
};

// The recipe a model declaration names; nullptr for "" (none). InputError for a name no recipe
// has (a model added at run time may name one).
const CalibrationRecipe* find_recipe(const std::string& name);

// Every tie's key set from its partner in `values`.
void apply_ties(const std::vector<FactorTie>& ties, models::ParameterValues& values);

}  // namespace iwb::calibration
