#include "dem/engines/liggghts/shear_checkpoint.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <regex>
#include <sstream>

#include "io/run_directory.hpp"

namespace iwb::dem {

namespace fs = std::filesystem;

namespace {

constexpr const char* kBasisFile = "shear_checkpoint.basis";
constexpr long kMinCheckpointSteps = 1000;  // a restart per 1000 steps costs < 1 % of them
constexpr long kCheckpointsPerShear = 50;

// "key value key value ...": the record the fresh attempt printed when shear started.
std::optional<ShearStart> read_start_record(const fs::path& file) {
  std::istringstream in(io::read_file(file));
  nlohmann::json facts = nlohmann::json::object();
  std::string key;
  double value = 0.0;
  while (in >> key >> value) facts[key] = value;
  if (!facts.contains("step0") || !facts.contains("z0_m")) return std::nullopt;
  ShearStart s{facts["step0"].get<long>(), facts["z0_m"].get<double>(), facts};
  s.facts.erase("step0");
  s.facts.erase("z0_m");
  return s;
}

// The attempt number of profiles.resumed_<k>.raw, or 0.
int resumed_profile_index(const fs::path& p) {
  static const std::regex name(R"(profiles\.resumed_([0-9]+)\.raw)");
  std::smatch m;
  const std::string f = p.filename().string();
  return std::regex_match(f, m, name) ? std::stoi(m[1]) : 0;
}

}  // namespace

long checkpoint_every(const Numerics& n) {
  const long period = std::max(1L, std::min(n.profile_every, n.shear_steps));
  const long target = std::max(kMinCheckpointSteps, n.shear_steps / kCheckpointsPerShear);
  const long floor = std::max(kMinCheckpointSteps, n.profile_repeat);
  long best = period;
  for (long k = 1; k <= period; ++k) {
    if (period % k != 0) continue;
    if (period / k < floor) break;
    best = period / k;
    if (best <= target) break;
  }
  return best;
}

std::optional<ShearStart> usable_checkpoint(const fs::path& work, const std::string& basis) {
  if (!fs::exists(work / kShearCheckpoint) || !fs::exists(work / kShearStartRecord) ||
      !fs::exists(work / kBasisFile) || io::read_file(work / kBasisFile) != basis)
    return std::nullopt;
  return read_start_record(work / kShearStartRecord);
}

std::vector<fs::path> shear_profile_files(const fs::path& work) {
  std::vector<fs::path> resumed;
  if (fs::exists(work))
    for (const auto& e : fs::directory_iterator(work))
      if (resumed_profile_index(e.path()) > 0) resumed.push_back(e.path());
  std::sort(resumed.begin(), resumed.end(), [](const fs::path& a, const fs::path& b) {
    return resumed_profile_index(a) < resumed_profile_index(b);
  });
  resumed.insert(resumed.begin(), work / "profiles.raw");
  return resumed;
}

void begin_fresh_shear(const fs::path& work, const std::string& basis) {
  for (const auto& p : shear_profile_files(work))
    if (p.filename() != "profiles.raw") fs::remove(p);
  fs::remove(work / kShearCheckpoint);
  fs::remove(work / kShearStartRecord);
  io::write_atomically(work / kBasisFile, basis);
}

void prepare_resumed_shear(const fs::path& work) {
  const fs::path raw = work / "timeseries.raw";
  if (!fs::exists(raw)) return;
  const std::string text = io::read_file(raw);
  if (text.empty() || text.back() == '\n') return;
  io::write_atomically(raw, text.substr(0, text.rfind('\n') + 1));
}

TemplateValues shear_entry_values(const Numerics& n, const std::optional<ShearStart>& resumed,
                                  const fs::path& work) {
  TemplateValues v = {{"checkpoint", kShearCheckpoint},
                      {"checkpoint_every", std::to_string(checkpoint_every(n))},
                      {"start_record", kShearStartRecord}};
  if (!resumed) {
    v.insert({{"entry", "starts afresh from the consolidated specimen"},
              {"start_restart", "consolidated.restart"},
              {"fresh", ""},
              {"resumed", "# (resumed only) "},
              {"recorded_z0", "0"},
              {"recorded_step0", "0"},
              {"profiles_file", "profiles.raw"},
              {"dump_first", "first yes "}});
    return v;
  }
  const int attempt = resumed_profile_index(shear_profile_files(work).back()) + 1;
  v.insert({{"entry", fmt::format("resumes from its checkpoint (attempt {})", attempt + 1)},
            {"start_restart", kShearCheckpoint},
            {"fresh", "# (fresh only) "},
            {"resumed", ""},
            {"recorded_z0", fmt::format("{:.17g}", resumed->z0_m)},
            {"recorded_step0", std::to_string(resumed->step0)},
            {"profiles_file", fmt::format("profiles.resumed_{}.raw", attempt)},
            {"dump_first", ""}});
  return v;
}

}  // namespace iwb::dem
