#pragma once
// `iwb assess` (issue 17, seed 4.3): the total Sobol indices of an interface model's element test,
// or its parameter uncertainty (assess.cpp), or the league of the interface models on a DEM scene
// (league_run.cpp): the runs, the files written, the table to show.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace iwb::assessment {

struct AssessOptions {
  std::string model, params, out, boundary = "CNL", uncertainty;
  std::vector<std::string> reference, models, params_for;  // the league
  std::string distributions;                               // empty: the files built into iwb
  std::string parameter_uncertainty = "seed";
  std::string form_limits;  // a directory of form-limit records: the league says why each breaks
  int sobol_samples = 0, threads = 0;
  bool force = false;
  bool convergence = false;  // the Sobol indices at N/16 ... N as well
  double cov = 0.1, sigma_n = 100.0, e0 = 0.0, K = 0.0, gamma = 0.1;
  int samples = 1000, increments = 200;
  unsigned seed = 1;
  std::vector<std::string> cov_of;  // KEY=COV
  std::vector<std::string> ties;    // KEY=FACTOR*OTHER
  // What the runs tell as they go, for the caller to show: a line per model of the league, and a
  // counter of runs (done, total) made afresh for each set of samples (each model of a league).
  std::function<void(const std::string&)> note = [](const std::string&) {};
  std::function<std::function<void(long, long)>()> run_counter = [] {
    return std::function<void(long, long)>();
  };
};

// What `iwb assess` shows: its table (markdown) and the file to name, none for the parameter
// uncertainty (uncertainty.md holds the table alone).
struct AssessOutcome {
  std::string table;
  std::filesystem::path file;
};

// The league with --reference, else the Sobol indices (or --uncertainty) of one model, written
// into `out` (default runs/assess-<model>); InputError for bad input before anything runs.
AssessOutcome run_assess(const AssessOptions& options);

// The league of the interface models on the DEM runs of `reference`, written into `out` (default
// runs/assess-league) and resumed there; InputError for bad input before anything runs.
AssessOutcome run_league(const AssessOptions& options);

}  // namespace iwb::assessment
