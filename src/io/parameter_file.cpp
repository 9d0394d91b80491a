#include "io/parameter_file.hpp"

#include <fmt/core.h>

#include <cmath>

#include "common/errors.hpp"
#include "io/toml_reader.hpp"

namespace iwb::io {

ParameterTables read_parameter_tables(const toml::table& root, const std::string& file) {
  ParameterTables out;
  for (const auto& [name, node] : root) {
    const auto* table = node.as_table();
    if (table == nullptr)
      throw InputError(
          fmt::format("{}: key '{}' = {} should be a table of parameters such as "
                      "[hypoplastic]",
                      file, name.str(), describe(node)));
    auto& values = out[std::string(name.str())];
    for (const auto& [key, v] : *table) {
      const auto number = v.value<double>();
      if (!number || !(v.is_integer() || v.is_floating_point()))
        throw InputError(fmt::format("{}: key '{}.{}' = {} is not a number", file, name.str(),
                                     key.str(), describe(v)));
      if (!std::isfinite(*number))  // TOML admits inf and nan
        throw InputError(fmt::format("{}: key '{}.{}' = {} is not a finite number", file,
                                     name.str(), key.str(), describe(v)));
      values[std::string(key.str())] = *number;
    }
  }
  return out;
}

ParameterTables load_parameter_file(const std::string& path) {
  return read_parameter_tables(parse_toml_file(path), path);
}

}  // namespace iwb::io
