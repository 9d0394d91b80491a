#pragma once
// How much a DEM run would change with another seed (issue 14): the scatter over runs of the same
// scene that differ only in the seed. It weighs the quantities of a joint fit against each other
// (tau in kPa, u_n in mm: each residual in units of its own scatter) and tells a verdict whether
// a model's miss is larger than the DEM's own uncertainty.
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "comparison/replay/dem_run.hpp"

namespace iwb::comparison {

// One series (tau, u_n or sigma_n) over the seeds, on the compared run's rows.
struct SeriesScatter {
  std::vector<double> mean, sd;  // per row
  double rms_sd = 0.0;           // RMS over the rows of sd; 0 with a single run
};

struct SeedScatter {
  // the runs the statistics rest on: the run compared first (unless left out), then its other seeds
  std::vector<std::string> runs;
  // Runs of the cell left out, with why: a run whose shear localised at the plate measured the
  // plate, not the wall under test (issue 36), and is not averaged with those that sheared there.
  std::vector<std::pair<std::string, std::string>> left_out;
  bool only_plate_runs = false;  // every run localised at the plate: kept, as nothing else is left
  // Runs kept whose friction had not settled over the last fifth (friction_steady_state, issue
  // 59): the residual is not judged on them, and the verdicts on the dilation say how many.
  std::vector<std::string> not_steady;
  // Runs kept whose shear split between the wall and the plate (a far field moving at 25-75 % of
  // the first layer's speed): they measured the wall in part.
  std::vector<std::string> split;
  std::size_t rows = 0;  // the compared run's rows that every seed covers
  // contract units (kPa, mm, kPa). Seeds write their rows at other u_x (the output fires on
  // whole multiples of its interval counted from the engine's step 0, and consolidation takes a
  // different number of steps per seed): each seed is interpolated linearly in the travelled
  // displacement onto the compared run's rows.
  SeriesScatter tau, u_n, sigma_n;
  // per quantity of interest: mean and standard deviation over the seeds, each from its own curve
  std::map<std::string, double> quantity_mean, quantity_sd;
  std::map<std::string, std::vector<double>> quantity_values;  // each admitted run's, in order
  // Where the SD was pooled across cells (pooled_scatter.hpp): its degrees of freedom (the
  // interval's t then has these, not seeds - 1) and a note for the verdict.
  std::map<std::string, int> quantity_dof;
  std::map<std::string, std::string> quantity_note;
  bool from_seeds() const { return runs.size() >= 2; }
};

// `run` and its other seeds (possibly none). InputError when a seed's scene differs from run's in
// anything but the seed. Runs localised at the plate are left out while another run is left.
SeedScatter seed_scatter(const DemRun& run, const std::vector<DemRun>& other_seeds);

// Whether two runs ran one scene but for the seed: their resolved scenes (manifest.json
// /scene/resolved) agree on every key both record; a key only one records was added to the schema
// after the other run, which then had its default.
bool same_scene_but_seed(const DemRun& a, const DemRun& b);

// The runs among `candidates` (other than `run` itself) whose scene is run's but for the seed.
std::vector<DemRun> seeds_of(const DemRun& run, const std::vector<DemRun>& candidates);

}  // namespace iwb::comparison
