#pragma once
// What a DEM engine does for the workbench: run a scene's stages in a work directory and turn
// its raw outputs into the run-directory contract (DEM.md). The orchestration around it
// (manifest, resume, failure statuses, summary) is the same for every engine: dem/run/run.hpp.
#include <atomic>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "dem/scene/scene.hpp"
#include "io/csv_table.hpp"

namespace iwb::dem {

struct StageContext {
  const Scene& scene;
  std::filesystem::path run_dir;   // the contract directory
  std::filesystem::path work_dir;  // engine inputs, logs, restarts, raw outputs
  int processes = 1;               // MPI ranks or threads
  const std::atomic<bool>* interrupt = nullptr;
  std::function<void(const std::string&)> progress;  // one human-readable line
};

struct StageResult {
  bool ok = false;
  bool interrupted = false;
  std::string failure;   // why, when !ok
  nlohmann::json facts;  // what the stage measured (particle count, plate position, ...)
};

// The contract's tables, in contract units (kPa, mm).
struct ContractTables {
  io::CsvTable timeseries;
  io::CsvTable profiles;
  nlohmann::json facts;  // engine facts for the manifest (timestep, servo deviation, ...)
};

class Engine {
 public:
  virtual ~Engine() = default;
  virtual std::string name() const = 0;
  virtual std::string version() const = 0;
  virtual std::vector<std::string> stages() const = 0;
  // Numbers the engine derived from the scene (timestep, steps, velocities) for the manifest.
  virtual nlohmann::json numerics(const Scene& scene) const = 0;
  virtual StageResult run_stage(const std::string& stage, const StageContext& ctx,
                                const nlohmann::json& earlier_facts) = 0;
  virtual ContractTables assemble(const StageContext& ctx, const nlohmann::json& facts) = 0;
  // The file a stage leaves in the work directory for the later stages to start from (its
  // restart); empty when none. Its size and hash are recorded when the stage ends and checked
  // before a later stage starts from it (dem/run/run.hpp).
  virtual std::string restart_file(const std::string& stage) const = 0;
  // Everything the consolidation stage of `scene` reads (its rendered engine input and meshes),
  // and nothing only later stages read: its hash, with the engine's name and version, keys a
  // consolidated specimen that runs differing only in the shear stage share
  // (dem/run/consolidation_cache.hpp).
  virtual std::string consolidation_inputs(const Scene& scene) const = 0;
  // What of `scene` this engine cannot model (LIGGGHTS: liquid bridges); empty when it can all.
  virtual std::string unsupported(const Scene& /*scene*/) const { return {}; }
};

// The stage that prepares the specimen (generate, settle, consolidate) in both engines.
inline constexpr const char* kConsolidationStage = "consolidate";

}  // namespace iwb::dem
