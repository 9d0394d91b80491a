#pragma once
// Per quantity of interest, whether a model holds against the DEM (issues 14, 36): the DEM value
// (the mean over its seeds when there are seeds, else the run's own) with its seed standard
// deviation and the 95 % Student's t-interval of that mean, the model's value, the relative error
// and the tolerance, and a verdict:
//   holds                 |error| <= tolerance;
//   breaks                the miss exceeds the tolerance by more than the half-width of the DEM
//                         mean's t-interval, t_{0.975, n-1} SD / sqrt(n) (the DEM is sure enough
//                         to convict; with a single run, any miss beyond the tolerance);
//   within DEM scatter    in between: the model misses the tolerance, but by no more than the
//                         DEM's own uncertainty;
//   not reached           the model stopped before the DEM's end, and the quantity needs the end.
// Each verdict also says what it rests on: its detection limit (the smallest relative error it
// can call "breaks": the tolerance plus the interval's half-width), the seeds the tolerance needs
// (an interval of at most half the tolerance, for the SD measured), and its notes (runs left out
// because they sheared at the plate, residuals that still drift).
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "comparison/replay/replay.hpp"
#include "comparison/replay/seed_scatter.hpp"

namespace iwb::comparison {

// Quantity key -> relative tolerance; quantities absent are not judged.
using Tolerances = std::map<std::string, double>;

// The defaults of comparison/replay/quantities.hpp for the quantities `dem`'s boundary condition
// leaves free, overridden by the [requirements] of the scene it ran ("not needed" drops a
// quantity).
Tolerances tolerances_for(const DemRun& dem);
// `defaults` with each key the [requirements] of `dem`'s scene states put in ("not needed" drops
// it); keys the defaults do not hold are not read.
Tolerances scene_tolerances(const DemRun& dem, Tolerances defaults);

struct Verdict {
  std::string key;
  std::optional<double> dem;     // the seed mean, or the run's own value without seeds
  std::optional<double> dem_sd;  // seed standard deviation (none with a single run)
  std::size_t seeds = 1;
  std::optional<double> model;
  std::optional<double> error;  // (model - DEM) / max(|DEM|, floor), signed
  double tolerance = 0.0;
  std::string verdict;
  std::optional<double>
      dem_ci;  // half-width of the t-interval of the seed mean (none with one run)
  std::optional<double>
      detection_limit;  // relative: tolerance + dem_ci / scale (tolerance alone: one run)
  std::optional<int> seeds_needed;  // for an interval of at most half the tolerance
  std::vector<std::string> notes;
};

std::vector<Verdict> judge(const DemRun& dem, const SeedScatter& scatter, const Replay& replay,
                           const Tolerances& tolerances);

// What a verdict rests on, for the monotonic and the cyclic verdicts alike: from the seeds' SD (in
// the quantity's unit) the half-width of the 95 % t-interval of their mean, the detection limit
// (tolerance + interval / scale, relative) and the seeds an interval of half the tolerance needs.
struct SeedInterval {
  std::optional<double> ci, detection_limit;
  std::optional<int> seeds_needed;
};
// `dof`: the SD's degrees of freedom where it is not the seeds' own (a pooled SD); else seeds - 1.
SeedInterval seed_interval(std::optional<double> sd, std::size_t seeds, double tolerance,
                           double scale, std::optional<int> dof = std::nullopt);
// "holds" within the tolerance, "within DEM scatter" when the miss lies inside the seed interval,
// else "breaks"; "not reached" without an error.
std::string verdict_word(std::optional<double> error, double tolerance, double scale,
                         std::optional<double> ci);

bool all_hold(const std::vector<Verdict>& verdicts);
// The keys of the verdicts that do not hold ("breaks" or "within DEM scatter" or "not reached").
std::vector<std::string> failing(const std::vector<Verdict>& verdicts);

nlohmann::json to_json(const std::vector<Verdict>& verdicts);

// The JSON fields every verdict shares, monotonic or cyclic (a V with dem, dem_sd, seeds, dem_ci,
// detection_limit, seeds_needed, model, error, tolerance, verdict): the DEM's seed statistics,
// the model's value and error, the tolerance and the word; null where a value is absent.
template <class V>
nlohmann::json shared_verdict_json(const V& v) {
  const auto value = [](const auto& x) { return x ? nlohmann::json(*x) : nlohmann::json(nullptr); };
  return {{"dem", value(v.dem)},
          {"dem_seed_sd", value(v.dem_sd)},
          {"seeds", v.seeds},
          {"dem_t_interval_95", value(v.dem_ci)},
          {"detection_limit", value(v.detection_limit)},
          {"seeds_needed", value(v.seeds_needed)},
          {"model", value(v.model)},
          {"relative_error", value(v.error)},
          {"tolerance", v.tolerance},
          {"verdict", v.verdict}};
}

}  // namespace iwb::comparison
