#pragma once
// Element-test files: what to run, declared as data (STYLE.md, after MTest). The schema is
// documented key by key in data/tests/README.md; every error names the file, key and value.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <toml++/toml.h>
#include <string>
#include <vector>

#include "driver/element_test.hpp"
#include "models/registry.hpp"

namespace iwb::io {

struct ElementTestSpec {
  std::string source;  // file path, or "<embedded:NAME>"
  std::string model;
  models::ModelInputs inputs;
  std::string parameter_source;  // file the parameters came from, or "inline"
  models::InitialState initial;
  driver::ShearZone zone;
  driver::BoundaryCondition boundary;
  driver::Path path;
  driver::RunSettings settings;
  std::vector<std::string> warnings;
  nlohmann::json resolved;  // every input after defaults and conversions, for the manifest
};

ElementTestSpec load_element_test(const std::string& path);
// `base_dir` resolves relative parameter-file paths.
ElementTestSpec parse_element_test(const toml::table& root, const std::string& source,
                                   const std::filesystem::path& base_dir);

}  // namespace iwb::io
