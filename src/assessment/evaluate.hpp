#pragma once
// Many model runs at once (issue 17, item 3): an assessment is thousands of independent element
// tests or replays, one per parameter row. They run on every core through TBB's work stealing; the
// rows' results come back in the rows' order, so that a result does not depend on the number of
// threads or their timing.
#include <functional>
#include <vector>

#include "assessment/sobol.hpp"

namespace iwb::assessment {

// f(row) for every row. f is called from several threads at once: it must not write shared state
// (a progress counter is the caller's, made atomic). threads 0: every core.
std::vector<std::vector<double>> evaluate_rows(const std::vector<std::vector<double>>& rows,
                                               const Quantities& f, int threads = 0);

// f counting its calls into progress(done, total), which is called by one thread at a time.
Quantities with_progress(const Quantities& f, long total,
                         const std::function<void(long, long)>& progress);

}  // namespace iwb::assessment
