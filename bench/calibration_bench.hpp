#pragma once
// `iwb bench calibration`: the cost of a full calibration (issue 60: speed is measured by a
// benchmark that prints figures, never by a timed unit test). The workload is the unit test's
// (tests/calibration/test_calibration.cpp, "recovers the Hostun parameters"): five noise-free
// synthetic vw3d soil tests of Table 5.2 Hostun (an oedometer, dense and loose CNL and CV simple
// shears), calibrated by `calibration::calibrate`. Prints CPU and wall seconds, evaluations and the
// largest relative error of a recovered parameter; asserts nothing.
#include <nlohmann/json.hpp>
#include <vector>

#include "models/registry.hpp"
#include "soil_test/soil_test.hpp"

namespace iwb::bench {

// A noise-free synthetic soil test of `truth` as the calibration tests build them: an oedometer
// from 10 kPa to sigma_max and back to 100 kPa (30 rows a branch), or a simple shear to gamma 2
// (40 rows) from e0.
soil_test::SoilTest synthetic_soil_test(soil_test::SoilTestKind kind, driver::BoundaryKind boundary,
                                        double e0, const std::string& name,
                                        const models::ModelInputs& truth,
                                        double sigma_max_kPa = 5000.0);

// The five synthetic soil tests of `truth` (the unit test's targets, built once here).
std::vector<soil_test::SoilTest> hostun_soil_tests(const models::ModelInputs& truth);

struct CalibrationBenchOptions {
  int repeats = 1;  // calibrations; the fastest is reported
};

nlohmann::json run_calibration_bench(const CalibrationBenchOptions& options);

}  // namespace iwb::bench
