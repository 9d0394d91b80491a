#pragma once
// The parameter sets a command chooses from: the .toml files of a directory (`--params-dir`), or
// the sets of data/params/ built into the binary at build time (src/CMakeLists.txt, iwb_embed), so
// that `iwb validate` and `iwb plan` run from any directory without a checkout of the repository.
// Every set is read and checked when the list is made, before anything runs.
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "io/parameter_file.hpp"
#include "models/registry.hpp"

namespace iwb::io {

struct ParameterSet {
  std::string name;  // file name: "dem_default_grains.toml"
  std::string
      origin;  // where it was read: the file's path, or "<embedded:dem_default_grains.toml>"
  std::string text;
  ParameterTables tables;
  bool embedded() const { return origin.rfind("<embedded:", 0) == 0; }
};

// data/params/*.toml as they were when the binary was built, by file name (generated).
const std::map<std::string, std::string>& embedded_parameter_sets();

// The sets in `dir`, sorted by name; with an empty `dir` the embedded ones. InputError naming the
// directory when it is missing or holds no .toml file, or naming the file, key and value of a set
// that is not a parameter file.
std::vector<ParameterSet> parameter_sets(const std::filesystem::path& dir);

// A set built into iwb by its file name ("table_5_1_evaluation.toml") as a model's inputs, for
// code that needs a known set wherever it runs (the benches, `iwb run`, a model's declared
// example); std::logic_error if the binary was built without it.
models::ModelInputs shipped_inputs(const std::string& name);

// One parameter file as a set; InputError naming the file when it is missing or not a parameter
// file.
ParameterSet read_parameter_set(const std::filesystem::path& file);

// `--params-for MODEL=FILE` (repeatable), the set a command gives one model: the models named,
// in order, each checked known (find_model); InputError naming the entry that is not MODEL=FILE
// or names no model. Nothing is read.
std::vector<std::string> models_given_sets(const std::vector<std::string>& params_for);
// The set given for `model`, read, if the entries name it.
std::optional<ParameterSet> parameter_set_given_for(const std::vector<std::string>& params_for,
                                                    const std::string& model);

// The set as a file a run directory can name: its own path, or (embedded) a copy written
// atomically into `dir` under its name.
std::filesystem::path parameter_set_file(const ParameterSet& set, const std::filesystem::path& dir);

}  // namespace iwb::io
