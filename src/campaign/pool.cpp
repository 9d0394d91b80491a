#include "campaign/pool.hpp"

#include <fmt/core.h>

#include <chrono>
#include <cmath>
#include <condition_variable>
#include <mutex>
#include <thread>

#include "campaign/job_start.hpp"
#include "campaign/sweep_record.hpp"
#include "dem/engines/engines.hpp"
#include "dem/run/consolidation_cache.hpp"
#include "dem/run/run.hpp"
#include "dem/scene/scene.hpp"
#include "io/json_file.hpp"
#include "io/run_directory.hpp"

namespace iwb::campaign {

namespace fs = std::filesystem;
using nlohmann::json;
using Clock = std::chrono::steady_clock;

namespace {

// How often the pool looks at the interrupt flag.
constexpr auto kPoll = std::chrono::milliseconds(200);

struct JobResult {
  std::string status;
  double wall_seconds = 0.0;
  JobStart how = JobStart::kFresh;
};

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

class Pool {
 public:
  Pool(const SweepSpec& spec, const std::vector<Job>& jobs, const PoolOptions& opt)
      : jobs_(jobs),
        opt_(opt),
        record_(initial_record(spec, jobs, opt.out, opt.command_line,
                               {{"executor", "local"},
                                {"jobs_at_once", opt.jobs},
                                {"processes_per_job", opt.processes}})) {}

  json run() {
    std::vector<std::size_t> queue = reuse_complete_runs();
    std::unique_lock lock(mutex_);
    write_record();
    std::size_t next = 0;
    for (;;) {
      if (opt_.interrupt && opt_.interrupt->load()) stop_ = true;
      while (!stop_ && running_ < opt_.jobs && next < queue.size()) start(queue[next++]);
      if (running_ == 0 && (stop_ || next == queue.size())) break;
      cv_.wait_for(lock, kPoll);
      if (seconds_since(last_progress_) > kProgressEverySeconds) report();
    }
    lock.unlock();
    for (auto& t : threads_) t.join();
    record_["status"] = overall_status(record_, stop_);
    record_["finished"] = io::utc_timestamp();
    write_record();
    report();
    return record_;
  }

 private:
  // Jobs whose complete run of the same scene is already there are not queued.
  std::vector<std::size_t> reuse_complete_runs() {
    std::vector<std::size_t> queue;
    for (std::size_t i = 0; i < jobs_.size(); ++i) {
      const fs::path dir = opt_.out / run_path(jobs_[i]);
      if (how_to_start(dir, job_scene_sha256(jobs_[i], opt_.out)) != JobStart::kSkip) {
        queue.push_back(i);
        continue;
      }
      mark_reused(record_["jobs"][i], dir);
    }
    return queue;
  }

  void start(std::size_t i) {  // under the lock
    ++running_;
    record_["jobs"][i]["status"] = "running";
    record_["jobs"][i]["started"] = io::utc_timestamp();
    write_record();
    threads_.emplace_back([this, i] {
      const JobResult r = run_one(i);
      std::lock_guard guard(mutex_);
      finish(i, r);
      cv_.notify_all();
    });
  }

  JobResult run_one(std::size_t i) {  // without the lock: this is where the hours go
    const Job& job = jobs_[i];
    const auto t0 = Clock::now();
    const fs::path dir = opt_.out / run_path(job);
    JobStart how = JobStart::kFresh;
    try {
      how = how_to_start(dir, job_scene_sha256(job, opt_.out));
      const auto engine = dem::make_engine(job.engine);
      const auto scene = dem::parse_scene(job.scene_text, (opt_.out / scene_path(job)).string());
      dem::RunOptions ro{dir,
                         opt_.processes,
                         how == JobStart::kResume,
                         how == JobStart::kFresh,
                         opt_.command_line,
                         &stop_,
                         [this, i](const std::string& line) { note_progress(i, line); },
                         dem::consolidation_cache_dir(opt_.out / "consolidated")};
      const auto outcome = dem::run_scene(scene, job.scene_text, *engine, ro);
      return {outcome.status, seconds_since(t0), how};
    } catch (const std::exception& e) {
      return {fmt::format("failed: {}", e.what()), seconds_since(t0), how};
    }
  }

  // A run's own progress line (its stage, how far, its ETA), kept for the sweep's next report:
  // a campaign's jobs run for an hour and more, and until the first ends the sweep has no ETA.
  void note_progress(std::size_t i, const std::string& line) {  // from the job's thread
    std::lock_guard guard(mutex_);
    job_progress_[i] = line;
  }

  void finish(std::size_t i, const JobResult& r) {  // under the lock
    job_progress_[i].clear();
    --running_;
    ++ended_;
    auto& j = record_["jobs"][i];
    j["status"] = r.status;
    j["start"] = to_string(r.how);
    j["wall_seconds"] = r.wall_seconds;
    j["finished"] = io::utc_timestamp();
    if (r.status == "complete") run_seconds_.push_back(r.wall_seconds);
    if (opt_.stop_after > 0 && ended_ >= opt_.stop_after) stop_ = true;
    write_record();
    report(fmt::format("{}: {}", jobs_[i].name, r.status));
  }

  // Remaining jobs in waves of `jobs` at once, each wave as long as the mean job run so far.
  std::string eta(const JobCounts& c) const {
    if (run_seconds_.empty()) return "ETA after the first job";
    double mean = 0.0;
    for (double s : run_seconds_) mean += s / double(run_seconds_.size());
    const double waves = std::ceil(double(c.pending + c.running) / double(opt_.jobs));
    return fmt::format("ETA ~{:.0f} s", waves * mean);
  }

  void report(const std::string& event = "") {
    last_progress_ = Clock::now();
    if (!opt_.progress) return;
    const JobCounts c = count_jobs(record_);
    const std::string prefix = event.empty() ? "" : event + "; ";
    std::string running;
    for (std::size_t i = 0; i < jobs_.size(); ++i)
      if (!job_progress_[i].empty())
        running += fmt::format("; {}: {}", jobs_[i].name, job_progress_[i]);
    opt_.progress(fmt::format(
        "{}sweep: {}/{} complete ({} reused), {} running, {} failed, {} to do, {:.0f} s, {}{}",
        prefix, c.complete, jobs_.size(), c.reused, c.running, c.failed, c.pending,
        seconds_since(started_), eta(c), running));
  }

  void write_record() { campaign::write_record(record_, opt_.out); }

  const std::vector<Job>& jobs_;
  const PoolOptions& opt_;
  json record_;
  std::mutex mutex_;
  std::condition_variable cv_;
  std::atomic<bool> stop_{false};  // handed to every run_scene: the one way jobs are stopped
  std::vector<std::thread> threads_;
  int running_ = 0, ended_ = 0;
  std::vector<double> run_seconds_;  // complete jobs of this invocation, for the ETA
  std::vector<std::string> job_progress_ =
      std::vector<std::string>(jobs_.size());  // running jobs' last line
  Clock::time_point started_ = Clock::now(), last_progress_ = Clock::now();
};

}  // namespace

json run_jobs(const SweepSpec& spec, const std::vector<Job>& jobs, const PoolOptions& opt) {
  fs::create_directories(opt.out);
  return Pool(spec, jobs, opt).run();
}

}  // namespace iwb::campaign
