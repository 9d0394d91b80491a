#pragma once
// Cyclic verdicts (issue 34, item 4): a model replayed along a cyclic DEM run's own path is
// judged cycle by cycle on the quantities of src/cycles/ (one definition for both), at the cycles
// a reader looks at first (1, 2, 5 and the last), as a change from the first cycle to the last,
// and after the cycles. Default tolerances, each a [requirements] key of the scene the run ran
// (dem::cyclic_quantities; "not needed" drops it):
//   cycle_peak_friction        peak tau/sigma_n towards +A and -A                     10 %
//   cycle_sigma_n_ratio        sigma_n at the cycle's end over sigma_n0 (CNS, CV: the   10 %
//                              degradation behind pile shaft friction fatigue)
//   cycle_u_n                  accumulated u_n at the cycle's end (CNL, CNS; against   20 %
//                              at least 0.02 d50)
//   reversal_secant            secant stiffness over 50 % of A after reversals         30 %
//                              (the 10 % secant is reported, not judged: at 3e-4 it
//                              scatters by ~10 % per reversal)
//   post_cyclic_peak_friction  peak tau/sigma_n of the shear after the cycles          10 %
//   post_cyclic_u_n_change     its u_n change                                          20 %
// The change over the cycles (quantity "<name>_change", where "cycle 1 to N") is judged with the
// quantity's tolerance against the larger of |the DEM's first-cycle mean| and |its change|: a
// sigma_n ratio that falls from 1.03 to 0.80 is missed by 10 % when the model's change misses
// -0.23 by 0.10; a ratchet of u_n from near zero is judged on the ratchet itself.
// The DEM's value is the mean over the cell's seeds (those the monotonic verdicts rest on), with
// the 95 % t-interval of that mean, the detection limit and the seeds an interval of half the
// tolerance needs (verdicts.hpp, seed_interval). A verdict is "holds" within the tolerance,
// "within DEM scatter" when the miss lies inside the interval, else "breaks", or "not reached"
// where the replay stopped before the cycle's end.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "comparison/replay/dem_run.hpp"
#include "comparison/replay/replay.hpp"
#include "comparison/verdicts/verdicts.hpp"
#include "cycles/cycle_quantities.hpp"

namespace iwb::comparison {

// The cycles a reader looks at first, judged and drawn: 1, 2, 5 and the last of `cycles` (each
// once, those that exist).
std::vector<int> judged_cycles(int cycles);

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

// The tolerances above for the quantities `dem`'s boundary leaves free (CNL holds sigma_n, CV u_n),
// overridden by its scene's [requirements].
Tolerances cyclic_tolerances(const DemRun& dem);
// The default tolerance of each [requirements] key of the cyclic quantities (issue 34's), written
// here once (`iwb compare --help` lists them from it).
const Tolerances& cyclic_default_tolerances();

// `dem_seeds`: the quantities of each seed run of the cell (at least the compared run's).
std::vector<CyclicVerdict> judge_cycles(const DemRun& dem,
                                        const std::vector<cycles::CyclicQuantities>& dem_seeds,
                                        const cycles::CyclicQuantities& model_q);

nlohmann::json to_json(const std::vector<CyclicVerdict>& verdicts);

}  // namespace iwb::comparison
