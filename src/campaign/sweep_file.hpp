#pragma once
// A sweep file (schema: data/sweeps/README.md): a base scene, keys set in every job, the axes
// whose cartesian product gives the jobs, the engines, and optionally the comparison run over the
// complete runs afterwards. Validated as it is read; every error names the file, key and value.
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "io/toml_override.hpp"

namespace iwb::campaign {

using Setting = std::pair<std::string, io::TomlValue>;  // dotted scene key, value

// One value of an axis: usually one key, but an inline table sets several keys of one table
// together ({type = "CNS", K_kPa_per_mm = 50}: K is refused by the scene under CNL and CV).
using AxisValue = std::vector<Setting>;

struct Axis {
  std::string key;    // dotted scene key, e.g. "wall.height_d50", or a table ("boundary")
  std::string label;  // prefix of the value in job names ("rn" -> rn0.5); may be empty
  std::vector<AxisValue> values;
};

struct Comparison {
  std::string model;
  std::filesystem::path params;  // resolved against the sweep file's folder
};

struct SweepSpec {
  std::filesystem::path file;
  std::string text;  // the sweep file itself, for its hash
  std::string description;
  std::filesystem::path scene_file;  // resolved against the sweep file's folder
  std::string scene_text;
  std::vector<std::string> engines;
  std::vector<Setting> set;  // [set]: the same in every job
  std::vector<Axis> axes;
  std::optional<Comparison> compare;
  std::string slurm_time = "01:00:00";  // wall-clock limit of one array task
};

SweepSpec load_sweep(const std::filesystem::path& file);
SweepSpec parse_sweep(const std::string& text, const std::filesystem::path& file);

// The short name a key gets in job names unless its axis gives `label` (rn, d, sn, cf, s, ...).
std::string default_label(const std::string& key);

}  // namespace iwb::campaign
