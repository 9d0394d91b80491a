#pragma once
// Parameter files (CONVENTIONS.md "Parameter sets"): TOML, one table per model family, numbers
// only, units in the keys. Which keys a table must hold is the model's business (its
// ParameterTable); this only reads numbers and names the file and key when something is not one.
#include <toml++/toml.h>

#include <map>
#include <string>

#include "models/parameters.hpp"

namespace iwb::io {

using ParameterTables = std::map<std::string, models::ParameterValues>;

ParameterTables read_parameter_tables(const toml::table& root, const std::string& file);
ParameterTables load_parameter_file(const std::string& path);

}  // namespace iwb::io
