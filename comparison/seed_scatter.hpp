#pragma once
// How much a DEM run would change with another seed (issue 14): the scatter over runs of the same
// scene that differ only in the seed. It weighs the quantities of a joint fit against each other
// (tau in kPa, u_n in mm: each residual in units of its own scatter) and tells a verdict whether
// a model's miss is larger than the DEM's own uncertainty.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "comparison/dem_run.hpp"

namespace iwb::comparison {

struct SeedScatter {
  std::vector<std::string> runs;  // the run compared first, then its other seeds
  std::size_t rows = 0;           // rows every seed has (the shortest run's)
  // RMS over the common rows of the per-row standard deviation across seeds (contract units);
  // 0 with a single run
  double tau_kPa = 0.0, u_n_mm = 0.0, sigma_n_kPa = 0.0;
  // per quantity of interest: mean and standard deviation over the seeds
  std::map<std::string, double> quantity_mean, quantity_sd;
  bool from_seeds() const { return runs.size() >= 2; }
};

// `run` and its other seeds (possibly none). InputError when a seed's scene differs from run's in
// anything but the seed, or its rows are not at the same u_x (a different output spacing).
SeedScatter seed_scatter(const DemRun& run, const std::vector<DemRun>& other_seeds);

// The runs among `candidates` (other than `run` itself) whose scene is run's but for the seed.
std::vector<DemRun> seeds_of(const DemRun& run, const std::vector<DemRun>& candidates);

}  // namespace iwb::comparison
