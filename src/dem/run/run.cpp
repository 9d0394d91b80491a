#include "dem/run/run.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>

#include "common/errors.hpp"
#include "dem/analysis/plausibility.hpp"
#include "dem/analysis/run_fields.hpp"
#include "dem/analysis/summary.hpp"
#include "dem/run/consolidation_cache.hpp"
#include "dem/scene/scene_roughness.hpp"
#include "io/checksum_record.hpp"
#include "io/json_file.hpp"
#include "io/run_directory.hpp"

namespace iwb::dem {

namespace fs = std::filesystem;

namespace {

nlohmann::json fresh_manifest(const Scene& scene, const std::string& text, Engine& engine,
                              const RunOptions& opt) {
  return {
      {"kind", "dem-run"},
      {"workbench", {{"name", "iwb"}, {"version", IWB_VERSION}}},
      {"engine",
       {{"name", engine.name()}, {"version", engine.version()}, {"processes", opt.processes}}},
      {"command_line", opt.command_line},
      {"scene",
       {{"source", scene.source},
        {"sha256", scene_sha256(scene, text)},
        {"text", text},
        {"resolved", scene.resolved}}},
      {"seed", scene.seed},
      {"numerics", engine.numerics(scene)},
      {"R_n", scene.wall.normalized_roughness(scene.particles.d50_m)},
      {"roughness", scene_roughness(scene)},
      {"stiffness_level", scene.stiffness_level()},
      {"inertial_number", scene.shear.inertial_number},
      {"conventions",
       {{"signs",
         "compression positive; u_n > 0 is dilation; tau has the sign of the wall displacement"},
        {"units", "kPa, mm, s in the contract files; SI inside the engine"}}},
      {"warnings", scene.warnings},
      {"stages", nlohmann::json::object()},
      {"files",
       nlohmann::json::array()},  // set when they are written: never a file that is not there
      {"started", io::utc_timestamp()},
      {"status", "running"}};
}

// The manifest of an earlier run of the same scene, for --resume; `key` points at the hash of the
// scene text the engine ran.
nlohmann::json earlier_manifest(const fs::path& dir, const std::string& sha,
                                const nlohmann::json::json_pointer& key) {
  auto m = nlohmann::json::parse(io::read_file(dir / "manifest.json"));
  if (m.value(key, std::string()) != sha)
    throw InputError(
        fmt::format("{}: the earlier run used a different scene (sha256 {}); "
                    "--resume needs the same scene file",
                    dir.string(), m.value(key, std::string("?"))));
  return m;
}

bool is_done(const nlohmann::json& m, const std::string& stage) {
  return m["stages"].contains(stage) && m["stages"][stage].value("status", "") == "done";
}

// Where a run starts: at the first stage not done, or at an earlier one whose restart, which the
// later stages start from, is missing or does not match the size and hash recorded with it: that
// stage is run again, its restart never used (finding 8: a truncated consolidation restart made
// --resume fail while the stage stayed "done").
struct Start {
  std::size_t stage = 0;
  std::string rebuilt_because;  // empty: nothing is run again
};

Start where_to_start(const nlohmann::json& m, const std::vector<std::string>& stages,
                     const Engine& engine, const fs::path& work) {
  Start s;
  while (s.stage < stages.size() && is_done(m, stages[s.stage])) ++s.stage;
  if (s.stage == stages.size()) return s;  // nothing left that would start from a restart
  for (std::size_t i = 0; i < s.stage; ++i) {
    const std::string restart = engine.restart_file(stages[i]);
    if (restart.empty()) continue;
    if (const auto why = io::checksum_problem(work / restart)) return {i, *why};
  }
  return s;
}

// Runs one stage into its manifest entry (status, wall time, facts); the restart it leaves gets
// its size and hash recorded next to it, and in the entry. A stage that says it is done without
// leaving its restart has failed.
StageResult run_recorded_stage(Engine& engine, const std::string& stage, const StageContext& ctx,
                               const nlohmann::json& facts, nlohmann::json& entry) {
  const auto t0 = std::chrono::steady_clock::now();
  StageResult r = engine.run_stage(stage, ctx, facts);
  const std::string restart = engine.restart_file(stage);
  nlohmann::json record;
  if (r.ok && !restart.empty()) {
    if (fs::exists(ctx.work_dir / restart)) {
      record = io::write_checksum_record(ctx.work_dir / restart);
    } else {
      r.ok = false;
      r.failure = fmt::format("the engine ended the stage without writing {}",
                              (ctx.work_dir / restart).string());
    }
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  entry = {{"status", r.ok ? "done" : (r.interrupted ? "interrupted" : "failed")},
           {"wall_seconds", seconds},
           {"facts", r.facts}};
  if (!record.is_null()) entry["restart"] = record;
  return r;
}

// The fields of the snapshots (run_fields.hpp) once the run is complete. They are
// a view of the run, not part of it: a failure is a warning, and `iwb dem fields` can redo them.
void coarse_grain_fields(const RunOptions& opt, nlohmann::json& m) {
  try {
    coarse_grain_run(opt.out, {std::nullopt, false, opt.progress});
    m["files"].push_back("fields/fields.pvd");
  } catch (const std::exception& e) {
    m["warnings"].push_back(fmt::format("coarse-graining failed ({}); `iwb dem fields {}` retries",
                                        e.what(), opt.out.string()));
  }
}

// --force removed the earlier run's files and kept what the workbench did not write: said once.
void report_kept(const std::vector<std::string>& kept, const RunOptions& opt) {
  if (!kept.empty() && opt.progress)
    opt.progress(fmt::format("{}: kept {} file(s) the workbench did not write (first: {})",
                             opt.out.string(), kept.size(), kept.front()));
}

}  // namespace

std::optional<StagedRun> run_stages(const Scene& scene, const std::string& text, Engine& engine,
                                    const RunOptions& opt, const std::string& kind,
                                    const std::function<nlohmann::json()>& fresh, RunOutcome& out,
                                    const std::string& sha_key) {
  const io::OutputKind run_kind{kind};
  auto& m = out.manifest;
  const std::string sha = scene_sha256(scene, text);
  if (opt.resume &&
      !fs::exists(opt.out / "manifest.json"))  // refused before the lock creates anything
    throw InputError(fmt::format("{}: nothing to resume (no manifest.json)", opt.out.string()));
  if (opt.resume)  // before the lock touches it
    io::require_output_directory(opt.out, run_kind, false);
  else
    io::require_new_run_directory(opt.out, run_kind, opt.force);
  auto lock = io::DirectoryLock::take(opt.out, opt.command_line);
  if (lock.stale() && opt.progress) opt.progress(lock.stale_message());
  if (opt.resume) {
    m = earlier_manifest(opt.out, sha, nlohmann::json::json_pointer(sha_key));
    io::claim_output_directory(opt.out, run_kind, false);
    if (m.value("status", "") == "complete") {
      out.status = "complete";
      return StagedRun{StageContext{scene, opt.out, opt.out / engine.name(), opt.processes,
                                    opt.interrupt, opt.progress},
                       nlohmann::json::object(), std::move(lock), true};
    }
    m["status"] = "running";
    m["resumed"].push_back(io::utc_timestamp());
  } else {
    report_kept(io::prepare_run_directory(opt.out, run_kind, opt.force), opt);
    m = fresh();
  }
  if (lock.stale()) m["stale_lock_taken_over"] = lock.stale()->describe();
  const fs::path work = opt.out / engine.name();
  fs::create_directories(work);
  fs::create_directories(opt.out / "vtk");
  fs::create_directories(work / "dumps");  // the engines' raw snapshots (snapshots.hpp)
  io::write_manifest(opt.out, m);

  StagedRun run{StageContext{scene, opt.out, work, opt.processes, opt.interrupt, opt.progress},
                nlohmann::json::object(), std::move(lock)};
  auto& facts = run.facts;
  for (const auto& [name, stage] : m["stages"].items())
    facts[name] = stage.value("facts", nlohmann::json::object());
  const std::vector<std::string> stages = engine.stages();
  const Start start = where_to_start(m, stages, engine, work);
  if (!start.rebuilt_because.empty() && opt.progress)
    opt.progress(
        fmt::format("{}: stage {} is run again", start.rebuilt_because, stages[start.stage]));
  for (std::size_t i = start.stage; i < stages.size(); ++i) {
    const std::string& stage = stages[i];
    nlohmann::json& entry = m["stages"][stage];
    const auto here = [&] { return run_recorded_stage(engine, stage, run.ctx, facts, entry); };
    const StageResult r = opt.consolidation_cache.empty() || stage != kConsolidationStage
                              ? here()
                              : consolidate_through_cache(engine, run.ctx, opt.consolidation_cache,
                                                          opt.command_line, entry, here);
    if (i == start.stage && !start.rebuilt_because.empty())
      m["stages"][stage]["rebuilt_because"] = start.rebuilt_because;
    facts[stage] = r.facts;
    if (!r.ok) {
      out.status = r.interrupted ? fmt::format("interrupted at stage {}", stage)
                                 : fmt::format("failed: {} (stage {})", r.failure, stage);
      m["status"] = out.status;
      m["finished"] = io::utc_timestamp();
      io::write_manifest(opt.out, m);
      return std::nullopt;
    }
    io::write_manifest(opt.out, m);  // a finished stage is never lost
  }
  return run;
}

RunOutcome run_scene(const Scene& scene, const std::string& text, Engine& engine,
                     const RunOptions& opt) {
  if (const auto why = engine.unsupported(scene); !why.empty())
    throw InputError(fmt::format("{}: {} (engine {})", scene.source, why, engine.name()));
  RunOutcome out;
  const auto run = run_stages(
      scene, text, engine, opt, "dem-run", [&] { return fresh_manifest(scene, text, engine, opt); },
      out);
  if (!run || run->complete_before) return out;
  auto& m = out.manifest;
  const auto& ctx = run->ctx;
  const auto& facts = run->facts;
  const ContractTables tables = engine.assemble(ctx, facts);
  io::write_atomically(opt.out / "timeseries.csv", tables.timeseries.to_csv());
  io::write_atomically(opt.out / "profiles.csv", tables.profiles.to_csv());
  // From the files as written (10 digits), as `iwb dem summary` recomputes it: the same bytes,
  // where the tables in memory gave numbers apart in their ninth digit (issue 37)
  const Summary summary = summarize(scene, io::read_csv_table(opt.out / "timeseries.csv"),
                                    io::read_csv_table(opt.out / "profiles.csv"));
  io::write_atomically(opt.out / "summary.json", to_json(summary).dump(2) + "\n");
  m["files"] = {"timeseries.csv",    "profiles.csv",     "summary.json",
                "vtk/particles.pvd", "vtk/contacts.pvd", "vtk/walls.pvd"};
  m["engine_facts"] = tables.facts;
  m["particle_count"] = facts.value("/consolidate/particles"_json_pointer, 0);
  // complete only if the run did what the scene asked; the files stay for a look at why not
  const auto checks = plausibility_checks(asked_by(scene), tables.timeseries);
  m["plausibility"] = to_json(checks);
  for (const auto& w : plausibility_warnings(checks))  // once, though --resume assembles again
    if (std::find(m["warnings"].begin(), m["warnings"].end(), w) == m["warnings"].end())
      m["warnings"].push_back(w);
  m["finished"] = io::utc_timestamp();
  const auto failure = failure_reason(checks);
  out.status = failure ? "failed: implausible: " + *failure : "complete";
  m["status"] = out.status;
  if (out.complete() && scene.coarse_graining.enabled) coarse_grain_fields(opt, m);
  io::write_manifest(opt.out, m);
  return out;
}

nlohmann::json resummarize(const fs::path& dir) {
  const fs::path manifest = dir / "manifest.json", timeseries = dir / "timeseries.csv";
  if (!fs::exists(manifest))  // refused before the lock creates anything
    throw InputError(fmt::format("{}: not a run directory (no manifest.json)", dir.string()));
  const auto lock = io::DirectoryLock::take(dir, "iwb dem summary");
  const auto m = io::read_json_file(manifest);
  const auto status = io::json_field<std::string>(m, "/status", manifest);
  if (status != "complete")
    throw InputError(fmt::format("{}: run status is '{}'; only complete runs are summarised",
                                 manifest.string(), status));
  const Scene scene = parse_scene(io::json_field<std::string>(m, "/scene/text", manifest),
                                  io::json_field<std::string>(m, "/scene/source", manifest));
  const auto ts = io::read_csv_table(timeseries);
  for (const char* column : {"u_x_mm", "u_n_mm", "sigma_n_kPa", "tau_kPa"})
    if (ts.column(column) < 0)
      throw InputError(fmt::format("{}: no column '{}'", timeseries.string(), column));
  // never a worse summary over a good one: files that no longer show what the scene asked are
  // refused
  if (const auto why = failure_reason(plausibility_checks(asked_by(scene), ts)))
    throw InputError(fmt::format("{}: {}; summary.json left as it was", timeseries.string(), *why));
  auto summary = to_json(summarize(scene, ts, io::read_csv_table(dir / "profiles.csv")));
  const fs::path earlier =
      dir / "summary.json";  // the coarse-grained checks are not derived here: kept
  if (fs::exists(earlier)) {
    const auto before = io::read_json_file(earlier);
    if (before.contains("coarse_graining")) summary["coarse_graining"] = before["coarse_graining"];
  }
  io::write_atomically(earlier, summary.dump(2) + "\n");
  return summary;
}

}  // namespace iwb::dem
