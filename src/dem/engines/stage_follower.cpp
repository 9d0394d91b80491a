#include "dem/engines/stage_follower.hpp"

#include <fmt/core.h>

#include <chrono>
#include <fstream>
#include <optional>
#include <sstream>

#include "common/subprocess.hpp"

namespace iwb::dem {

namespace {

std::vector<std::string> words(const std::string& line) {
  std::istringstream is(line);
  std::vector<std::string> w;
  for (std::string x; is >> x;) w.push_back(x);
  return w;
}

struct Follower {
  const StageContext& ctx;
  const ExtraLineReader& extra;
  std::ofstream log;
  StageResult result;
  std::string done_marker;
  bool done = false;
  EngineCost cost;
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  std::optional<std::pair<double, std::chrono::steady_clock::time_point>> first_progress =
      std::nullopt;

  bool line(const std::string& l) {
    log << l << '\n';
    const auto w = words(l);
    if (w.empty()) return true;
    if (l.rfind("ERROR", 0) == 0 || l.find("ERROR on proc") != std::string::npos) {
      result.failure = "engine error: " + l;
      return true;  // the engine aborts by itself; keep reading its last words
    }
    if (extra) extra(w, cost);
    if (w[0] == "IWB_FAIL") {
      result.failure = l.substr(9);
      return false;
    }
    if (w[0] == "IWB_COST" && w.size() >= 5) {
      cost.loop_seconds += std::stod(w[2]);
      cost.particle_steps += std::stod(w[4]);
    }
    if (w[0] == "IWB_PARTICLES" && w.size() >= 4) particles(std::stol(w[1]), std::stol(w[3]));
    if (w[0] == "IWB_APPROACH" && w.size() >= 4 && ctx.progress)
      ctx.progress(
          fmt::format("consolidating: bringing the grains together, window {}, sigma {:.2f} kPa",
                      w[1], std::stod(w[3]) / 1e3));
    if (w[0] == "IWB_WINDOW" && w.size() >= 10 && ctx.progress)
      ctx.progress(
          fmt::format("consolidating: window {}, sigma {:.1f} kPa, {} of {} windows accepted", w[1],
                      std::stod(w[3]) / 1e3, w[9], ctx.scene.consolidation.windows_required));
    if (w[0] == "IWB_SETTLE" && w.size() >= 10 && ctx.progress)
      ctx.progress(fmt::format(
          "settling at the test's contacts: window {}, sigma {:.1f} kPa, {} of {} windows accepted",
          w[1], std::stod(w[3]) / 1e3, w[9], ctx.scene.consolidation.windows_required));
    if (w[0] == "IWB_SHEAR_START" && w.size() >= 5) {
      result.facts["step0"] = std::stol(w[2]);
      result.facts["z0_m"] = std::stod(w[4]);
    }
    if (w[0] == "IWB_PROGRESS" && w.size() >= 3 && ctx.progress)
      progress(std::stod(w[1]), std::stod(w[2]));
    if (w[0] == "IWB_FACT" && w.size() >= 3) result.facts[w[1]] = std::stod(w[2]);
    if (w[0] == "IWB_ROW" && w.size() >= 3) row(w);
    if (w[0] == "IWB_LEVEL" && w.size() >= 4 && ctx.progress)
      level(std::stol(w[1]), std::stol(w[2]), std::stod(w[3]));
    if (w[0] == "IWB_STAGE_DONE" && w.size() >= 2) {
      if (w.size() >= 6 && w[1] == "consolidate") {
        result.facts["zplate_m"] = std::stod(w[3]);
        result.facts["sigma_Pa"] = std::stod(w[5]);
      }
      if (w[1] == done_marker) done = true;
    }
    return true;
  }

  void particles(long got, long want) {
    result.facts["particles"] = got;
    result.facts["particles_requested"] = want;
    if (got < want && result.failure.empty())
      // The region is sized for a loose solid fraction (dem/scene/numerics.cpp) with every grain
      // wholly inside it, so a narrow or short box, whose margins of one grain weigh more, fills it
      // nearly to jamming: seen with the truth halved to 12 x 4 x 10 d50 (639 of 640).
      result.failure = fmt::format(
          "particle count short: {} of {} inserted (random insertion jammed in "
          "its region; fewer specimen.particles, or a wider or longer box)",
          got, want);
  }

  // "IWB_ROW table v1 v2 ...": a row of numbers the stage measured (a soil cell's states), kept
  // in the stage's facts so that the manifest holds them and a resumed run needs no raw file.
  void row(const std::vector<std::string>& w) {
    nlohmann::json r = nlohmann::json::array();
    for (std::size_t i = 2; i < w.size(); ++i) r.push_back(std::stod(w[i]));
    result.facts["rows"][w[1]].push_back(r);
  }

  // A soil cell's stress level (oedometer): level i of n, its target stress.
  void level(long i, long n, double sigma_Pa) {
    const double f = double(i - 1) / double(n);
    const double t =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ctx.progress(fmt::format("oedometer: level {} of {}, sigma_v -> {:.1f} kPa, ETA {:.0f} s", i, n,
                             sigma_Pa / 1e3, f > 0.01 ? t * (1 - f) / f : 0.0));
  }

  // The ETA from the rate since the first progress line: a resumed stage starts part-way.
  void progress(double u, double total) {
    const double f = u / total;
    const auto now = std::chrono::steady_clock::now();
    if (!first_progress) first_progress = std::make_pair(f, now);
    const double advanced = f - first_progress->first;
    const double t = std::chrono::duration<double>(now - first_progress->second).count();
    ctx.progress(fmt::format("shearing: u_x {:.2f} of {:.2f} mm ({:.0f} %), ETA {:.0f} s", u * 1e3,
                             total * 1e3, 100 * f, advanced > 0.01 ? t * (1 - f) / advanced : 0.0));
  }
};

}  // namespace

StageResult run_followed_stage(const std::vector<std::string>& command, const std::string& stage,
                               const StageContext& ctx, const ExtraLineReader& extra) {
  Follower f{ctx, extra, std::ofstream(ctx.work_dir / (stage + ".out")), {}, stage, false, {}};
  const ProcessResult p = run_process(
      command, ctx.work_dir,
      [&f](const std::string& l) {
        const bool go_on = f.line(l);
        return go_on && f.result.failure.rfind("particle count short", 0) != 0;
      },
      ctx.interrupt);
  StageResult r = f.result;
  r.facts["engine_loop_seconds"] = f.cost.loop_seconds;
  r.facts["particle_steps"] = f.cost.particle_steps;
  if (p.stopped && r.failure.empty()) {
    r.interrupted = true;
  } else if (r.failure.empty() && (p.exit_code != 0 || !f.done)) {
    r.failure = p.exit_code != 0
                    ? fmt::format("engine exited with code {}{}", p.exit_code,
                                  p.signal_name.empty() ? "" : " (" + p.signal_name + ")")
                    : fmt::format("engine stopped before the end of stage {}", stage);
  }
  r.ok = r.failure.empty() && !r.interrupted;
  if (!r.ok && !r.interrupted)
    r.failure += fmt::format(" [log: {}]", (ctx.work_dir / (stage + ".out")).string());
  return r;
}

}  // namespace iwb::dem
