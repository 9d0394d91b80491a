#pragma once
// What `iwb calibrate` does between its options and its printing: check the destination, read
// the held tables, the weights, the fixed values and the soil tests (the held-out ones too, so
// that a bad one is refused before minutes of fitting), fit or trace a front, refuse a fit that
// identifies nothing, and predict the held-out tests with the fitted set.
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "calibration/calibrate.hpp"
#include "calibration/pareto.hpp"
#include "common/errors.hpp"

namespace iwb::calibration {

// As the command line gives it; read and checked by run_calibration in this order.
struct CalibrationRequest {
  std::vector<std::string> runs, held_out;  // soil-test run directories
  std::string out;                          // the parameter file to write (checked first)
  std::string model = "vw3d", table;
  std::string held_params;           // a parameter file whose tables but `table` are held
  std::vector<std::string> weights;  // GROUP=W items (objectives.hpp)
  std::vector<std::string> fixed;    // KEY=VALUE items
  std::string pareto;                // "A,B": trace the front between two groups; empty: none
  int points = 5;
};

struct CalibrationRun {
  std::vector<soil_test::SoilTest> tests;
  CalibrationResult result;  // with its held-out tests predicted
  std::optional<ParetoFront> front;
};

// Tests that identify none of the parameters (a single oedometer, say) give no parameter set
// (issue 37): the input is refused with the fit, which says why, for the caller to show.
class NothingIdentified : public InputError {
 public:
  NothingIdentified(CalibrationResult refused, const std::string& message)
      : InputError(message), fit(std::move(refused)) {}
  CalibrationResult fit;
};

// --fix KEY=VALUE items; InputError naming the item (the keys are checked against the model's
// table by calibrate()).
models::ParameterValues parse_fixed(const std::vector<std::string>& items);

// The request carried out up to the files: InputError for a bad input, NothingIdentified when the
// tests identify nothing. `progress` receives a line per point of a front.
CalibrationRun run_calibration(const CalibrationRequest& request,
                               const std::function<void(const std::string&)>& progress = {});

// The parameter file, calibration.json and (with a front) its files (write_calibration).
void write_calibration(const CalibrationRun& run, const std::filesystem::path& toml_file,
                       const std::string& command_line);

}  // namespace iwb::calibration
