#pragma once
// Element-test files: what to run, declared as data (STYLE.md, after MTest). The schema is
// documented key by key in data/tests/README.md; every error names the file, key and value.
#include <toml++/toml.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "driver/element_test.hpp"
#include "models/registry.hpp"

namespace iwb::element {

struct ElementTestSpec {
  std::string source;  // file path, or "<embedded:NAME>"
  std::string model;
  models::ModelInputs inputs;
  std::string parameter_source;  // file the parameters came from, or "inline"
  models::InitialState initial;
  driver::ShearZone zone;
  driver::BoundaryCondition boundary;
  driver::Path path;
  driver::ShearDirection direction = driver::ShearDirection::kX;  // of the path's shear
  driver::RunSettings settings;
  std::vector<std::string> warnings;
  nlohmann::json resolved;  // every input after defaults and conversions, for the manifest
};

// Stress-point integration settings from a table laid out as a test file's [integration] (scheme,
// substeps, pair, rtol), for the C interface. InputError naming `source`.
integration::IntegratorSettings parse_integrator_settings(const toml::table& integration,
                                                          const std::string& source);

// The initial state of `model` from a table laid out as a test file's [initial] (the model's
// declared inputs, their ranges, defaults and groups; unknown keys refused), for callers without a
// test file (the C interface). InputError naming `source`.
models::InitialState parse_initial_state(const toml::table& initial, const std::string& model,
                                         const models::ModelInputs& inputs,
                                         const std::string& source);

ElementTestSpec load_element_test(const std::string& path);
// `base_dir` resolves relative parameter-file paths.
ElementTestSpec parse_element_test(const toml::table& root, const std::string& source,
                                   const std::filesystem::path& base_dir);

}  // namespace iwb::element
