#pragma once
// Interface models judged on one DEM scene (issue 17, items 2-4; seed 4.3): each model is
// calibrated to the scene's runs, then its model uncertainty against their seed mean
// (model_uncertainty.hpp), its parameter uncertainty about the calibrated set (Latin hypercube
// samples with the COVs of the seed's Table 4.8 and Appendix A), optionally its total Sobol indices
// there, and the global uncertainty sqrt(UA_model^2 + UA_par^2) (ERRATA 16). Every sample is a
// replay along the DEM's own path (comparison/replay/replay.hpp), so the models are judged on
// exactly the test the DEM ran.
//
// Calibration to the runs: kappa_r and d_s as `iwb compare` fits them; d_s where the model's
// response depends on it (not for displacement-based models); and, for a model whose parameters
// have no soil-test calibration (no calibration recipe: Mohr-Coulomb, Clough & Duncan, Mortara,
// Lashkari), every material parameter with a calibration box. A hypoplastic model keeps the set
// calibrated from soil tests: its roughness and shear zone are what the interface adds.
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "assessment/model_uncertainty.hpp"
#include "assessment/sobol.hpp"
#include "assessment/uncertainty.hpp"
#include "comparison/replay/fit.hpp"
#include "comparison/replay/seed_scatter.hpp"
#include "comparison/verdicts/verdicts.hpp"

namespace iwb::assessment {

// The seed mean of a scene's runs as one run: the first run's path and rows (those every seed
// covers), tau, u_n and sigma_n averaged over the seeds; with its scatter.
struct SceneReference {
  comparison::DemRun mean;
  comparison::SeedScatter scatter;
};
SceneReference scene_reference(const std::vector<comparison::DemRun>& runs);

// What a fit to the runs adjusts for `model` (see above), boxes in absolute units.
std::vector<comparison::Unknown> calibration_unknowns(const models::ModelSpec& spec,
                                                      const comparison::DemRun& dem);

// Where the parameter samples spread: the seed's Table 4.8 / Appendix A COVs about the calibrated
// values (its framework: parameters as a lab would know them), or each fitted quantity's own
// Gauss-Newton sigma from the calibration to these runs (the parameters as this scene pins them
// down; a parameter the runs do not identify, or one calibrated from soil tests, is held).
enum class ParameterSpread { kSeedCovs, kFitSigmas };

struct LeagueOptions {
  ParameterSpread spread = ParameterSpread::kSeedCovs;
  // distribution files by name, <table>.toml per parameter table (Table 4.8's COVs):
  // distribution_texts() of a directory or the embedded ones
  std::map<std::string, std::string> distributions;
  int uncertainty_samples = 1000;  // Latin hypercube samples
  int sobol_samples = 0;           // N of the Sobol indices; 0: none
  unsigned seed = 1;
  int threads = 0;  // 0: every core
  std::function<void(long done, long total)> progress;
};

// The parameter uncertainty's quantities, and the Sobol indices': peak and residual tau (kPa), the
// free normal quantity's change at the end and its rate over the last fifth.
const std::vector<std::string>& league_quantities();

struct LeagueEntry {
  std::string model;
  std::string parameters_source;
  std::string status = "assessed";  // or why the model could not be assessed
  comparison::VariantFit fit;
  ResponseCurve reference, fitted;          // the seed mean and the calibrated model's replay
  std::vector<double> band_low, band_high;  // 5 % and 95 % of tau over the samples, per row
  TestUncertainty model_uncertainty;
  std::vector<comparison::Verdict>
      verdicts;  // the calibrated model's quantities of interest against the seed mean
  std::vector<Distribution> distributions;    // about the calibrated values
  std::vector<models::FitParameter> sampled;  // where each distribution's value goes
  std::vector<std::string> held;  // parameters without a distribution: held at their value
  UncertaintyResult parameter_uncertainty;
  std::optional<SobolResult> sobol;
  double ua_par = 0.0;        // CV of the peak shear stress (the seed's Appendix B: one per model)
  double global_shear = 0.0;  // sqrt(UA_model,shear^2 + UA_par^2): the seed's measure
  double global = 0.0;        // sqrt(UA_model,shear^2 + UA_model,normal^2 + UA_par^2)
};

// One model on the scene: calibrated from `start` (its parameter set), then judged.
LeagueEntry assess_model(const SceneReference& reference, const std::string& model,
                         const models::ModelInputs& start, const LeagueOptions& options);

// The free normal quantity of a curve on `dem`'s boundary: u_n - u_n0 (CNL, CNS) or sigma_n -
// sigma_n0 (CV).
ResponseCurve response_curve(const comparison::DemRun& dem, const std::vector<double>& u_x,
                             const std::vector<double>& tau, const std::vector<double>& u_n,
                             const std::vector<double>& sigma_n);

}  // namespace iwb::assessment
