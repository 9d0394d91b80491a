// Calibration recipes (issue 33 item 3): a recipe is data a model family declares, and calibrate()
// runs any of them. Here a recipe declared in this test alone, for a table that has none
// ([intergranular_strain] of vw3d-igs), runs through calibrate.cpp unchanged: its stages in their
// order, its tie after its closed form, its pass for a kind of test the set lacks skipped, and the
// joint fit from its estimate finds the synthetic set again.
#include <fmt/core.h>

#include <catch2/catch.hpp>
#include <cmath>

#include "calibration/calibrate.hpp"
#include "calibration/synthetic.hpp"
#include "common/errors.hpp"
#include "support/cyclic_soil_tests.hpp"
#include "support/fixtures.hpp"

using namespace iwb;
using driver::BoundaryKind;
using soil_test::SoilTestKind;

namespace {

// Table 5.3's m_R and m_T (5 and 2): the values the test's recipe takes for m_R and ties m_T to.
constexpr double kRecipeMR = 5.0, kRecipeMTOverMR = 0.4;

// What the recipe's stages saw, in the order they ran.
struct Trace {
  std::vector<std::string> ran;
  models::ParameterValues after_fit;
  std::size_t fit_tests = 0;
};

// 1: m_R by a closed form (here the tabulated value), m_T following it by the tie; 2: R, beta_r
// and chi fitted on every test; 3: chi again, only with oedometer tests (none here).
calibration::CalibrationRecipe two_stage_recipe(Trace& trace) {
  using calibration::StageTests;
  const auto estimate_m_R = [&trace](const calibration::StageInput&, models::ParameterValues& v) {
    trace.ran.push_back("1");
    v["m_R"] = kRecipeMR;
    return std::string("1: m_R from the table");
  };
  const auto note = [&trace](const std::string& label) {
    return [&trace, label](const models::ParameterValues& v, std::size_t tests,
                           const fitting::LeastSquaresResult&) {
      trace.ran.push_back(label);
      trace.after_fit = v;
      trace.fit_tests = tests;
      return label + ": fitted";
    };
  };
  calibration::RecipeStage oedometer_pass{"3", {"chi"}, StageTests::kAll, {}, note("3"), ""};
  oedometer_pass.only_with = SoilTestKind::kOedometer;
  return {"test-two-stage",
          "intergranular_strain",
          [](const std::vector<soil_test::SoilTest>&) {
            return models::ParameterValues{
                {"R", 3e-4}, {"m_R", 4.0}, {"m_T", 3.0}, {"beta_r", 0.3}, {"chi", 3.0}};
          },
          {{"1", {"m_R"}, StageTests::kAll, estimate_m_R, {}, ""},
           {"2", {"R", "beta_r", "chi"}, StageTests::kAll, {}, note("2"), ""},
           oedometer_pass},
          {{"m_T", "m_T", "m_R", "m_R", kRecipeMTOverMR, 0.1, "this test's factor"}}};
}

calibration::CalibrationOptions options_with(const calibration::CalibrationRecipe& recipe) {
  calibration::CalibrationOptions o;
  o.model = "vw3d-igs";
  o.table = "intergranular_strain";
  o.held["hypoplastic"] = test::table_5_3_toyoura().tables.at("hypoplastic");
  o.recipe = &recipe;
  return o;
}

}  // namespace

TEST_CASE("a recipe declared for another table runs its stages in order and recovers the set",
          "[calibration][recipe][cyclic]") {
  Trace trace;
  const auto recipe = two_stage_recipe(trace);
  const std::vector<soil_test::SoilTest> tests{test::cyclic_soil_test(BoundaryKind::kCV, 5e-4),
                                               test::cyclic_soil_test(BoundaryKind::kCV, 2e-3),
                                               test::cyclic_soil_test(BoundaryKind::kCNL, 5e-4),
                                               test::cyclic_soil_test(BoundaryKind::kCNL, 2e-3)};
  const auto r = calibration::calibrate(tests, options_with(recipe));
  for (const auto& n : r.notes) UNSCOPED_INFO(n);
  // the declared order, and no pass for the oedometer tests the set lacks
  CHECK(trace.ran == std::vector<std::string>{"1", "2"});
  REQUIRE(r.notes.size() >= 3);
  CHECK(r.notes[0] == "1: m_R from the table");
  CHECK(r.notes[1] == "2: fitted");
  CHECK(r.notes[2].rfind("E: joint fit", 0) == 0);
  // the closed form set m_R, the tie moved m_T with it, and stage 2 fitted only its own keys
  CHECK(trace.after_fit.at("m_R") == kRecipeMR);
  CHECK(trace.after_fit.at("m_T") == kRecipeMTOverMR * kRecipeMR);
  CHECK(trace.fit_tests == tests.size());
  const auto truth = test::table_5_3_toyoura_igs();
  for (const auto& p : r.parameters) {
    INFO(p.key << " = " << p.value << " (true " << truth.at(p.key) << ") " << p.how);
    CHECK(p.identified);
    CHECK(p.value == Approx(truth.at(p.key)).epsilon(1e-3));
  }
}

TEST_CASE("a recipe for another table than the one fitted is refused", "[calibration][recipe]") {
  Trace trace;
  const auto recipe = two_stage_recipe(trace);
  auto o = options_with(recipe);
  o.table = "hypoplastic";
  o.held = {{"intergranular_strain", test::table_5_3_toyoura_igs()}};
  REQUIRE_THROWS_AS(calibration::calibrate({test::cyclic_soil_test(BoundaryKind::kCV, 5e-4)}, o),
                    InputError);
  CHECK(trace.ran.empty());
}

// Until the recipes were declared, the staged start belonged to the [hypoplastic] table whatever
// the model; it is now the model's declaration that names it, so every model with that table must.
TEST_CASE("every model with the hypoplastic table declares Herle & Gudehus's recipe",
          "[calibration][recipe]") {
  for (const auto& spec : models::model_registry())
    for (const auto* table : spec.tables)
      if (table->name == "hypoplastic") {
        INFO(spec.name);
        CHECK(spec.declaration.calibration_recipe == "herle-gudehus");
        CHECK(calibration::find_recipe(spec.declaration.calibration_recipe)->table ==
              "hypoplastic");
      }
}
