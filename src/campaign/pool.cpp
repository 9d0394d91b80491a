#include "campaign/pool.hpp"

#include <chrono>
#include <cmath>
#include <condition_variable>
#include <fmt/core.h>
#include <mutex>
#include <thread>

#include "campaign/job_start.hpp"
#include "dem/consolidation_cache.hpp"
#include "dem/engines.hpp"
#include "dem/run.hpp"
#include "dem/scene.hpp"
#include "io/json_file.hpp"
#include "io/run_directory.hpp"

namespace iwb::campaign {

namespace fs = std::filesystem;
using nlohmann::json;
using Clock = std::chrono::steady_clock;

namespace {

// How often the pool looks at the interrupt flag, and how often it repeats the progress line
// while nothing changes.
constexpr auto kPoll = std::chrono::milliseconds(200);
constexpr double kProgressEverySeconds = 15.0;

struct JobResult {
  std::string status;
  double wall_seconds = 0.0;
  JobStart how = JobStart::kFresh;
};

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// The engine's own time in an earlier run, for reused jobs.
double recorded_seconds(const fs::path& dir) {
  const auto m = io::read_json_file(dir / "manifest.json");
  double s = 0.0;
  for (const auto& [name, stage] : m["stages"].items()) s += stage.value("wall_seconds", 0.0);
  return s;
}

// The sha256 that decides reuse of a job's run (dem::scene_sha256: its text and any wall file it names).
std::string job_scene_sha256(const Job& job, const fs::path& out) {
  return dem::scene_sha256(dem::parse_scene(job.scene_text, (out / scene_path(job)).string()), job.scene_text);
}

json initial_record(const SweepSpec& spec, const std::vector<Job>& jobs, const PoolOptions& opt) {
  json r = {{"kind", "dem-sweep"},
            {"sweep", spec.file.string()},
            {"sweep_sha256", io::sha256_hex(spec.text)},
            {"scene", spec.scene_file.string()},
            {"command_line", opt.command_line},
            {"jobs_at_once", opt.jobs},
            {"processes_per_job", opt.processes},
            {"started", io::utc_timestamp()},
            {"status", "running"},
            {"jobs", json::array()}};
  for (const auto& job : jobs) {
    json values = json::object();
    for (const auto& [key, value] : job.values) values[key] = io::to_toml(value);
    r["jobs"].push_back({{"name", job.name}, {"engine", job.engine}, {"values", values},
                         {"scene", scene_path(job)}, {"run", run_path(job)},
                         {"scene_sha256", job_scene_sha256(job, opt.out)}, {"status", "pending"}});
  }
  return r;
}

class Pool {
 public:
  Pool(const SweepSpec& spec, const std::vector<Job>& jobs, const PoolOptions& opt)
      : jobs_(jobs), opt_(opt), record_(initial_record(spec, jobs, opt)) {}

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
    record_["status"] = overall_status();
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
      auto& j = record_["jobs"][i];
      j["status"] = "complete";
      j["start"] = to_string(JobStart::kSkip);
      j["wall_seconds"] = recorded_seconds(dir);
    }
    return queue;
  }

  void start(std::size_t i) {  // under the lock
    ++running_;
    record_["jobs"][i]["status"] = "running";
    record_["jobs"][i]["started"] = io::utc_timestamp();
    write_record();
    threads_.emplace_back([this, i] {
      const JobResult r = run_one(jobs_[i]);
      std::lock_guard guard(mutex_);
      finish(i, r);
      cv_.notify_all();
    });
  }

  JobResult run_one(const Job& job) {  // without the lock: this is where the hours go
    const auto t0 = Clock::now();
    const fs::path dir = opt_.out / run_path(job);
    JobStart how = JobStart::kFresh;
    try {
      how = how_to_start(dir, job_scene_sha256(job, opt_.out));
      const auto engine = dem::make_engine(job.engine);
      const auto scene = dem::parse_scene(job.scene_text, (opt_.out / scene_path(job)).string());
      dem::RunOptions ro{dir, opt_.processes, how == JobStart::kResume, how == JobStart::kFresh,
                         opt_.command_line, &stop_, nullptr, dem::consolidation_cache_dir(opt_.out / "consolidated")};
      const auto outcome = dem::run_scene(scene, job.scene_text, *engine, ro);
      return {outcome.status, seconds_since(t0), how};
    } catch (const std::exception& e) {
      return {fmt::format("failed: {}", e.what()), seconds_since(t0), how};
    }
  }

  void finish(std::size_t i, const JobResult& r) {  // under the lock
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

  struct Counts {
    int complete = 0, reused = 0, running = 0, failed = 0, pending = 0;
  };
  Counts counts() const {
    Counts c;
    for (const auto& j : record_["jobs"]) {
      const std::string s = j["status"];
      if (s == "complete") {
        ++c.complete;
        if (j.value("start", "") == "reused") ++c.reused;
      } else if (s == "running") {
        ++c.running;
      } else if (s == "pending" || s.rfind("interrupted", 0) == 0) {
        ++c.pending;  // an interrupted job is still to do
      } else {
        ++c.failed;
      }
    }
    return c;
  }

  // Remaining jobs in waves of `jobs` at once, each wave as long as the mean job run so far.
  std::string eta(const Counts& c) const {
    if (run_seconds_.empty()) return "ETA after the first job";
    double mean = 0.0;
    for (double s : run_seconds_) mean += s / double(run_seconds_.size());
    const double waves = std::ceil(double(c.pending + c.running) / double(opt_.jobs));
    return fmt::format("ETA ~{:.0f} s", waves * mean);
  }

  void report(const std::string& event = "") {
    last_progress_ = Clock::now();
    if (!opt_.progress) return;
    const Counts c = counts();
    const std::string prefix = event.empty() ? "" : event + "; ";
    opt_.progress(fmt::format("{}sweep: {}/{} complete ({} reused), {} running, {} failed, {} to do, {:.0f} s, {}",
                              prefix, c.complete, jobs_.size(), c.reused, c.running, c.failed, c.pending,
                              seconds_since(started_), eta(c)));
  }

  std::string overall_status() const {
    const Counts c = counts();
    if (c.complete == int(jobs_.size())) return "complete";
    if (stop_ && c.pending > 0) return "interrupted";
    return fmt::format("finished: {} of {} failed", c.failed, jobs_.size());
  }

  void write_record() {
    record_["updated"] = io::utc_timestamp();
    io::write_atomically(opt_.out / "sweep.json", record_.dump(2) + "\n");
  }

  const std::vector<Job>& jobs_;
  const PoolOptions& opt_;
  json record_;
  std::mutex mutex_;
  std::condition_variable cv_;
  std::atomic<bool> stop_{false};  // handed to every run_scene: the one way jobs are stopped
  std::vector<std::thread> threads_;
  int running_ = 0, ended_ = 0;
  std::vector<double> run_seconds_;  // complete jobs of this invocation, for the ETA
  Clock::time_point started_ = Clock::now(), last_progress_ = Clock::now();
};

}  // namespace

json run_jobs(const SweepSpec& spec, const std::vector<Job>& jobs, const PoolOptions& opt) {
  fs::create_directories(opt.out);
  return Pool(spec, jobs, opt).run();
}

}  // namespace iwb::campaign
