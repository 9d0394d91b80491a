#pragma once
// Calibration of a model's parameter table from soil tests: a staged estimate, then the joint
// fit, each a bounded least-squares fit (src/fitting) of the model driven along the tests' own
// control (simulate.hpp).
//   start  the model family's recipe (recipe.hpp) where it declares one for the table: its
//          starting values and its stages in order (for sand Herle & Gudehus's A-D,
//          models/hypoplastic/calibration_recipe.hpp); else the middle of the table's calibration
//          boxes;
//   E      every free parameter jointly on all tests, from that start; Gauss-Newton covariance.
//          A parameter the data do not determine (singular direction, or one sigma at the
//          declared scatter above kUnidentifiedShareOfBox of its calibration box) is flagged;
//          the recipe's tied parameters (e_d0, e_i0) so flagged are set from their partner by
//          the recipe's factors and the rest refitted, and the output says so.
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "calibration/objectives.hpp"
#include "calibration/recipe.hpp"
#include "models/parameters.hpp"
#include "models/registry.hpp"
#include "soil_test/soil_test.hpp"

namespace iwb::calibration {

// Residual scales: a residual is (model - measured) / scale, so one unit is a typical measurement
// scatter and s^2 of the fit near 1 means a fit to the scatter. tau and sigma_n are scaled by
// the test's sigma0 (a stress-ratio error), e by itself.
inline constexpr double kStressRatioScale = 0.01;
inline constexpr double kVoidRatioScale = 0.002;
// Residual of a row the model did not reach (inadmissible start, domain left): the penalty that
// keeps the optimiser away from such parameters.
inline constexpr double kUnreachedResidual = 1e3;
// Flag a parameter as not identified when one sigma exceeds this share of its box.
inline constexpr double kUnidentifiedShareOfBox = 0.25;

struct CalibrationOptions {
  std::string model = "vw3d";
  // The table fitted: empty for the model's first table that declares calibration boxes
  // ([hypoplastic] of vw3d). Its staged start is the recipe the model declares for it (Herle &
  // Gudehus for [hypoplastic]); a table without one (the -igs models' [intergranular_strain])
  // starts at the middle of its boxes.
  std::string table = {};
  // A recipe in place of the one the model declares (a family's recipe tried before it is
  // declared); InputError if it is for another table than the one fitted.
  const CalibrationRecipe* recipe = nullptr;
  // The model's other tables, held at these values (a monotonic set while the intergranular
  // strain is fitted); every table the model needs but the fitted one must be here.
  std::map<std::string, models::ParameterValues> held = {};
  // The joint fit's objective (objectives.hpp); the staged start always weighs every group 1.
  ObjectiveWeights weights = {};
  // Parameters held at a given value and not fitted (keys of the model's calibrated table).
  models::ParameterValues fixed = {};
  // A start for the joint fit in place of the staged estimate (a Pareto front's previous point).
  std::optional<models::ParameterValues> start = {};
  int max_evaluations_per_stage = 300;
  int max_evaluations_joint = 100;  // BOBYQA's share; Levenberg-Marquardt finishes (fitting/)
  int polish_iterations = 300;
  // A line while it fits ("calibrating: stage B (h_s, n), phase 2 of 6, evaluation 140, RMS ...,
  // 95 s"), at most every `progress_every_s` (a fit of the DEM soil cells takes 25 s to 25 min).
  std::function<void(const std::string&)> progress = {};
  double progress_every_s = 10.0;
};

struct ParameterEstimate {
  std::string key;  // as in the parameter file: phi_c_deg, hs_kPa, ...
  double value = 0.0;
  double sigma =
      0.0;  // one standard deviation: sqrt(statistical^2 + systematic^2); inf when singular
  double sigma_statistical = 0.0;  // s^2 (J^T J)^-1
  double sigma_systematic = 0.0;   // from the recipe's factors when they stand in (else 0)
  // The same at the declared scatter (s^2 = 1 if the fit is better than that): what decides
  // `identified`, and what a noisy test of the same design would give.
  double sigma_at_scatter = 0.0;
  bool identified = true;
  bool fixed = false;    // held at a given value (CalibrationOptions::fixed)
  std::string at_bound;  // "lower"/"upper": fitted onto its box's edge; "order": held at a declared
                         // order (m_T <= m_R); else ""
  std::string how;       // which stage or rule set it
  double lower = 0.0, upper = 0.0;  // calibration box
};

struct ChannelError {
  std::string column;  // contract column, with its unit
  double rmse = 0.0;
  double end_model = 0.0, end_measured = 0.0;  // at the last row the model reached
};

struct TestFit {
  std::string name, test, boundary, status;
  std::size_t rows_reached = 0, rows = 0;
  std::vector<ChannelError> rmse;
  // CNL simple shear run to its end: the peak dilatancy rate d eps_n / d gamma (objectives.hpp)
  double peak_rate_model = NAN, peak_rate_measured = NAN;
};

// One objective group at the fitted set: its weight, how many residuals it has and their RMS in
// scatter units (unweighted: comparable across weightings), the rows the model did not reach
// apart (their penalty would swamp the RMS: one in 90 makes it 105).
struct GroupFit {
  ObjectiveGroup group;
  double weight = 1.0;
  std::size_t residuals = 0;
  double rms = 0.0;           // over the residuals of rows the model reached
  std::size_t unreached = 0;  // residuals of rows it did not reach (kUnreachedResidual each)
};

struct CalibrationResult {
  std::string model;
  std::string table;  // the parameter table fitted ("hypoplastic")
  std::map<std::string, models::ParameterValues> held;  // the other tables, as given
  std::vector<GroupFit> objectives;
  std::vector<ParameterEstimate> parameters;
  std::vector<TestFit> tests;
  std::vector<TestFit> held_out;   // tests left out of the fit and predicted with its set
  std::vector<std::string> notes;  // what was assumed, what was not identifiable, stage summaries
  double s2 = 0.0;                 // residual variance of the joint fit in (weighted) scatter units
  int evaluations = 0;
  double seconds = 0.0;
  bool converged = false;  // the joint fit stopped on its convergence test, not on a limit
  models::ParameterValues values() const;
  // The model's inputs with the fitted set: the held tables and the fitted one.
  models::ModelInputs inputs() const;
};

// InputError for no tests, a model without calibration boxes, and a fixed key the model does not
// declare or a fixed value outside its bounds.
CalibrationResult calibrate(const std::vector<soil_test::SoilTest>& tests,
                            const CalibrationOptions& options = {});

// Each objective group's residuals over `tests` run with `inputs`, unweighted, in scatter units
// (kUnreachedResidual for a row the model did not reach), indexed by ObjectiveGroup; a group no
// test gives a residual to is empty. The tests run in parallel: each is its own simulation.
std::array<std::vector<double>, kObjectiveGroups.size()> group_residuals(
    const std::vector<soil_test::SoilTest>& tests, const std::string& model,
    const models::ModelInputs& inputs);

// The RMS of a group's residuals over the rows the model reached, and how many it did not reach.
GroupFit group_fit(ObjectiveGroup group, const std::vector<double>& residuals, double weight = 1.0);

// Each objective group's RMS (unweighted, scatter units) over `tests` run with `inputs`; groups
// no test gives a residual to are left out.
std::vector<GroupFit> group_fits(const std::vector<soil_test::SoilTest>& tests,
                                 const std::string& model, const models::ModelInputs& inputs,
                                 const ObjectiveWeights& weights);

// A test run through `model` with a parameter set: its RMSE per column and end values. For the
// tests of a fit, and for a test held out of it (a prediction).
TestFit test_fit(const soil_test::SoilTest& test, const std::string& model,
                 const models::ModelInputs& inputs);

struct ParetoFront;

// The parameter file (data/params format, header comment: source and fit quality) and
// calibration.json next to it; with a front, also pareto.csv/.json, its figure (pareto.svg, .png,
// .gp) and pareto/point-K.toml, each point's parameter file (pareto_files.cpp). All or nothing.
void write_calibration(const CalibrationResult& result, const std::filesystem::path& toml_file,
                       const std::vector<soil_test::SoilTest>& tests,
                       const std::string& command_line, const ParetoFront* front = nullptr);

// The parameter file's text, and calibration.json's content.
std::string parameter_file_text(const CalibrationResult& r,
                                const std::vector<soil_test::SoilTest>& tests,
                                const std::string& command_line);
nlohmann::json calibration_json(const CalibrationResult& r,
                                const std::vector<soil_test::SoilTest>& tests,
                                const std::string& command_line);

}  // namespace iwb::calibration
