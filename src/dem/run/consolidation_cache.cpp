#include "dem/run/consolidation_cache.hpp"

#include <fmt/core.h>

#include <chrono>
#include <cstdlib>

#include "io/checksum_record.hpp"
#include "io/directory_lock.hpp"
#include "io/run_directory.hpp"

namespace iwb::dem {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr const char* kEntryRecord = "consolidation.json";
constexpr const char* kEntryInputs = "consolidation_inputs.txt";
constexpr const char* kCacheVariable = "IWB_CONSOLIDATED_DIR";

// The files of a consolidated specimen: its restart first, then the stage's log.
std::vector<std::string> specimen_files(const Engine& engine) {
  return {engine.restart_file(kConsolidationStage), std::string(kConsolidationStage) + ".out"};
}

void copy_specimen(const Engine& engine, const fs::path& from, const fs::path& to) {
  for (const auto& name : specimen_files(engine))
    if (fs::exists(from / name))
      fs::copy_file(from / name, to / name, fs::copy_options::overwrite_existing);
  const fs::path record = io::checksum_record_path(from / engine.restart_file(kConsolidationStage));
  fs::copy_file(record, to / record.filename(), fs::copy_options::overwrite_existing);
}

// Empties a stale or corrupt entry of the files an entry holds, and no other (issue 60: the cache
// is a directory the user names); its lock, held by the caller, stays.
void clear_entry(const Engine& engine, const fs::path& dir) {
  auto names = specimen_files(engine);
  names.push_back(
      io::checksum_record_path(dir / engine.restart_file(kConsolidationStage)).filename());
  names.push_back(kEntryRecord);
  names.push_back(kEntryInputs);
  for (const auto& name : names) fs::remove(dir / name);
}

// The entry's record when it holds an intact specimen, copied into work_dir; null when there is
// none; `why` says what was wrong with one that could not be used.
json fetch(const Engine& engine, const fs::path& dir, const fs::path& work_dir, std::string& why) {
  if (!fs::exists(dir / kEntryRecord)) return nullptr;
  const std::string restart = engine.restart_file(kConsolidationStage);
  json record;
  try {
    record = json::parse(io::read_file(dir / kEntryRecord));
  } catch (const json::exception& e) {
    why = fmt::format("{}: not readable ({})", (dir / kEntryRecord).string(), e.what());
  }
  if (why.empty()) {
    if (const auto problem = io::checksum_problem(dir / restart)) why = *problem;
  }
  if (!why.empty()) {
    clear_entry(engine, dir);
    return nullptr;
  }
  copy_specimen(engine, dir, work_dir);
  if (const auto problem =
          io::checksum_problem(work_dir / restart)) {  // the copy, as the shear stage will read it
    why = fmt::format("the copy: {}", *problem);
    return nullptr;
  }
  return record;
}

void store(const Engine& engine, const StageContext& ctx, const fs::path& dir,
           const std::string& key, const json& entry) {
  fs::remove(dir / kEntryRecord);  // an entry without its record is no entry
  io::write_atomically(dir / kEntryInputs, engine.consolidation_inputs(ctx.scene));
  copy_specimen(engine, ctx.work_dir, dir);
  io::write_atomically(
      dir / kEntryRecord,
      json{{"key", key},
           {"engine", {{"name", engine.name()}, {"version", engine.version()}}},
           {"scene", ctx.scene.source},
           {"consolidated_in", fs::absolute(ctx.run_dir).lexically_normal().string()},
           {"processes", ctx.processes},
           {"created", io::utc_timestamp()},
           {"wall_seconds", entry.value("wall_seconds", 0.0)},
           {"facts", entry.value("facts", json::object())},
           {"restart", entry.value("restart", json::object())}}
              .dump(2) +
          "\n");
}

StageResult reused(const json& record, const fs::path& dir, const std::string& key, double seconds,
                   json& entry) {
  StageResult r;
  r.ok = true;
  r.facts = record.value("facts", json::object());
  entry = {{"status", "done"},
           {"wall_seconds", seconds},
           {"facts", r.facts},
           {"restart", record.value("restart", json::object())},
           {"consolidation",
            {{"key", key},
             {"entry", dir.string()},
             {"reused", true},
             {"consolidated_in", record.value("consolidated_in", std::string("?"))},
             {"consolidation_wall_seconds", record.value("wall_seconds", 0.0)}}}};
  return r;
}

}  // namespace

fs::path consolidation_cache_dir(const fs::path& fallback) {
  if (const char* v = std::getenv(kCacheVariable); v != nullptr && *v != '\0')
    return std::string(v) == "off" ? fs::path() : fs::path(v);
  return fallback;
}

std::string consolidation_key(const Engine& engine, const Scene& scene) {
  return io::sha256_hex(json{{"engine", engine.name()},
                             {"version", engine.version()},
                             {"inputs", engine.consolidation_inputs(scene)}}
                            .dump());
}

StageResult consolidate_through_cache(const Engine& engine, const StageContext& ctx,
                                      const fs::path& cache_dir, const std::string& command,
                                      json& entry,
                                      const std::function<StageResult()>& consolidate_here) {
  const auto t0 = std::chrono::steady_clock::now();
  const std::string key = consolidation_key(engine, ctx.scene);
  const fs::path dir = cache_dir / key;
  // another run consolidating this specimen holds the lock: wait for it, then reuse its work
  auto lock = io::DirectoryLock::wait(dir, command, ctx.interrupt);
  if (!lock) {
    StageResult r;
    r.interrupted = true;
    entry = {{"status", "interrupted"}, {"wall_seconds", 0.0}, {"facts", json::object()}};
    return r;
  }
  if (lock->stale() && ctx.progress) ctx.progress(lock->stale_message());
  std::string why;
  if (const json record = fetch(engine, dir, ctx.work_dir, why); !record.is_null()) {
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (ctx.progress)
      ctx.progress(fmt::format("consolidation reused: {} ({})", dir.string(),
                               record.value("consolidated_in", std::string("?"))));
    return reused(record, dir, key, seconds, entry);
  }
  if (!why.empty() && ctx.progress)
    ctx.progress(fmt::format("cached specimen not used: {}; consolidating again", why));
  StageResult r = consolidate_here();
  entry["consolidation"] = {{"key", key}, {"entry", dir.string()}, {"reused", false}};
  if (!why.empty()) entry["consolidation"]["rebuilt_because"] = why;
  if (r.ok) store(engine, ctx, dir, key, entry);
  return r;
}

}  // namespace iwb::dem
