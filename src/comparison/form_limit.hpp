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
// calibration. The movement of each parameter from the soil-test set is reported in that set's
// sigmas (its calibration.json, when it has one).
#include <filesystem>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace iwb::comparison {

struct FormLimitOptions {
  std::string model = "hvwe";
  std::string params;  // the soil-test set: the start, and what the movement is measured from
  // its calibration.json (parameters[].sigma); empty: the one beside `params`, if any
  std::filesystem::path calibration;
  std::vector<std::filesystem::path> fit_runs, held_out;
  std::filesystem::path out;
  bool force = false;
  std::string command_line;
  // BOBYQA's budget; Levenberg-Marquardt steps finish (fitting/least_squares.hpp)
  int max_evaluations = 600;
  int polish_iterations = 100;
  std::function<void(const std::string&)> progress = {};
  // What the form limit costs elsewhere: given the material tables of the form limit and of the
  // soil-test set, rows {"what", "soil_test", "form_limit"} (the soil tests' RMS per objective
  // group, say: the caller knows them, the comparison does not); empty: not asked.
  using Tables = std::map<std::string, std::map<std::string, double>>;
  using Elsewhere = std::function<nlohmann::json(const Tables& form, const Tables& soil)>;
  Elsewhere elsewhere = {};
};

// Fits, predicts, judges and writes OUT/form_limit.json, OUT/form_limit.md and OUT/form_limit.toml
// (the fitted material set as a parameter file), with OUT/manifest.json. InputError before
// anything is written for: a model that declares no calibration box (no bounds to fit within), a
// run given both to fit and to hold out, a run that is not a complete DEM run, a bad parameter
// file, a calibration.json that is not one or is truncated or edited.
nlohmann::json run_form_limit(const FormLimitOptions& options);

// How a form-limit record names a wall: "R_n 0.5, d50 2 mm".
std::string wall_name(double R_n, double d50_mm);

// The form-limit record `file` (form_limit.json) read for `model`: InputError naming the file
// when it is not one, or is another model's (a form limit says nothing of another model's form),
// or when check_form_limit_record refuses it.
nlohmann::json read_form_limit(const std::filesystem::path& file, const std::string& model);

// A form-limit record read from `file`, checked where its readers take it (form_limit_verdicts,
// causes_on): runs[] of objects with a wall, a boundary and (if any) a dir as strings, and per
// quantity the verdicts soil_test_predicted and form_limit as strings. InputError "FILE: key
// '/runs/0/wall' = 3: should be a string" (issue 60), never nlohmann's type_error.
void check_form_limit_record(const nlohmann::json& record, const std::filesystem::path& file);

// Per quantity, the form limit's verdict for a run of this wall and boundary in `record` (the
// run itself when the record holds it, else the first run of its wall and boundary); empty when
// the record has no such run.
std::map<std::string, std::string> form_limit_verdicts(const nlohmann::json& record,
                                                       const std::filesystem::path& dem_dir,
                                                       double R_n, double d50_mm,
                                                       const std::string& boundary);

// A "breaks" verdict's cause: "form" when the form limit also breaks the quantity, else
// "calibration"; empty for other verdicts or a quantity the form limit did not judge.
std::string cause_of(const std::string& verdict, const std::string& form_limit_verdict);

}  // namespace iwb::comparison
