#pragma once
// The element tests of the clay studies (seed 6.4, chapter 8) as data: which model, set, boundary,
// stress, density, roughness and path, written out as the element-test TOML that `iwb element`
// reads.
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace iwb::studies {

struct ClayCase {
  std::string name;        // run directory and key: "cv100_hce"
  std::string model;       // hcc, hce, hcc3d, hce3d, hce-igs
  std::string parameters;  // a shipped set (data/params/)
  std::string boundary;    // CNL, CNS, CV
  double sigma_n_kPa = 100.0;
  double OCR = 1.0;      // the seed's tests start normally consolidated (ERRATA 15: N at p = 1 kPa)
  double K_kPa = 0.0;    // CNS: per unit normal strain (the seed's "K of 100 kPa", d_s = 1 mm)
  double kappa_r = 1.0;  // interface models only
  std::string scheme = {};  // empty: the model's own
  bool cyclic = false;      // cycles of +-kCyclicAmplitude instead of monotonic shear
  double e0 = NAN;  // given instead of OCR where the study needs one void ratio for every model
  double K0 = NAN;  // NaN: the model's default
  double gamma =
      0.2;  // monotonic paths: the shear strain reached, in kIncrementsPerUnitGamma steps per unit
  // Further [initial] inputs the model declares (hcthm's T_K, s_kPa), and keys of the parameter set
  // changed for this case ("thermo_hydro.n_t"): the run reads a copy of the set with them.
  std::map<std::string, double> initial_inputs = {};
  std::map<std::string, double> parameter_changes = {};
  // The seed's own start, though it lies outside the model's state boundary surface: run, with
  // the model's warning in the run's manifest and the study's output, where it would be refused.
  bool seed_start_outside = false;
};

// The name of the parameter file a case runs with: its set, or the set with its changes.
std::string parameter_file_name(const ClayCase& c);

// Monotonic shear to gamma (0.2 by default) in increments of 1e-4
// (data/tests/hce_cv_table_6_1.toml); cyclic paths of 10 cycles of +-0.001 in 50 increments a
// quarter: Table 6.4 gives no amplitude; 10 R keeps the cycles in the intergranular strain's range,
// steps of R/5 resolve it.
inline constexpr int kIncrementsPerUnitGamma = 10000;
inline constexpr double kCyclicAmplitude = 0.001;
inline constexpr int kCycles = 10;
inline constexpr int kIncrementsPerQuarter = 50;

// What a case's run gives the study: per recorded row, contract units (compression positive;
// eps_n opening positive, as the history).
struct ClayCurve {
  std::string status;
  std::vector<double> gamma, eps_n, tau, sigma_n;
  std::vector<std::string> warnings;  // the run manifest's

  double end_tau() const { return tau.back(); }
  double max_tau() const;
  // tau at the first row where gamma reaches `g` (monotonic paths), NaN if it never does
  double tau_at(double g) const;
  nlohmann::json end_values() const;  // gamma, eps_n, tau, sigma_n of the last row
};

// Every case of the study, in the order they run.
std::vector<ClayCase> clay_cases();

// The element-test file of a case; `parameters` is the path of its parameter set.
std::string element_test_text(const ClayCase& c, const std::string& parameters);

}  // namespace iwb::studies
