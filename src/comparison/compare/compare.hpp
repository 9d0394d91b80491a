#pragma once
// `iwb compare`: one DEM run against a continuum model (issues 6, 14), into a directory with
// manifest.json, compare.json and compare.csv. Variants of kappa_r and d_s: predicted without
// fitting (kappa_r from eq. 5.35 with the wall's R_n, d_s a given multiple of d50; also 5 and 10
// d50 and the measured wall band), fitted to tau alone (for contrast), and fitted jointly to tau
// and the free normal quantity. Each variant is judged per quantity of interest
// (comparison/verdicts/verdicts.hpp), and a scan of the (kappa_r, d_s) box says whether any pair
// makes every quantity hold: where none does, that is a finding about the model, not a failed fit.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "comparison/replay/fit.hpp"
#include "comparison/replay/pooled_scatter.hpp"
#include "comparison/replay/replay.hpp"
#include "comparison/replay/seed_scatter.hpp"
#include "comparison/verdicts/verdicts.hpp"
#include "models/registry.hpp"

namespace iwb::comparison {

// The d_s of the predicted variant, in d50, when none is given (the low end of the 5-10 d50 the
// seed's interface models assume).
inline constexpr double kDefaultPredictedDsD50 = 5.0;
// Points per axis of the feasibility scan of the (kappa_r, ln d_s) box.
inline constexpr int kScanPoints = 12;

struct CompareOptions {
  std::filesystem::path dem_dir;
  std::string model = models::kDefaultInterfaceModel;
  std::string params;  // parameter file
  std::filesystem::path out;
  bool allow_partial = false;
  bool force = false;
  std::string command_line;
  std::vector<std::filesystem::path> seed_dirs;  // runs of the same scene with other seeds
  double predicted_ds_d50 = kDefaultPredictedDsD50;
  // The wall's scheme for every variant instead of the model's default (one it declares), and
  // Arnold & Herle's f_c reading (ERRATA 9): empty = the defaults.
  std::string roughness_scheme, f_c;
  // A form-limit record of the model (iwb form-limit's form_limit.json): each "breaks" then says
  // whether the form or the calibration broke (comparison/causes/form_limit.hpp). Empty: none.
  std::filesystem::path form_limit;
  // The set's seed scatter pooled across cells (pooled_scatter.hpp), for `iwb compare --runs`;
  // none: the cell's own.
  std::optional<PooledScatter> pooled;
};

// The (kappa_r, d_s) box of a fit: kappa_r in [floor, 1] for a model that reads wall roughness,
// fixed at 1 for one that does not (d_s is then fitted alone).
FitBounds fit_bounds(const std::string& model);

// kappa_r from the wall's R_n by Gutjahr's eq. 5.35 in the given log base; a flat wall (R_n = 0)
// gets the floor models::kKappaRFloor.
double gutjahr_kappa_r(double R_n, double log_base = 10.0);

// The variants that need no fitting, kappa_r from eq. 5.35 with the wall's R_n (base 10): first
// the prediction at d_s = `predicted_ds_d50` d50, then 5 and 10 d50 (where they differ from it)
// and the measured wall band when the DEM has one.
std::vector<Variant> standard_variants(const DemRun& dem, const std::string& model,
                                       const models::ModelInputs& parameters,
                                       double predicted_ds_d50 = kDefaultPredictedDsD50);

// Everything a comparison reads, read and checked (InputError naming the file, key or option)
// before anything is written: the DEM run and its seeds, the parameter file for the model, the
// roughness options, the form-limit record. `options.out` is not looked at yet.
struct ComparisonInputs {
  CompareOptions options;
  DemRun dem;
  std::vector<DemRun> seeds;
  SeedScatter scatter;
  Tolerances tolerances;
  nlohmann::json form_limit;        // null: none
  std::vector<Variant> candidates;  // standard_variants, with the roughness options applied
};
ComparisonInputs read_comparison_inputs(const CompareOptions& options);

// Writes the comparison into `options.out` (refused if it holds an earlier run, without force).
nlohmann::json run_comparison(const ComparisonInputs& inputs);
nlohmann::json run_comparison(const CompareOptions& options);  // the two steps above

// --roughness-scheme and --f-c of `options` applied to a variant's wall; InputError for what the
// model does not take (checked before a comparison or a set writes anything).
void chosen_roughness(const CompareOptions& options, models::Roughness& roughness);

// The parameter file read and validated for `model` (InputError naming the file, key and value):
// checked before a comparison writes anything.
models::ModelInputs validated_parameters(const std::string& model, const std::string& params);

// InputError (naming the run, the set and why) where the model cannot start from the DEM's first
// state with the predicted variant nor with kappa_r = 1: every replay would reach no row.
void require_startable(const DemRun& dem, const Variant& predicted, const std::string& params);

}  // namespace iwb::comparison
