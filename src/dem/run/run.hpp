#pragma once
// `iwb dem run`: one scene through one engine into a run directory (DEM.md contract):
// manifest.json, timeseries.csv, profiles.csv, vtk/ (+ .pvd), summary.json. Stages are recorded
// in the manifest as they finish; --resume continues from the last finished stage of the same
// scene. An engine failure, lost particles, a servo that does not converge or a short particle
// count ends the run with status "failed: <reason>"; an interrupt with "interrupted at stage X".
#include <atomic>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "dem/engines/engine.hpp"
#include "io/directory_lock.hpp"

namespace iwb::dem {

struct RunOptions {
  std::filesystem::path out;
  int processes = 1;
  bool resume = false;
  bool force = false;
  std::string command_line;
  const std::atomic<bool>* interrupt = nullptr;
  std::function<void(const std::string&)> progress;
  // Where consolidated specimens are kept (dem/run/consolidation_cache.hpp): the run starts from
  // one of its consolidation key when there is one, and keeps the one it consolidates. Empty: none.
  std::filesystem::path consolidation_cache;
};

struct RunOutcome {
  std::string status;  // "complete", "failed: ...", "interrupted at stage ..."
  nlohmann::json manifest;
  bool complete() const { return status == "complete"; }
};

// What every kind of DEM run directory shares (a scene's interface run, a soil cell): the
// manifest `fresh` (or, with --resume, the earlier one of the same scene text) written before and
// after each stage, stages already done skipped. Returns the context and every stage's facts, or
// nothing when a stage failed or was interrupted (out.status and the manifest then say so).
// `sha_key` points at the manifest's hash of scene_text (what --resume must find again).
// The run directory is locked (io/directory_lock.hpp) from before anything is read or written in
// it until the StagedRun is gone: another process working in it is refused (InputError naming it).
// --resume of a run whose manifest says complete does nothing (issue 37: a recomputation
// changed a band stress in its sixth digit): `complete_before` is set, the manifest is the earlier
// one and no file is written; the caller returns.
struct StagedRun {
  StageContext ctx;
  nlohmann::json facts;  // by stage name
  std::optional<io::DirectoryLock> lock;
  bool complete_before = false;
};
// `fresh` makes a new run's manifest (of kind `kind`); it is called only once the output
// directory is accepted (it asks the engine for its version: half a second of MPI start-up that a
// refused directory should not cost).
std::optional<StagedRun> run_stages(const Scene& scene, const std::string& scene_text,
                                    Engine& engine, const RunOptions& options,
                                    const std::string& kind,
                                    const std::function<nlohmann::json()>& fresh, RunOutcome& out,
                                    const std::string& sha_key = "/scene/sha256");

RunOutcome run_scene(const Scene& scene, const std::string& scene_text, Engine& engine,
                     const RunOptions& options);

// Recomputes summary.json of a finished run directory from its contract files and the scene
// copy in its manifest, under the directory's lock; returns the summary.
nlohmann::json resummarize(const std::filesystem::path& run_dir);

}  // namespace iwb::dem
