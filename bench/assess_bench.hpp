#pragma once
// `iwb bench assess`: the throughput of the model assessment (issue 17, item 3). For each
// interface model of the league (ModelDeclaration::plan_rank), a Latin hypercube of monotonic CNL
// simple-shear element tests (gamma 0.1 in 200 increments, every material parameter at COV 0.05
// about the model's example set, from its example start), first on one thread, then on every
// core: element tests per second per core and the speed-up. Prints figures; asserts nothing.
#include <nlohmann/json.hpp>

namespace iwb::bench {

struct AssessBenchOptions {
  int tests = 200;  // element tests per model and thread count
};

nlohmann::json run_assess_bench(const AssessBenchOptions& options);

}  // namespace iwb::bench
