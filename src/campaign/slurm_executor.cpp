#include "campaign/slurm_executor.hpp"

#include <fmt/core.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>
#include <thread>

#include "campaign/job_start.hpp"
#include "campaign/sweep_record.hpp"
#include "common/errors.hpp"
#include "common/subprocess.hpp"
#include "io/json_file.hpp"
#include "io/run_directory.hpp"

namespace iwb::campaign {

namespace fs = std::filesystem;
using nlohmann::json;
using Clock = std::chrono::steady_clock;

namespace {

struct Captured {
  int exit_code = -1;
  std::string text;
};

Captured capture(const std::vector<std::string>& argv, const fs::path& cwd) {
  Captured c;
  c.exit_code = run_process(argv, cwd, [&c](const std::string& line) {
                  c.text += line + "\n";
                  return true;
                }).exit_code;
  return c;
}

bool on_path(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::istringstream dirs(path ? path : "");
  for (std::string dir; std::getline(dirs, dir, ':');)
    if (!dir.empty() && ::access((fs::path(dir) / program).c_str(), X_OK) == 0) return true;
  return false;
}

std::string trimmed(std::string s) {
  while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
  return s;
}

// Array task `index` of Slurm job `job_id`, as squeue -r names it.
struct TaskKey {
  std::string job_id;
  std::size_t index = 0;
  bool operator<(const TaskKey& o) const {
    return std::tie(job_id, index) < std::tie(o.job_id, o.index);
  }
};

// The user's queued and running array tasks with their states (PENDING, RUNNING, COMPLETING, ...),
// on `cluster` when sbatch named one (a multi-cluster setup). A task that has ended is not listed
// (squeue shows only live jobs by default). A busy controller is asked again before giving up.
std::map<TaskKey, std::string> live_tasks(const std::string& cluster) {
  std::vector<std::string> argv = {"squeue", "--noheader", "--array", "--me", "--format=%F %K %T"};
  if (!cluster.empty()) argv.push_back("--clusters=" + cluster);
  Captured q;
  for (int attempt = 0; attempt < 5; ++attempt) {
    q = capture(argv, ".");
    if (q.exit_code == 0) break;
    std::this_thread::sleep_for(std::chrono::seconds(2 << attempt));
  }
  if (q.exit_code != 0)
    throw std::runtime_error(
        fmt::format("squeue failed five times (exit {}): {}; the tasks stay in Slurm, "
                    "the same command again watches them",
                    q.exit_code, trimmed(q.text)));
  std::map<TaskKey, std::string> out;
  std::istringstream lines(q.text);
  for (std::string id, index, state; lines >> id >> index >> state;) {
    if (index.find_first_not_of("0123456789") != std::string::npos) continue;  // not an array task
    out[{id, std::stoul(index)}] = state;
  }
  return out;
}

std::string index_list(const std::vector<std::size_t>& indices) {
  std::string s;
  for (auto i : indices) s += (s.empty() ? "" : ",") + std::to_string(i);
  return s;
}

}  // namespace

void check_slurm_submission(const std::vector<Job>& jobs, const SlurmOptions& options) {
  check_slurm_options(options);
  for (const char* program : {"sbatch", "squeue"})
    if (!on_path(program))
      throw InputError(
          fmt::format("--executor slurm: no {} on this machine's PATH (Slurm's client commands are "
                      "needed where iwb runs); nothing was submitted",
                      program));
  // the cluster's own judgement of the script (partition, account, time limit), nothing queued
  const fs::path dir = fs::temp_directory_path() / fmt::format("iwb-slurm-test-{}", ::getpid());
  fs::create_directories(dir);
  io::write_atomically(dir / "sweep.slurm", slurm_script(jobs, options));
  const auto test = capture({"sbatch", "--test-only", "sweep.slurm"}, dir);
  fs::remove_all(dir);
  if (test.exit_code != 0)
    throw InputError(fmt::format(
        "--executor slurm: sbatch --test-only refuses the campaign's script: {}; nothing "
        "was submitted",
        trimmed(test.text)));
}

namespace {

class SlurmWatch {
 public:
  SlurmWatch(const SweepSpec& spec, const std::vector<Job>& jobs, const SlurmExecutorOptions& opt)
      : jobs_(jobs),
        opt_(opt),
        record_(initial_record(spec, jobs, opt.out, opt.command_line, executor_record(opt))) {}

  json run() {
    const auto previous = previous_tasks();
    const auto live = live_tasks(cluster_);
    std::vector<std::size_t> to_submit;
    for (std::size_t i = 0; i < jobs_.size(); ++i) {
      if (how_to_start(run_dir(i), record_["jobs"][i]["scene_sha256"]) == JobStart::kSkip) {
        mark_reused(record_["jobs"][i], run_dir(i));
        continue;
      }
      const auto p = previous.find(i);
      if (p != previous.end() && live.count({p->second, i})) {
        track(i, p->second, "adopted");  // still queued or running from an earlier watch
        attempts_[i] = 1;                // its one resubmission is still to come
        continue;
      }
      to_submit.push_back(i);
    }
    watch(to_submit);
    return record_;
  }

 private:
  static json executor_record(const SlurmExecutorOptions& o) {
    return {{"executor", "slurm"},
            {"processes_per_job", o.slurm.processes},
            {"slurm",
             {{"time", o.slurm.time},
              {"partition", o.slurm.partition},
              {"account", o.slurm.account},
              {"mem", o.slurm.memory},
              {"prologue", o.slurm.prologue},
              {"submissions", json::array()}}}};
  }

  fs::path run_dir(std::size_t i) const { return opt_.out / run_path(jobs_[i]); }

  // The Slurm job of each job's last task, from the sweep.json of an earlier watch of this campaign
  // (whose submissions the record keeps).
  std::map<std::size_t, std::string> previous_tasks() {
    std::map<std::size_t, std::string> out;
    if (!fs::exists(opt_.out / "sweep.json")) return out;
    const json old = io::read_json_file(opt_.out / "sweep.json");
    if (old.value("executor", "") != "slurm") return out;
    record_["slurm"]["submissions"] = old["slurm"].value("submissions", json::array());
    cluster_ = old["slurm"].value("cluster", "");
    for (std::size_t i = 0; i < jobs_.size() && i < old["jobs"].size(); ++i) {
      const auto& j = old["jobs"][i];
      // a task of an edited sweep runs another scene: not adopted (the job is submitted again)
      if (j.value("name", "") == jobs_[i].name && j.contains("slurm_job") &&
          j.value("scene_sha256", "") == record_["jobs"][i]["scene_sha256"])
        out[i] = j["slurm_job"];
    }
    return out;
  }

  void track(std::size_t i, const std::string& job_id, const std::string& start) {
    tracked_[i] = job_id;
    auto& j = record_["jobs"][i];
    j["slurm_job"] = job_id;
    j["log"] = task_log(i, job_id);
    j["start"] = start;
    j["status"] = "queued";
  }

  // --resume for a run of the same scene that stopped part-way, --force for another scene's run.
  std::string start_flag(std::size_t i) const {
    switch (how_to_start(run_dir(i), record_["jobs"][i]["scene_sha256"])) {
      case JobStart::kResume:
        return "--resume";
      case JobStart::kFresh:
        return fs::exists(run_dir(i)) ? "--force" : "";
      case JobStart::kSkip:
        break;
    }
    return "";
  }

  void submit(const std::vector<std::size_t>& indices) {
    StartFlags flags(jobs_.size());
    for (auto i : indices) flags[i] = start_flag(i);
    fs::create_directories(opt_.out / "logs");  // Slurm does not create the --output folder
    io::write_atomically(opt_.out / "sweep.slurm", slurm_script(jobs_, opt_.slurm, flags));
    const auto s = capture(
        {"sbatch", "--parsable", "--array=" + index_list(indices), "sweep.slurm"}, opt_.out);
    if (s.exit_code != 0)
      throw std::runtime_error(
          fmt::format("sbatch failed (exit {}): {}", s.exit_code, trimmed(s.text)));
    const std::string out = trimmed(s.text),
                      id = out.substr(0, out.find(';'));  // "ID" or "ID;cluster"
    if (out.find(';') != std::string::npos) cluster_ = out.substr(out.find(';') + 1);
    record_["slurm"]["cluster"] = cluster_;
    record_["slurm"]["submissions"].push_back(
        {{"job", id}, {"array", index_list(indices)}, {"at", io::utc_timestamp()}});
    for (auto i : indices) {
      ++attempts_[i];
      track(i, id, flags[i] == "--resume" ? "resumed" : "fresh");
    }
    write_record(record_, opt_.out);  // the job IDs are kept before anything else can fail
    report(fmt::format("submitted Slurm job {} (array {})", id, index_list(indices)));
  }

  // A task that left the queue: its run directory says how it ended.
  void settle(std::size_t i, std::vector<std::size_t>& resubmit) {
    tracked_.erase(i);
    auto& j = record_["jobs"][i];
    const fs::path manifest = run_dir(i) / "manifest.json";
    std::string status = fs::exists(manifest)
                             ? io::read_json_file(manifest).value("status", "unknown")
                             : "no run directory written";
    // complete, and of this job's scene: not a stale run the task never got to replace
    if (how_to_start(run_dir(i), j["scene_sha256"]) == JobStart::kSkip) {
      j["status"] = "complete";
      j["wall_seconds"] = recorded_seconds(run_dir(i));
      j["finished"] = io::utc_timestamp();
      run_seconds_.push_back(j["wall_seconds"]);
      report(fmt::format("{}: complete", jobs_[i].name));
      return;
    }
    if (status == "complete")
      status = "complete, but of another scene (the task did not replace it)";
    if (attempts_[i] <= opt_.resubmits) {
      resubmit.push_back(i);
      report(fmt::format("{}: its task ended with the run '{}' (log {}); resubmitting it",
                         jobs_[i].name, status, j.value("log", "")));
      return;
    }
    j["status"] = status.rfind("failed", 0) == 0 ? status : "failed: " + status;
    j["finished"] = io::utc_timestamp();
    report(fmt::format("{}: {} (log {})", jobs_[i].name, j["status"].get<std::string>(),
                       j.value("log", "")));
  }

  void watch(std::vector<std::size_t> to_submit) {
    bool stopped = false;
    for (;;) {
      if (opt_.interrupt && opt_.interrupt->load()) {
        stopped = true;
        for (auto i : to_submit)  // settled, not yet resubmitted: to do when run again
          record_["jobs"][i]["status"] = "interrupted before its resubmission";
        break;
      }
      if (!to_submit.empty()) submit(to_submit);
      to_submit.clear();
      const auto live = live_tasks(cluster_);
      for (auto it = tracked_.begin(); it != tracked_.end();) {
        const auto [i, id] = *it++;  // settle() erases i
        const auto state = live.find({id, i});
        if (state == live.end())
          settle(i, to_submit);
        else
          record_["jobs"][i]["status"] = state->second == "PENDING" ? "queued" : "running";
      }
      write_record(record_, opt_.out);
      if (tracked_.empty() && to_submit.empty()) break;
      if (seconds_since(last_progress_) > kProgressEverySeconds) report();
      sleep_interruptibly();
    }
    record_["status"] = overall_status(record_, stopped);
    if (stopped && !tracked_.empty())
      record_["note"] =
          "the watch was stopped; the tasks still queued or running stay in Slurm (their job IDs "
          "are in "
          "jobs[].slurm_job); the same command again watches them, scancel stops them";
    record_["finished"] = io::utc_timestamp();
    write_record(record_, opt_.out);
    report();
  }

  void sleep_interruptibly() const {
    const auto until = Clock::now() + std::chrono::duration<double>(opt_.poll_seconds);
    while (Clock::now() < until && !(opt_.interrupt && opt_.interrupt->load()))
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }

  static double seconds_since(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
  }

  // The jobs left, at the mean time of those complete so far and as many at once as run now.
  std::string eta(const JobCounts& c) const {
    if (run_seconds_.empty()) return "ETA after the first job";
    double mean = 0.0;
    for (double s : run_seconds_) mean += s / double(run_seconds_.size());
    const int at_once = std::max(1, int(tracked_.size()));
    return fmt::format("ETA ~{:.0f} s", std::ceil(double(c.pending + c.running) / at_once) * mean);
  }

  void report(const std::string& event = "") {
    last_progress_ = Clock::now();
    if (!opt_.progress) return;
    const JobCounts c = count_jobs(record_);
    opt_.progress(fmt::format(
        "{}slurm: {}/{} complete ({} reused), {} queued or running, {} failed, {} to submit, "
        "{:.0f} s, {}",
        event.empty() ? "" : event + "; ", c.complete, jobs_.size(), c.reused, c.running, c.failed,
        c.pending, seconds_since(started_), eta(c)));
  }

  const std::vector<Job>& jobs_;
  const SlurmExecutorOptions& opt_;
  json record_;
  std::map<std::size_t, std::string> tracked_;  // job index -> Slurm job of its live task
  std::map<std::size_t, int> attempts_;         // submissions per job in this watch
  std::string cluster_;  // the cluster sbatch named (multi-cluster setups), else empty
  std::vector<double> run_seconds_;
  Clock::time_point started_ = Clock::now(), last_progress_ = Clock::now();
};

}  // namespace

json run_jobs_on_slurm(const SweepSpec& spec, const std::vector<Job>& jobs,
                       const SlurmExecutorOptions& opt) {
  fs::create_directories(opt.out);
  return SlurmWatch(spec, jobs, opt).run();
}

}  // namespace iwb::campaign
