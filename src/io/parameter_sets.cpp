#include "io/parameter_sets.hpp"

#include <fmt/core.h>

#include <algorithm>

#include "common/errors.hpp"
#include "common/input_file.hpp"
#include "io/run_directory.hpp"
#include "io/toml_reader.hpp"

namespace iwb::io {

namespace fs = std::filesystem;

namespace {

ParameterSet read_set(std::string name, std::string origin, std::string text) {
  ParameterSet set{std::move(name), std::move(origin), std::move(text), {}};
  set.tables = read_parameter_tables(parse_toml_text(set.text, set.origin), set.origin);
  return set;
}

std::vector<ParameterSet> sets_in_directory(const fs::path& dir) {
  if (!fs::is_directory(dir))
    throw InputError(
        fmt::format("--params-dir {}: not a directory (without --params-dir the sets built into "
                    "iwb are used)",
                    dir.string()));
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".toml" && e.is_regular_file()) files.push_back(e.path());
  if (files.empty())
    throw InputError(fmt::format("--params-dir {}: holds no parameter set (*.toml)", dir.string()));
  std::sort(files.begin(), files.end());
  std::vector<ParameterSet> out;
  for (const auto& f : files) out.push_back(read_parameter_set(f));
  return out;
}

}  // namespace

ParameterSet read_parameter_set(const fs::path& file) {
  if (const auto why = unreadable_input_file(file); !why.empty())
    throw InputError(fmt::format("{}: {}", file.string(), why));
  return read_set(file.filename().string(), file.string(), read_file(file));
}

std::vector<ParameterSet> parameter_sets(const fs::path& dir) {
  if (!dir.empty()) return sets_in_directory(dir);
  std::vector<ParameterSet> out;  // std::map: already sorted by name
  for (const auto& [name, text] : embedded_parameter_sets())
    out.push_back(read_set(name, "<embedded:" + name + ">", text));
  return out;
}

fs::path parameter_set_file(const ParameterSet& set, const fs::path& dir) {
  if (!set.embedded()) return set.origin;
  fs::create_directories(dir);
  write_atomically(dir / set.name, set.text);
  return dir / set.name;
}

models::ModelInputs shipped_inputs(const std::string& name) {
  for (const auto& set : parameter_sets({}))
    if (set.name == name) return {set.tables, set.origin, {}};
  throw std::logic_error(
      fmt::format("{} is not among the parameter sets built into iwb (data/params/)", name));
}

std::vector<std::string> models_given_sets(const std::vector<std::string>& params_for) {
  std::vector<std::string> models;
  for (const auto& g : params_for) {
    const auto eq = g.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == g.size())
      throw InputError(fmt::format(
          "--params-for {}: give MODEL=FILE, e.g. hvwe=data/params/truth_grains.toml", g));
    try {
      models::find_model(g.substr(0, eq));
    } catch (const InputError& e) {
      throw InputError(fmt::format("--params-for {}: {}", g, e.what()));
    }
    models.push_back(g.substr(0, eq));
  }
  return models;
}

std::optional<ParameterSet> parameter_set_given_for(const std::vector<std::string>& params_for,
                                                    const std::string& model) {
  const auto named = models_given_sets(params_for);
  for (std::size_t k = 0; k < named.size(); ++k)
    if (named[k] == model) try {
        return read_parameter_set(params_for[k].substr(model.size() + 1));
      } catch (const InputError& e) {
        throw InputError(fmt::format("--params-for {}: {}", params_for[k], e.what()));
      }
  return std::nullopt;
}

}  // namespace iwb::io
