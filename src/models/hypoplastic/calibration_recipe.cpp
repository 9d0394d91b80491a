#include "models/hypoplastic/calibration_recipe.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "models/hypoplastic/von_wolffersdorff.hpp"

namespace iwb::calibration {

namespace {

// In the order the joint fit checks them and its notes name them.
const std::vector<FactorTie>& limit_ties() {
  static const std::vector<FactorTie> ties{
      {"ed0", "e_d0", "ec0", "e_c0", kEd0OverEc0, kEd0OverEc0Sigma, "Herle & Gudehus 1999 factor"},
      {"ei0", "e_i0", "ec0", "e_c0", kEi0OverEc0, kEi0OverEc0Sigma, "Herle & Gudehus 1999 factor"}};
  return ties;
}

// The start: phi_c, h_s, n, alpha and beta inside their boxes where sands have them; e_c0 a
// little above the loosest test's e0 (a loose specimen starts near its critical state), the limits
// from it by the factors.
constexpr double kStartPhiCDeg = 30.0, kStartHsKPa = 1e6, kStartN = 0.3, kStartAlpha = 0.15,
                 kStartBeta = 1.0;
constexpr double kStartEc0OverLoosestE0 = 1.05;

models::ParameterValues starting_values(const std::vector<soil_test::SoilTest>& tests) {
  double loosest = 0.0;
  for (const auto& t : tests) loosest = std::max(loosest, t.e0);
  models::ParameterValues v{{"phi_c_deg", kStartPhiCDeg},
                            {"hs_kPa", kStartHsKPa},
                            {"n", kStartN},
                            {"ec0", kStartEc0OverLoosestE0 * loosest},
                            {"alpha", kStartAlpha},
                            {"beta", kStartBeta}};
  apply_ties(limit_ties(), v);
  return v;
}

// A: the residual tau/sigma_n of the tests at critical state through vW's simple-shear relation.
std::string phi_c_from_critical_states(const StageInput& in, models::ParameterValues& v) {
  double eta = 0.0;
  for (const auto i : in.selected)
    eta += in.tests[i].tau_kPa.back() / in.tests[i].sigma_n_kPa.back();
  eta /= double(in.selected.size());
  v["phi_c_deg"] = models::friction_angle_of_simple_shear_ratio(eta) * 180.0 / M_PI;
  return fmt::format(
      "A: residual tau/sigma_n = {:.5f} over {} test(s) at critical state -> "
      "phi_c = {:.3f} deg through the simple-shear critical state "
      "(tan phi_c would be {:.3f})",
      eta, in.selected.size(), v["phi_c_deg"], std::tan(v["phi_c_deg"] * M_PI / 180.0));
}

// The smallest e_c0 whose e_i (e_i0 = kEi0OverEc0 e_c0, Bauer's factor at p = 3 sigma0, an upper
// bound of the start's mean stress) lies 1 % above every test's initial void ratio.
double smallest_admissible_ec0(const std::vector<soil_test::SoilTest>& tests,
                               const models::ParameterValues& v) {
  double out = 0.0;
  for (const auto& t : tests) {
    const double factor = std::exp(-std::pow(3.0 * t.sigma0_kPa / v.at("hs_kPa"), v.at("n")));
    out = std::max(out, 1.01 * t.e0 / (kEi0OverEc0 * factor));
  }
  return out;
}

// C: Bauer (eq. 5.13): e_c = e_c0 exp(-(p/h_s)^n) with p = -tr T = 3 sigma_n at the critical state
// of simple shear (sigma_p -> sigma_n there; vw3d README).
std::string ec0_from_critical_void_ratios(const StageInput& in, models::ParameterValues& v) {
  double ec0 = 0.0;
  for (const auto i : in.selected) {
    const auto& t = in.tests[i];
    ec0 += t.e.back() / std::exp(-std::pow(3.0 * t.sigma_n_kPa.back() / v["hs_kPa"], v["n"]));
  }
  v["ec0"] = ec0 / double(in.selected.size());
  // A DEM cell that localises ends with a stationary bulk e below the critical state line (only
  // its band dilated to it): e_c0 from such a test can leave the loosest tests' starts above
  // e_i, where no fit can reach them. The start is raised until every test starts admissibly.
  const double admissible = smallest_admissible_ec0(in.tests, v);
  const bool raised = admissible > v["ec0"];
  v["ec0"] = std::max(v["ec0"], admissible);
  return fmt::format(
      "C: e_c0 = {:.4f} from the critical void ratios of {} test(s){}; e_i0 = "
      "{} e_c0, e_d0 = {} e_c0 as starting values",
      v["ec0"], in.selected.size(),
      raised ? fmt::format(", raised from {:.4f} so that every test starts below e_i (a localised "
                           "cell's bulk e lies below the critical state line)",
                           ec0 / double(in.selected.size()))
             : "",
      kEi0OverEc0, kEd0OverEc0);
}

std::string compression_note(const models::ParameterValues& v, std::size_t tests,
                             const fitting::LeastSquaresResult& r) {
  return fmt::format(
      "B: h_s = {:.4g} kPa, n = {:.4f} from {} oedometer test(s), RMS "
      "residual {:.3g} scatter units ({})",
      v.at("hs_kPa"), v.at("n"), tests, r.rmse, r.stop_reason);
}

std::string density_note(const models::ParameterValues& v, std::size_t,
                         const fitting::LeastSquaresResult& r) {
  return fmt::format("D: alpha = {:.4f}, beta = {:.4f} from all tests, RMS residual {:.3g} ({})",
                     v.at("alpha"), v.at("beta"), r.rmse, r.stop_reason);
}

RecipeStage compression_stage() {
  return {"B", {"hs_kPa", "n"},  StageTests::kOedometer,
          {},  compression_note, "B: no oedometer test; h_s and n are left to the joint fit"};
}

RecipeStage void_ratio_stage() {
  return {"C",
          {"ec0"},
          StageTests::kCriticalState,
          ec0_from_critical_void_ratios,
          {},
          "C: no critical state reached; e_c0 starts from the loosest test and is left to the "
          "joint fit"};
}

// B and C twice when there are oedometer tests: h_s, n and e_c0 depend on each other only weakly
// (e_c0 through exp(-(3 sigma_n/h_s)^n) ~ 0.9, the oedometric curve through the limits), and two
// passes settle them.
RecipeStage second_pass(RecipeStage s) {
  s.only_with = soil_test::SoilTestKind::kOedometer;
  return s;
}

}  // namespace

const CalibrationRecipe& herle_gudehus_recipe() {
  static const CalibrationRecipe recipe{
      "herle-gudehus",
      "hypoplastic",
      starting_values,
      {{"A",
        {"phi_c_deg"},
        StageTests::kCriticalState,
        phi_c_from_critical_states,
        {},
        fmt::format("A: no simple-shear test ends at a critical state (tau/sigma_n and e "
                    "stationary over the last fifth); phi_c starts from {:g} deg and is left to "
                    "the joint fit",
                    kStartPhiCDeg)},
       compression_stage(),
       void_ratio_stage(),
       second_pass(compression_stage()),
       second_pass(void_ratio_stage()),
       {"D", {"alpha", "beta"}, StageTests::kAll, {}, density_note, ""}},
      limit_ties()};
  return recipe;
}

// The sand family's recipes, collected by the generated recipe list (src/CMakeLists.txt).
void register_recipes_hypoplastic(std::vector<const CalibrationRecipe*>& recipes) {
  recipes.push_back(&herle_gudehus_recipe());
}

}  // namespace iwb::calibration
