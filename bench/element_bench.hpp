#pragma once
// `iwb bench element`: the cost of the continuum core. For each model: rate evaluations per
// second (double and dual numbers) on a sheared state, and the wall time of a 2000-increment CNL
// simple shear (d gamma = 1e-4) at relative tolerance 1e-6. Prints figures; asserts nothing.
#include <nlohmann/json.hpp>

namespace iwb::bench {

struct ElementBenchOptions {
  int repeats = 5;  // the test time is the best of these
};

nlohmann::json run_element_bench(const ElementBenchOptions& options);

}  // namespace iwb::bench
