#pragma once
// Runs an element-test spec into a run directory: manifest.json, history.csv and, for cyclic
// paths, cycles.csv.
#include <atomic>
#include <filesystem>
#include <functional>
#include <string>

#include "element/element_test_file.hpp"

namespace iwb::element {

struct ElementRunOptions {
  std::filesystem::path out;
  bool force = false;
  std::string command_line;
  std::string input_text;  // the test file as read, hashed into the manifest
  const std::atomic<bool>* interrupt = nullptr;
};

struct ElementRunOutcome {
  driver::ElementTestResult result;
  nlohmann::json manifest;
};

// Builds the model, runs the path, writes the run directory. Input errors throw InputError
// before anything is written; a run that fails or is interrupted still writes its history up to
// the last accepted increment and a manifest saying so.
ElementRunOutcome run_element_to_directory(const ElementTestSpec& spec,
                                           const ElementRunOptions& options);

}  // namespace iwb::element
