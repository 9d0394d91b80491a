#pragma once
// The options of `iwb assess` (assess.cpp), shared with its league (assess_league.cpp).
#include <string>
#include <vector>

namespace iwb::app {

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
};

// `iwb assess --reference RUN...`: the league of the interface models on a DEM scene.
int run_league(const AssessOptions& o);

}  // namespace iwb::app
