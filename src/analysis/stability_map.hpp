#pragma once
// `iwb stability MODEL PARAMS [--full] [-o DIR]`: the stability map of one model from its parameter
// file (stability.hpp sweeps, stability_output.hpp writes).
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "analysis/stability.hpp"

namespace iwb::analysis {

struct StabilityMapOptions {
  std::string model;
  std::string params;           // parameter file (data/params/)
  bool full = false;            // the full sweep (minutes) instead of the reduced one (seconds)
  std::string out;              // default runs/stability-<model>
  double budget_seconds = 0.0;  // per point; 0 = the sweep's default
  // what is swept and where it goes, one line for the caller to show before the sweep starts
  std::function<void(const std::string&)> starting = [](const std::string&) {};
};

struct StabilityMap {
  std::vector<StabilityResult> results;
  double seconds = 0.0;  // wall-clock time of the sweep
  std::filesystem::path dir;
};

// InputError, before the sweep, for an unknown model or a parameter file it cannot use; the map
// is written whatever the points' outcomes.
StabilityMap run_stability_map(const StabilityMapOptions& options);

}  // namespace iwb::analysis
