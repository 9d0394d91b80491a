#pragma once
// `iwb stability MODEL PARAMS [--full] [-o DIR]`: the stability map of one model (analysis/).
#include <string>

namespace iwb::analysis {

struct StabilityOptions {
  std::string model;
  std::string params;           // parameter file (data/params/)
  bool full = false;            // the full sweep (minutes) instead of the reduced one (seconds)
  std::string out;              // default runs/stability-<model>
  double budget_seconds = 0.0;  // per point; 0 = the sweep's default
};

// Exit code: 0 when the map was written (whatever the outcomes), 2 for bad input.
int run_stability(const StabilityOptions& options);

}  // namespace iwb::analysis
