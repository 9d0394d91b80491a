#include "validation/validate.hpp"

#include <fmt/core.h>

#include "common/errors.hpp"
#include "comparison/compare/compare.hpp"
#include "comparison/presentation/report.hpp"
#include "dem/engines/engines.hpp"
#include "dem/run/run.hpp"
#include "dem/scene/scene_content.hpp"
#include "io/run_directory.hpp"
#include "validation/parameter_choice.hpp"

namespace iwb::validation {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// The scene text and its name: an embedded scene by name, or a file.
std::pair<std::string, std::string> scene_source(const std::string& scene) {
  const auto& embedded = dem::embedded_scenes();
  if (const auto it = embedded.find(scene + ".toml"); it != embedded.end())
    return {it->second, "<embedded:" + scene + ">"};
  if (fs::is_regular_file(scene)) return {io::read_file(scene), scene};
  std::string names;
  for (const auto& [n, t] : embedded)
    names += (names.empty() ? "" : ", ") + n.substr(0, n.size() - 5);
  throw InputError(
      fmt::format("--scene {}: neither an embedded scene ({}) nor a file", scene, names));
}

enum class DemStart {
  kReuse,   // a complete run of the same scene content: nothing to run
  kResume,  // a stopped run of the same scene text: its finished stages are kept
  kFresh,   // nothing there, or --force
};

struct DemRun {
  std::string engine;
  fs::path dir;
  DemStart start;
  json manifest;  // the earlier run's, when reused
};

// How the run in `dir` starts, decided before any engine starts. A run of another scene or
// engine is refused unless --force, naming what differs.
DemRun plan_dem_run(const std::string& engine, const fs::path& dir, const std::string& text,
                    const std::string& source, bool force) {
  DemRun run{engine, dir, DemStart::kFresh, json()};
  const fs::path file = dir / "manifest.json";
  if (force || !fs::exists(file)) return run;
  const auto refuse = [&](const std::string& why) {
    return InputError(
        fmt::format("--out: {} holds a DEM run of {}; pass --force to replace it, or another --out",
                    dir.string(), why));
  };
  try {
    run.manifest = json::parse(io::read_file(file));
  } catch (const json::exception& e) {
    throw refuse(fmt::format("which {} cannot be read ({})", file.string(), e.what()));
  }
  const std::string ran_engine = run.manifest.value("/engine/name"_json_pointer, std::string("?"));
  if (ran_engine != engine) throw refuse(fmt::format("engine {}, not {}", ran_engine, engine));
  const std::string ran_text = run.manifest.value("/scene/text"_json_pointer, std::string());
  const auto diff =
      dem::content_differences(dem::scene_content(text, source),
                               dem::scene_content(ran_text, file.string() + " /scene/text"));
  if (!diff.empty()) throw refuse(fmt::format("another scene ({})", dem::differences_text(diff)));
  if (run.manifest.value("status", "") == "complete")
    run.start = DemStart::kReuse;
  else if (ran_text == text)
    run.start = DemStart::kResume;
  else
    throw refuse(
        fmt::format("the same scene, stopped ({}), from another scene text: it cannot resume",
                    run.manifest.value("status", "?")));
  return run;
}

// What validate works from, resolved and checked before any engine starts.
struct Inputs {
  std::string text, source;
  dem::Scene scene;
  std::vector<io::ParameterSet> sets;
  std::string sets_origin;  // "built into iwb" or the --params-dir
  std::vector<DemRun> runs;
};

Inputs resolve_inputs(const ValidateOptions& opt) {
  if (opt.engines.empty()) throw InputError("--engines: name at least one engine (liggghts, yade)");
  for (const auto& e : opt.engines) dem::make_engine(e);
  Inputs in;
  std::tie(in.text, in.source) = scene_source(opt.scene);
  in.scene = dem::parse_scene(in.text, in.source);
  in.sets = io::parameter_sets(opt.params_dir);
  in.sets_origin =
      opt.params_dir.empty() ? "built into iwb" : "--params-dir " + opt.params_dir.string();
  std::string why;
  if (calibrated_parameters(in.sets, in.scene, why) == nullptr)
    require_matchable(in.sets, in.sets_origin);
  for (const auto& e : opt.engines)
    in.runs.push_back(
        plan_dem_run(e, opt.out / fmt::format("dem-{}", e), in.text, in.source, opt.force));
  return in;
}

// Runs (or resumes) the scene in one engine; false (and says why) if it did not complete.
bool run_dem(const Inputs& in, const DemRun& run, const ValidateOptions& opt,
             const std::string& step) {
  if (run.start == DemStart::kReuse) {
    opt.step(fmt::format(
        "{} DEM run of {} in {}: reused the complete run in {} (finished {}, {} processes); the "
        "engine is not started (--force runs it again)",
        step, in.source, run.engine, run.dir.string(), run.manifest.value("finished", "?"),
        run.manifest.value("/engine/processes"_json_pointer, 0)));
    return true;
  }
  const bool resume = run.start == DemStart::kResume;
  opt.step(fmt::format("{} DEM run of {} in {} ({} processes{}) -> {}", step, in.source, run.engine,
                       opt.processes, resume ? ", resuming the stopped run there" : "",
                       run.dir.string()));
  const auto engine = dem::make_engine(run.engine);
  const auto outcome = dem::run_scene(
      in.scene, in.text, *engine,
      {run.dir, opt.processes, resume, opt.force, opt.command_line, nullptr, opt.engine_line, {}});
  if (!outcome.complete())
    opt.step(fmt::format("the {} run did not complete: {}", run.engine, outcome.status));
  return outcome.complete();
}

// The parameter file for the replays, chosen on the first engine's run so that every engine is
// compared through the same continuum model; an embedded set is written into OUT/parameters/.
fs::path replay_parameters(const Inputs& in, const fs::path& dem_dir, const fs::path& out,
                           std::string& why) {
  const auto summary = json::parse(io::read_file(dem_dir / "summary.json"));
  const auto& set =
      parameters_for(in.sets, in.scene, summary["residual_friction"].get<double>(), why);
  why += ", " + in.sets_origin;
  return io::parameter_set_file(set, out / "parameters");
}

}  // namespace

ValidateOutcome run_validate(const ValidateOptions& opt) {
  const Inputs in = resolve_inputs(opt);  // refused before anything runs or is written
  for (const auto& w : in.scene.warnings) opt.warning(w);
  // its DEM runs are claimed apart (--force replaces them); the replays and report are redone
  io::claim_output_directory(opt.out, {"validate", "report.html"}, false);
  const std::size_t steps = 2 * in.runs.size() + 1;
  std::size_t step = 0;
  std::vector<fs::path> compares;
  fs::path params;
  std::string why;
  for (const auto& run : in.runs) {
    if (!run_dem(in, run, opt, fmt::format("{}/{}", ++step, steps))) return {};
    if (params.empty()) params = replay_parameters(in, run.dir, opt.out, why);
    opt.step(fmt::format("{}/{} replay of the {} run through hvwe with {} ({})", ++step, steps,
                         run.engine, params.string(), why));
    const fs::path out =
        opt.out /
        (in.runs.size() == 1 ? "compare-hvwe" : fmt::format("compare-hvwe-{}", run.engine));
    // The replay is redone on every call (seconds), replacing the last one: it follows the DEM
    // run beside it and the parameters chosen now.
    comparison::CompareOptions copt;
    copt.dem_dir = run.dir, copt.params = params.string(), copt.out = out, copt.force = true;
    copt.command_line = opt.command_line + " [parameters: " + why + "]";
    comparison::run_comparison(copt);
    compares.push_back(out);
  }
  const fs::path html = opt.out / "report.html";
  opt.step(fmt::format("{}/{} report", ++step, steps));
  comparison::write_report(compares, html);
  return {true, html};
}

}  // namespace iwb::validation
