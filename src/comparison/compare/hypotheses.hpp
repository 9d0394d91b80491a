#pragma once
// The assumptions of DEM.md "The assumptions we test", checked over a set of DEM runs that have
// each been compared (`iwb compare --runs`). Pure functions over per-run records: nothing here
// runs a model or reads a file, so the verdict logic is unit-tested on constructed records.
// Every verdict carries its numbers and their scatter, never a bare yes/no.
#include <array>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace iwb::comparison {

// What one compared DEM run contributes: the fit from compare.json, the rest from the DEM's
// summary.json.
struct RunRecord {
  std::string name;  // the DEM run's directory name
  double R_n = 0.0, d50_mm = 0.0;
  double kappa_r_fit = 0.0, sigma_kappa_r_fit = 0.0;  // NLopt fit, Gauss-Newton one sigma
  double d_s_fit_d50 = 0.0;
  double peak_friction = 0.0, residual_friction = 0.0;  // tau/sigma_n
  double dilation_mm = 0.0;                             // u_n at the end of shear
  std::string shear_mode;                               // summary.json's words
  std::optional<double> band_d50;                       // summary.json's wall band
};

// A difference counts as "within scatter" up to this many standard deviations.
inline constexpr double kWithinScatter = 2.0;
// Runs belong to one R_n group when their R_n differ by at most this share of the larger...
inline constexpr double kSameRnRelative = 0.02;
// ...or by this much in absolute terms (so that a numeric R_n of round-off size joins R_n = 0).
inline constexpr double kSameRnAbsolute = 1e-4;
// d50 is a scene input: sets within an R_n group differ in d50 by more than this share.
inline constexpr double kSameD50Relative = 1e-3;
// With a single run at an R_n there is no seed scatter: the fitted kappa_r follows eq. 5.35 when
// within this. 0.05 in kappa_r moves the residual friction of hvwe by about 0.03 (phi_c = 30 deg,
// kappa_r ~ 0.7), the size of the seed-to-seed scatter of DEM friction.
inline constexpr double kKappaSingleRunTolerance = 0.05;
// A difference of fitted kappa_r this small follows eq. 5.35 whatever the scatter (identical seeds
// would otherwise make any difference "many SD"): it moves the friction by ~0.006, below the DEM's
// friction resolution (kFrictionResolution).
inline constexpr double kKappaResolution = 0.01;
// The assumed band thickness of d_s = k d50 (DEM.md), in d50.
inline constexpr double kBandMinD50 = 5.0, kBandMaxD50 = 10.0;
// What the collapse check resolves: friction differences below 0.02 (the summary's former
// steadiness limit on the drift over the last fifth; the steady rule is now
// statistics::residual_steady_state's) and dilations below 0.05 d50 (a twentieth of a grain) are
// within what one run's steady window fluctuates by. Below these a difference collapses whatever
// the seed scatter; with no seed scatter (one run per d50) they are the only criterion.
inline constexpr double kFrictionResolution = 0.02;
inline constexpr double kDilationResolutionD50 = 0.05;

// The two readings of eq. 5.35 (CONVENTIONS.md "Roughness"): lg as printed, and ln.
inline constexpr std::array<double, 2> kGutjahrLogBases = {10.0, 2.718281828459045};

struct Scatter {
  int n = 0;
  double mean = 0.0, sd = 0.0;  // sd over the runs (n - 1 in the denominator), 0 for one run
};
Scatter scatter_of(const std::vector<double>& x);

// --- 1. fitted kappa_r against Gutjahr's kappa_r(R_n), eq. 5.35, for each log base.
struct KappaAgainstFormula {
  double base = 10.0;
  double formula = 0.0;              // eq. 5.35 (floor for a flat wall)
  double difference = 0.0;           // mean fit - formula
  std::optional<double> in_scatter;  // difference / scatter; empty for a single run
  bool follows = false;
};
struct KappaGroup {
  double R_n = 0.0;
  std::vector<std::string> runs;
  Scatter fit;           // fitted kappa_r over the seeds
  double scatter = 0.0;  // sqrt(sd^2 + mean fit sigma^2): seeds and the fit's own uncertainty
  std::array<KappaAgainstFormula, 2> bases;
};
struct KappaCheck {
  std::vector<KappaGroup> groups;
  std::array<std::string, 2> outcome;  // per base: "follows", "partly follows", "misses"
  std::array<std::string, 2> verdict;  // per base, with the numbers
  std::string verdict_overall;         // which base the data favour
};
KappaCheck check_kappa_r(const std::vector<RunRecord>& runs);

// --- 2. band thickness against d_s = k d50, k in [5, 10].
// The seeds of one wall and grain size: their bands with scatter (roughness decides whether the
// wall drags the grains or slips, so a pooled mean mixes different mechanisms).
struct BandGroup {
  double R_n = 0.0, d50_mm = 0.0;
  std::vector<std::string> runs;
  Scatter band;          // over the runs with a wall band
  int inside = 0;        // bands in [kBandMinD50, kBandMaxD50]
  int without_band = 0;  // distributed shear or no wall band
};
struct BandCheck {
  std::vector<std::pair<std::string, double>> bands;  // localised runs: name, wall band in d50
  std::vector<std::string> distributed;               // "distributed shear": no band, no thickness
  std::vector<std::string> without_wall_band;  // other modes with no wall band (plate, no profile)
  Scatter band;
  int inside = 0;       // bands in [kBandMinD50, kBandMaxD50]
  Scatter d_s_fit_d50;  // the fitted d_s of every run, for comparison
  // per R_n and d50, ascending
  std::vector<BandGroup> groups;
  std::string outcome;  // "holds", "holds on average", "does not hold", "not testable"
  std::string verdict;
};
BandCheck check_band_thickness(const std::vector<RunRecord>& runs);

// --- 3. same R_n at different d50: same friction and dilation.
struct D50Set {
  double d50_mm = 0.0;
  Scatter value;
};
struct QuantityCollapse {
  std::string quantity;  // "peak friction", "residual friction", "final u_n / d50"
  std::vector<D50Set> sets;
  double difference = 0.0;           // largest minus smallest set mean
  double pooled_sd = 0.0;            // seed scatter pooled over the d50 sets
  int dof = 0;                       // its degrees of freedom
  std::optional<double> in_scatter;  // difference / standard error of that difference
  double resolution = 0.0;           // used instead when there is no seed scatter
  bool collapses = false;
};
struct CollapseGroup {
  double R_n = 0.0;
  std::vector<double> d50s_mm;
  std::vector<QuantityCollapse> quantities;  // empty when only one d50
  bool collapses = false;
};
struct CollapseCheck {
  std::vector<CollapseGroup> groups;  // every R_n group, testable or not
  std::string outcome;                // "collapses", "does not collapse", "not testable"
  std::string verdict;
};
CollapseCheck check_d50_collapse(const std::vector<RunRecord>& runs);

struct Hypotheses {
  KappaCheck kappa;
  BandCheck band;
  CollapseCheck collapse;
};
Hypotheses check_hypotheses(const std::vector<RunRecord>& runs);

// hypotheses.json: the records, every number, and per check a title, the assumption, the
// verdict and a table of strings ready to print (the report and the text render those tables).
nlohmann::json to_json(const Hypotheses& h, const std::vector<RunRecord>& runs);
// hypotheses.md from that JSON.
std::string to_markdown(const nlohmann::json& hypotheses);

// Groups of indices into `values` whose members are within the tolerance of the group's first
// (smallest) value; groups in ascending order.
std::vector<std::vector<std::size_t>> group_close(const std::vector<double>& values,
                                                  double relative, double absolute);

}  // namespace iwb::comparison
