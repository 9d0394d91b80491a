#pragma once
// `iwb compare`: one DEM run against a continuum model, in labelled variants of kappa_r and d_s
// (eq. 5.35 with the wall's R_n at d_s = 5 d50, 10 d50 and the measured band, and both fitted),
// into a directory with manifest.json, compare.json (variants, metrics, fit) and compare.csv.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "comparison/replay.hpp"

namespace iwb::comparison {

struct CompareOptions {
  std::filesystem::path dem_dir;
  std::string model = "hvwe";
  std::string params;  // parameter file
  std::filesystem::path out;
  bool allow_partial = false;
  bool force = false;
  std::string command_line;
};

// kappa_r from the wall's R_n by Gutjahr's eq. 5.35 in the given log base; a flat wall (R_n = 0)
// gets the floor models::kKappaRFloor.
double gutjahr_kappa_r(double R_n, double log_base = 10.0);

// The variants of issue 6 that need no fitting: kappa_r from Gutjahr's eq. 5.35 with the wall's
// R_n (base 10), d_s = 5 d50, 10 d50 and the measured wall band when the DEM has one.
std::vector<Variant> standard_variants(const DemRun& dem, const std::string& model,
                                       const models::ModelInputs& parameters);

nlohmann::json run_comparison(const CompareOptions& options);

}  // namespace iwb::comparison
