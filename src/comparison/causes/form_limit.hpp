#pragma once
// The form limit of an interface model on a set of DEM runs (issue 38 item 4): is a "breaks" the
// model's form or its calibration? Every material parameter with a declared calibration box
// (shared by all runs) and the model's fit parameters (kappa_r and d_s, one of each per wall:
// R_n and d50) are fitted jointly to the fit runs, each residual as in `iwb compare`'s joint fit
// (tau and the free normal quantity in units of the cell's seed scatter, fit.hpp), from the
// soil-test set; runs held out are then predicted with the result. Every run is judged on the
// quantities of interest like `iwb compare` judges it (verdicts.hpp). A quantity that still
// breaks at the form limit breaks for the form: no parameter set inside the declared boxes meets
// it on these grains; one that holds there but breaks with the soil-test set breaks for the
// calibration only when a set the soil tests accept holds it (issue 59: the free form limit's set
// on the R_n 0.5 truth moved e_c0 by +562 of the soil tests' sigmas and raised their shear RMS
// from 1.77 to 18.7, and a user told "calibration" would recalibrate and fail). So with soil
// tests, a second fit: the same unknowns, the same residuals, constrained to the sets the soil
// tests accept (kSoilAcceptance; fitting/constrained.hpp). A "breaks" of the soil-test set's
// prediction is then
//   calibration  when the joint set (soil tests and wall together) holds it;
//   form         when it does not: no set inside the boxes holds it (the free limit breaks it
//                too), or only sets the soil tests refuse do (the note names the group);
//   calibration (unchecked)  without soil tests, where the free limit holds it.
// The movement of each parameter from the soil-test set is reported in that set's sigmas (its
// calibration.json, when it has one).
#include <filesystem>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "models/registry.hpp"

namespace iwb::comparison {

// The soil tests accept a set whose every objective group's RMS (scatter units) is at most this
// times the soil-test set's own, with every row reached. The soil-test set is the best fit of
// those tests, and its RMS is already the form's miss there (1.8 oedometer, 1.8 shear, 6.7
// dilatancy on the truth grains), so the bar is relative: a quarter more on a group is a set a
// modeller could still defend from the same tests; the sets that hold the rough walls without the
// soil tests raise the shear group tenfold. A stated choice, not a derived one: --soil-acceptance
// changes it, and the form-limit README shows the labels at other factors.
inline constexpr double kSoilAcceptance = 1.25;

struct FormLimitOptions {
  std::string model = models::kDefaultInterfaceModel;
  std::string params;  // the soil-test set: the start, and what the movement is measured from
  // its calibration.json (parameters[].sigma); empty: the one beside `params`, if any
  std::filesystem::path calibration;
  std::vector<std::filesystem::path> fit_runs, held_out;
  // Only these material parameters ("table.key" or "key") are fitted, the others held at
  // `params`; empty: every one with a calibration box. With `hold_walls` each wall's kappa_r and
  // d_s stay at their prediction (eq. 5.35, 5 d50) instead of being fitted. Either makes the run a
  // fit of those parameters, not a form limit: a break it leaves says nothing of the form, and no
  // cause is given (issue 56: a candidate's new parameters fitted with the soil held).
  std::vector<std::string> free;
  bool hold_walls = false;
  bool restricted() const { return !free.empty() || hold_walls; }
  std::filesystem::path out;
  bool force = false;
  std::string command_line;
  // BOBYQA's budget; Levenberg-Marquardt steps finish (fitting/least_squares.hpp)
  int max_evaluations = 600;
  int polish_iterations = 100;
  std::function<void(const std::string&)> progress = {};
  // The soil tests, the second judge of a material set (issue 59): per objective group, its
  // residuals in scatter units for the given material tables (the caller knows the soil tests and
  // the model they run with, the comparison does not). Empty: no soil tests, and no break can be
  // put down to the calibration, only to the form or to "calibration (unchecked)".
  using Tables = std::map<std::string, std::map<std::string, double>>;
  struct SoilGroup {
    std::string group;
    std::vector<double> residuals;  // a row the model did not reach counts as a large residual
    double rms = 0.0;               // over the rows reached
    std::size_t unreached = 0;
  };
  using SoilTests = std::function<std::vector<SoilGroup>(const Tables&)>;
  SoilTests soil_tests = {};
  std::string soil_tests_about;  // "30 soil tests": for the tables
  // A set the soil tests accept: every group's RMS at most this times the soil-test set's, and
  // every row reached (kSoilAcceptance).
  double soil_acceptance = kSoilAcceptance;
  int joint_evaluations = 600;  // COBYLA's budget a pass of the joint fit (2 starts x 4 passes)
};

// Fits, predicts, judges and writes OUT/form_limit.json, OUT/form_limit.md and OUT/form_limit.toml
// (the fitted material set as a parameter file), with OUT/manifest.json. InputError before
// anything is written for: a model that declares no calibration box (no bounds to fit within), a
// run given both to fit and to hold out, a run that is not a complete DEM run, a bad parameter
// file, a calibration.json that is not one or is truncated or edited.
nlohmann::json run_form_limit(const FormLimitOptions& options);

}  // namespace iwb::comparison
