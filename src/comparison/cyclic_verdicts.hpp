#pragma once
// Cyclic verdicts (issue 34, item 4): a model replayed along a cyclic DEM run's own path is
// judged cycle by cycle on the quantities of src/cycles/ (one definition for both), at the cycles
// a reader looks at first (1, 2, 5 and the last) and after the cycles:
//   peak tau/sigma_n towards +A and -A             10 %
//   sigma_n at the cycle's end over sigma_n0        10 %  (CNS and CV: the degradation behind pile
//                                                          shaft friction fatigue)
//   accumulated u_n at the cycle's end              20 %  (CNL and CNS; against at least 0.02 d50)
//   secant stiffness over 50 % of A after reversals 30 %  (the 10 % secant is reported, not judged:
//                                                          at 3e-4 it scatters by ~10 % per
//                                                          reversal)
//   post-cyclic peak tau/sigma_n 10 %, its u_n change 20 %.
// The DEM's value is the mean over the cell's seeds (those the monotonic verdicts rest on), with
// the 95 % t-interval of that mean, the detection limit and the seeds an interval of half the
// tolerance needs (verdicts.hpp, seed_interval). A verdict is "holds" within the tolerance,
// "within DEM scatter" when the miss lies inside the interval, else "breaks", or "not reached"
// where the replay stopped before the cycle's end.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "comparison/dem_run.hpp"
#include "comparison/replay.hpp"
#include "cycles/cycle_quantities.hpp"

namespace iwb::comparison {

// The wall's program of a cyclic run (its manifest's /scene/resolved/shear); nullopt when the run
// is monotonic.
std::optional<cycles::Program> cyclic_program(const DemRun& dem);

// The cycles a reader looks at first, judged and drawn: 1, 2, 5 and the last of `cycles` (each
// once, those that exist).
std::vector<int> judged_cycles(int cycles);

// A cyclic run's travel at each row: its wall moves at v throughout (no ramp with cycles), so v t.
std::vector<double> cyclic_travel(const DemRun& dem);

// The per-cycle quantities of the DEM run and of a replay of it (its rows are the DEM's, in time).
cycles::CyclicQuantities dem_cycles(const DemRun& dem, const cycles::Program& program);
cycles::CyclicQuantities replay_cycles(const DemRun& dem, const Replay& replay,
                                       const cycles::Program& program);

struct CyclicVerdict {
  std::string quantity;                     // e.g. "sigma_n_ratio"
  std::string where;                        // "cycle 5", "after the cycles"
  std::optional<double> dem, model, error;  // dem: the seed mean
  double tolerance = 0.0;
  std::string verdict;
  std::size_t seeds = 1;  // the seeds that reached this cycle
  std::optional<double> dem_sd, dem_ci, detection_limit;
  std::optional<int> seeds_needed;
};

// `dem_seeds`: the quantities of each seed run of the cell (at least the compared run's).
std::vector<CyclicVerdict> judge_cycles(const DemRun& dem,
                                        const std::vector<cycles::CyclicQuantities>& dem_seeds,
                                        const cycles::CyclicQuantities& model_q);

nlohmann::json to_json(const std::vector<CyclicVerdict>& verdicts);

}  // namespace iwb::comparison
