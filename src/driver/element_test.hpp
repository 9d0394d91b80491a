#pragma once
// The element-test driver: walks a path increment by increment, solves the mixed control, commits
// accepted increments and records history. It knows a model only through models::Model.
#include <atomic>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "driver/mixed_control.hpp"
#include "driver/path.hpp"
#include "integration/stress_point_integrator.hpp"
#include "models/model.hpp"

namespace iwb::driver {

// Displacement <-> strain through the shear-zone thickness d_s (seed eq. 5.5, CONVENTIONS.md).
enum class ShearStrainMeasure {
  kLinear,   // gamma = u / d_s (default)
  kTangent,  // tan(gamma) = u / d_s as eq. 5.5 prints it
};

struct ShearZone {
  double d_s_mm = 1.0;
  ShearStrainMeasure measure = ShearStrainMeasure::kLinear;

  double gamma_of(double u_mm) const;
  double u_of(double gamma) const;
  double u_n_of(double eps_n) const { return eps_n * d_s_mm; }  // always linear
  std::string describe() const;
};

struct HistoryRow {
  long increment = 0;
  int segment = -1;                                  // -1: the initial state
  double gamma_x = 0.0, gamma_y = 0.0, eps_n = 0.0;  // accumulated
  models::StateVector state;
  int newton_iterations = 0;
  long rate_evaluations = 0;
  long rejected_substeps = 0;
};

struct RunSettings {
  integration::IntegratorSettings integrator;
  MixedControlSettings mixed;
  int output_every = 1;                          // record every n-th increment (and the last)
  const std::atomic<bool>* interrupt = nullptr;  // set from a signal handler: stop cleanly
  // Called after each accepted increment with (done, total): progress reporting.
  std::function<void(long, long)> on_increment;
};

// One cycle of a cyclic path, taken from every increment (not only the recorded rows). Stresses
// geotechnical (compression positive), kPa; tau in the direction of shear; strains accumulated
// from the start of the test.
struct CycleSummary {
  int cycle = 0;
  double tau_max_kPa = -INFINITY;             // largest tau in the cycle (peak towards +A)
  double tau_min_kPa = INFINITY;              // smallest tau (peak towards -A)
  double sigma_n_at_plus_kPa = NAN;           // at the reversal at +A
  double sigma_n_at_minus_kPa = NAN;          // at the reversal at -A
  double eps_n_start = NAN, eps_n_end = NAN;  // normal strain (opening positive)
  double sigma_n_end_kPa = NAN;
  double e_end = NAN;
  bool complete = false;  // the cycle's last increment was reached
};

struct ElementTestResult {
  std::vector<HistoryRow> rows;
  std::vector<CycleSummary> cycles;  // empty for paths without cycles
  std::string status = "complete";   // "complete", "failed: ...", "interrupted at ..."
  integration::IntegrationCounters counters;
  long increments = 0;
  long newton_iterations = 0;
  bool complete() const { return status == "complete"; }
};

// InputError when `model` cannot follow `path` (shear in y for a model with one shear direction);
// run_element_test checks it too, callers that write check it first.
void check_path(const models::Model& model, const Path& path);

// Runs `path` from `initial`. Domain and convergence errors end the run with a "failed: ..."
// status naming the increment, the segment and the state; rows up to the last accepted
// increment are kept, and no row ever holds a non-finite value.
ElementTestResult run_element_test(const models::Model& model, const models::StateVector& initial,
                                   const Path& path, const RunSettings& settings);

}  // namespace iwb::driver
