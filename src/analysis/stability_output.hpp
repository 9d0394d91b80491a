#pragma once
// Writing a stability map: stability.csv (one row per point), stability.md (counts per outcome and
// boundary condition, the reasons of the stops with an example each, the integrator's cut-backs)
// and one figure per boundary condition (stability_CNL.svg/.png, ...: sigma_n x density index,
// each cell coloured by the worst outcome among its points and labelled completed/points).
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "analysis/stability.hpp"
#include "io/output_directory.hpp"

namespace iwb::analysis {

// A stability map's directory (issue 60): a later map of the same kind replaces its files.
inline const io::OutputKind kStabilityOutput{"stability", "stability.csv"};

struct StabilityMapInfo {
  std::string model;
  std::string parameter_file;
  std::string form;                               // "reduced" or "full"
  DensityAxis axis = DensityAxis::kDensityIndex;  // how e0 was placed (density_axis_of)
};

// Points per outcome, every outcome of the closed set present (zero if none).
std::map<Outcome, long> count_outcomes(const std::vector<StabilityResult>& results);

std::string stability_csv(const std::vector<StabilityResult>& results, DensityAxis axis);
std::string stability_markdown(const std::vector<StabilityResult>& results,
                               const StabilitySweep& sweep, const StabilityMapInfo& info);
// Writes the CSV, the markdown and the figures into `dir` (created); returns the figures' SVGs.
std::vector<std::filesystem::path> write_stability_map(const std::vector<StabilityResult>& results,
                                                       const StabilitySweep& sweep,
                                                       const StabilityMapInfo& info,
                                                       const std::filesystem::path& dir);

}  // namespace iwb::analysis
