#include "assessment/evaluate.hpp"

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <memory>
#include <mutex>

namespace iwb::assessment {

std::vector<std::vector<double>> evaluate_rows(const std::vector<std::vector<double>>& rows,
                                               const Quantities& f, int threads) {
  std::unique_ptr<tbb::global_control> limit;
  if (threads > 0)
    limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                  threads);
  std::vector<std::vector<double>> out(rows.size());
  // one row per task: a run takes milliseconds to seconds, far above TBB's scheduling cost
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rows.size(), 1),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t i = r.begin(); i != r.end(); ++i) out[i] = f(rows[i]);
                    });
  return out;
}

Quantities with_progress(const Quantities& f, long total,
                         const std::function<void(long, long)>& progress) {
  if (!progress) return f;
  auto done = std::make_shared<std::atomic<long>>(0);
  auto lock = std::make_shared<std::mutex>();
  return [=](const std::vector<double>& x) {
    auto q = f(x);
    const long now = ++*done;
    std::lock_guard<std::mutex> hold(*lock);
    progress(now, total);
    return q;
  };
}

}  // namespace iwb::assessment
