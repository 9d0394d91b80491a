#include "campaign/jobs.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>

#include "common/errors.hpp"
#include "dem/scene/scene.hpp"
#include "dem/scene/scene_keys.hpp"
#include "io/toml_reader.hpp"

namespace iwb::campaign {

std::string scene_path(const Job& job) {
  return "scenes/" + job.name + ".toml";
}
std::string run_path(const Job& job) {
  return "runs/" + job.name;
}

std::string describe(const std::vector<Setting>& settings) {
  std::string s;
  for (const auto& [key, value] : settings)
    s += (s.empty() ? "" : ", ") + key + " = " + io::to_toml(value);
  return s;
}

namespace {

// A value as it reads in a file name: 0.5, 2 (also for 2.0), cnl, a list by its first and last
// values (0.5..1.7); anything else outside [a-z0-9.-] becomes '-'.
std::string name_part(const io::TomlValue& value) {
  std::string text = std::visit(
      [](const auto& v) -> std::string {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, std::string>)
          return v;
        else if constexpr (std::is_same_v<T, std::vector<double>>)  // a list by its ends: 0.5..1.7
          return fmt::format("{}..{}", v.front(), v.back());
        else if constexpr (std::is_same_v<T, double>)
          return fmt::format("{}", v);  // shortest round trip
        else
          return io::to_toml(v);
      },
      value);
  if (text.size() > 2 && text.compare(text.size() - 2, 2, ".0") == 0) text.resize(text.size() - 2);
  for (char& c : text) {
    c = char(std::tolower(static_cast<unsigned char>(c)));
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '-') c = '-';
  }
  return text;
}

// One value per axis, in axis order.
namespace fs = std::filesystem;
using Combination = std::vector<const AxisValue*>;

bool is_path_key(const std::string& dotted) {
  const auto keys = io::path_keys(dem::scene_keys());
  return std::find(keys.begin(), keys.end(), dotted) != keys.end();
}

// A file names a job by its stem (file-sandblasted_like-6.3, not
// file-..-walls-sandblasted-like.csv-6.3).
std::string file_stem(const io::TomlValue& value) {
  const auto* text = std::get_if<std::string>(&value);
  return text != nullptr ? fs::path(*text).stem().string() : io::to_toml(value);
}

// label + value per axis, joined by '_'; a table value reads as its values joined by '-' (cns-50).
std::string job_name(const std::string& engine, bool several_engines,
                     const Combination& combination, const std::vector<Axis>& axes) {
  std::string name = several_engines ? engine : "";
  for (std::size_t i = 0; i < combination.size(); ++i) {
    if (!name.empty()) name += '_';
    name += axes[i].label;
    for (std::size_t k = 0; k < combination[i]->size(); ++k) {
      if (k > 0) name += '-';
      const auto& [key, value] = (*combination[i])[k];
      name += name_part(is_path_key(key) ? io::TomlValue(file_stem(value)) : value);
    }
  }
  return name.empty() ? "base" : name;
}

// Every combination of one value per axis, the last axis varying fastest.
std::vector<Combination> combinations(const std::vector<Axis>& axes) {
  std::vector<Combination> out = {{}};
  for (const auto& axis : axes) {
    std::vector<Combination> next;
    for (const auto& partial : out)
      for (const auto& v : axis.values) {
        next.push_back(partial);
        next.back().push_back(&v);
      }
    out = std::move(next);
  }
  return out;
}

std::vector<Setting> flattened(const Combination& combination) {
  std::vector<Setting> out;
  for (const auto* value : combination) out.insert(out.end(), value->begin(), value->end());
  return out;
}

// A value that sets a profile (`wall.profile`, `plate.profile`) replaces its whole table: the
// other keys of a wall belong to its profile, and a flat wall refuses the base sawtooth's pitch
// and height. (Over a base whose table holds the profile alone, as every sweep's base did before,
// the text is the same: toml++ writes keys in order.)
void drop_tables_of_profiles(toml::table& root, const std::vector<Setting>& values) {
  constexpr std::string_view kProfile = ".profile";
  for (const auto& [key, value] : values)
    if (key.size() > kProfile.size() && key.ends_with(kProfile) &&
        key.find('.') == key.size() - kProfile.size())
      root.erase(key.substr(0, key.size() - kProfile.size()));
}

// Files a scene names (its declared path keys) made absolute: a job's scene is written elsewhere.
// (Such a job's text, and so its reuse, then depends on where the file lies; the file's content
// counts too: dem::scene_sha256.)
// Run before the sweep's own values, for the base scene's (relative to the scene), and after them,
// for the sweep's (relative to the sweep file); an absolute path stays.
void absolute_paths(toml::table& root, const fs::path& folder) {
  for (const auto& dotted : io::path_keys(dem::scene_keys())) {
    const auto dot = dotted.find('.');
    auto* value = root.at_path(dotted).as_string();
    if (dot == std::string::npos || value == nullptr || fs::path(value->get()).is_absolute())
      continue;
    value->get() = fs::absolute(folder / value->get()).lexically_normal().string();
  }
}

std::string job_scene(const SweepSpec& spec, const Job& job) {
  const std::string where = fmt::format("{}: job {}", spec.file.string(), job.name);
  auto root = io::parse_toml_text(spec.scene_text, spec.scene_file.string());
  absolute_paths(root, spec.scene_file.parent_path());
  for (const auto& [key, value] : spec.set) io::set_dotted(root, key, value, where);
  drop_tables_of_profiles(root, job.values);
  for (const auto& [key, value] : job.values) io::set_dotted(root, key, value, where);
  absolute_paths(root, spec.file.parent_path());
  // Comments of the base do not survive re-serialisation; this header says where the text came
  // from. File names only: the text's sha256 decides reuse and must not depend on the working
  // directory.
  return fmt::format("# {} with {}{}{} (iwb sweep {}, job {})\n",
                     spec.scene_file.filename().string(), describe(spec.set),
                     spec.set.empty() || job.values.empty() ? "" : ", ", describe(job.values),
                     spec.file.filename().string(), job.name) +
         io::serialise(root);
}

void validate(const SweepSpec& spec, const Job& job) {
  try {
    dem::parse_scene(job.scene_text, scene_path(job));
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}: job {} ({}) is not a valid scene; nothing was run: {}",
                                 spec.file.string(), job.name, describe(job.values), e.what()));
  }
}

}  // namespace

std::vector<Job> expand_jobs(const SweepSpec& spec) {
  std::vector<Job> jobs;
  std::map<std::string, std::string> seen;  // name -> its values, to explain a collision
  for (const auto& engine : spec.engines)
    for (const auto& combination : combinations(spec.axes)) {
      Job job{job_name(engine, spec.engines.size() > 1, combination, spec.axes), engine,
              flattened(combination), ""};
      if (auto [it, fresh] = seen.emplace(job.name, describe(job.values)); !fresh)
        throw InputError(
            fmt::format("{}: two jobs would be named {} ({} and {}); give the axes distinct values "
                        "or labels",
                        spec.file.string(), job.name, it->second, describe(job.values)));
      job.scene_text = job_scene(spec, job);
      validate(spec, job);
      jobs.push_back(std::move(job));
    }
  return jobs;
}

}  // namespace iwb::campaign
