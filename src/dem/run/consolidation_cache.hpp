#pragma once
// Consolidate once, shear many (issue 20): runs of one scene that differ only in the shear stage
// (boundary condition, K, inertial number or velocity, distance, cycles, outputs) start from one
// consolidated specimen. It is keyed by the sha256 of the engine's name, its version and
// Engine::consolidation_inputs (the consolidation's rendered input and meshes: grains, specimen,
// walls and plate, consolidation stress and numerics, seed), and kept in
// CACHE/<key>/: the restart with its size and hash record, the stage's log, consolidation.json
// (written last: what it is, where it was consolidated, its facts) and consolidation_inputs.txt
// (what the key hashes). CACHE is $IWB_CONSOLIDATED_DIR if set (`off`: no reuse), else the
// command's: DIR/consolidated of `iwb sweep`, `iwb tradeoff` and `iwb dem crosscheck`, the
// `--consolidated DIR` of `iwb dem run` (none without it).
//
// An entry is used only under its lock (io/directory_lock.hpp), so a second run of the same key
// waits while the first consolidates and then reuses it; its restart is checked against its
// record before it is copied and again after: a stale or corrupt entry is rebuilt, never used.
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "dem/engines/engine.hpp"

namespace iwb::dem {

// Where consolidated specimens are kept: $IWB_CONSOLIDATED_DIR when set (empty for `off`), else
// `fallback` (the command's own).
std::filesystem::path consolidation_cache_dir(const std::filesystem::path& fallback);

// sha256 of what the consolidation of `scene` in `engine` depends on.
std::string consolidation_key(const Engine& engine, const Scene& scene);

// Runs the consolidation stage (kConsolidationStage) of ctx.scene through the cache in
// cache_dir: copies an intact cached specimen into ctx.work_dir, or else runs the stage there
// (`consolidate_here`, which fills `entry` as run_stages does) and stores the specimen. `entry`
// is the stage's manifest entry; it gets "consolidation": {"key", "entry", "reused", and when
// reused "consolidated_in" and "consolidation_wall_seconds"; "rebuilt_because" when a cached one
// was stale or corrupt}.
StageResult consolidate_through_cache(const Engine& engine, const StageContext& ctx,
                                      const std::filesystem::path& cache_dir,
                                      const std::string& command, nlohmann::json& entry,
                                      const std::function<StageResult()>& consolidate_here);

}  // namespace iwb::dem
