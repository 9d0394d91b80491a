#pragma once
// Stability map (issue 3, item 3): where a model completes an element test, where it stops with a
// domain error (and why), and where the integrator had to cut back, over normal stress, initial
// void ratio, wall roughness, increment size and long cyclic runs, under CNL, CNS and CV.
//
// Every point ends with exactly one outcome of a closed set. A point never crashes the sweep
// (every exception is caught and classified), never hangs (a wall-clock budget per point, checked
// after every increment, plus a cap on substeps per increment) and never reports NaN (a
// non-finite value anywhere in a point's history is itself an outcome, which tests assert never
// occurs).
#include <array>
#include <string>
#include <vector>

#include "driver/control.hpp"
#include "models/registry.hpp"

namespace iwb::analysis {

// Ordered by severity: a cell of the map shows the worst outcome among its points.
enum class Outcome {
  kComplete,           // the whole path was walked
  kDomainError,        // the state left the model's domain (message says where and why)
  kNoConvergence,      // Newton or the substep cap gave up
  kBudgetExceeded,     // the point's wall-clock budget ran out
  kInadmissibleStart,  // the initial state is outside the model's domain (e.g. e0 > e_i)
  kNonFinite,          // a NaN or inf in the history: must never happen
  kOtherError,         // any other exception: must never happen
};
inline constexpr std::array kAllOutcomes{Outcome::kComplete,          Outcome::kDomainError,
                                         Outcome::kNoConvergence,     Outcome::kBudgetExceeded,
                                         Outcome::kInadmissibleStart, Outcome::kNonFinite,
                                         Outcome::kOtherError};
const char* to_string(Outcome o);

enum class PathKind { kMonotonic, kCyclic };

// One point of the sweep.
struct StabilityPoint {
  driver::BoundaryKind boundary = driver::BoundaryKind::kCNL;
  double sigma_n_kPa = 100.0;
  // Where e0 lies, on the sweep's density axis (DensityAxis): for sand the density index
  // e0 = e_d + I (e_i - e_d), so 0 is e_d and 1 is e_i (values outside [0, 1] ask for an
  // inadmissible start on purpose); for clay the overconsolidation ratio (1: normally
  // consolidated); for a state-parameter model psi = e0 - e_c.
  double density = 0.5;
  double kappa_r = 1.0;
  double d_gamma = 1e-4;  // shear strain per increment
  PathKind path = PathKind::kMonotonic;
};

// How the map places e0 at each sigma_n0, chosen by what a model declares: between its limiting
// void ratios when it reports e_d and e_i (sand, Bauer eq. 5.13), else by its overconsolidation
// ratio when it declares an OCR input (clay, seed 6.2: 1 on the asymptotic state boundary surface).
// kStateParameter: by psi = e0 - e_c when it reports only a critical void ratio (Lashkari's model,
// seed 3.3.5: dense below 0, loose above). kNone: a model without a void ratio or an OCR input
// (mc): one level, the map's density axis unused.
enum class DensityAxis { kDensityIndex, kOverconsolidationRatio, kStateParameter, kNone };
DensityAxis density_axis_of(const models::ModelSpec& spec);
const char* column_of(DensityAxis axis);  // "density_index", "OCR"
const char* label_of(DensityAxis axis);   // the axis title of the maps

struct StabilitySweep {
  std::vector<driver::BoundaryKind> boundaries;
  std::vector<double> sigma_n_kPa, density_index, ocr, psi, kappa_r, d_gamma;
  double gamma_total = 0.2;   // monotonic shear ends here ...
  int max_increments = 1000;  // ... or after this many increments, whichever comes first
  int cycles = 3;             // cyclic runs: cycles 0 -> +A -> -A -> 0 at kappa_r = 1
  double cyclic_amplitude = 1e-3;
  int cyclic_per_quarter = 5;    // increments per quarter cycle
  double budget_seconds = 10.0;  // wall clock per point
  int max_substeps = 10000;      // adaptive substeps per increment (bounds one increment)

  // A few points per axis, a few cycles: seconds per model, in the default test suite.
  static StabilitySweep reduced();
  // 1 kPa to 10 MPa, e_d to e_i, kappa_r 0.05 to 1, 1e-6 to 1e-2 per increment, 1000 cycles.
  static StabilitySweep full();
  std::vector<StabilityPoint> points(const models::ModelSpec& spec) const;
  const std::vector<double>& densities(DensityAxis axis) const;
};

// CNS stiffness per unit normal strain as a multiple of sigma_n0, so the spring means the same
// over four decades of stress (at 100 kPa: 1000 kPa, the default job's 1000 kPa/mm at d_s = 1 mm).
inline constexpr double kCnsStiffnessPerSigma = 10.0;

struct StabilityResult {
  StabilityPoint point;
  double e_d = 0.0, e_c = 0.0, e_i = 0.0;  // limits at sigma_n0 (0 if unknown)
  double e0 = 0.0;
  Outcome outcome = Outcome::kOtherError;
  std::string
      reason;  // the class of the stop: "void ratio left (e_d, e_i)", ...; empty if complete
  std::string message;  // the full status or error text
  long increments = 0, increments_planned = 0;
  long rate_evaluations = 0, rejected_substeps = 0, domain_cutbacks = 0;
  double seconds = 0.0;
  double sigma_n_end_kPa = 0.0, tau_end_kPa = 0.0, e_end = 0.0;  // last accepted state
};

// The void-ratio limits (e_d, e_c, e_i) of `model` at sigma_n (compression positive) and K0,
// read from its diagnostics by their declared roles (DiagnosticRole kMinVoidRatio,
// kCriticalVoidRatio, kMaxVoidRatio), not by name; InputError if the model declares none or no
// admissible e exists.
std::array<double, 3> limiting_void_ratios_at(const models::ModelSpec& spec,
                                              const models::Model& model, double sigma_n_kPa,
                                              double K0);

// Runs one point; never throws for anything the point itself causes.
StabilityResult run_stability_point(const models::ModelSpec& spec,
                                    const models::ModelInputs& inputs, const StabilityPoint& point,
                                    const StabilitySweep& sweep);

// Every point of `sweep` for one model.
std::vector<StabilityResult> run_stability_sweep(const models::ModelSpec& spec,
                                                 const models::ModelInputs& inputs,
                                                 const StabilitySweep& sweep);

// The class of a stop from its message (the stable part, without numbers).
std::string classify_reason(const std::string& message);

}  // namespace iwb::analysis
