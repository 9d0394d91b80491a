#include "analysis/stability.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>

#include "common/errors.hpp"
#include "driver/element_test.hpp"

namespace iwb::analysis {

using driver::BoundaryKind;
using Clock = std::chrono::steady_clock;

const char* to_string(Outcome o) {
  switch (o) {
    case Outcome::kComplete:
      return "complete";
    case Outcome::kDomainError:
      return "domain error";
    case Outcome::kNoConvergence:
      return "no convergence";
    case Outcome::kBudgetExceeded:
      return "budget exceeded";
    case Outcome::kInadmissibleStart:
      return "inadmissible start";
    case Outcome::kNonFinite:
      return "non-finite value";
    case Outcome::kOtherError:
      return "other error";
  }
  return "?";
}

StabilitySweep StabilitySweep::reduced() {
  StabilitySweep s;
  s.boundaries = {BoundaryKind::kCNL, BoundaryKind::kCNS, BoundaryKind::kCV};
  s.sigma_n_kPa = {1.0, 100.0, 1e4};
  s.density_index = {0.02, 0.3, 0.98};
  s.ocr = {1.0, 2.0, 8.0};
  s.psi = {-0.2, 0.0, 0.1};
  s.kappa_r = {0.05, 1.0};
  s.d_gamma = {1e-6, 1e-2};
  s.gamma_total = 0.1;
  s.max_increments = 50;
  s.cycles = 3;
  s.budget_seconds = 5.0;
  return s;
}

StabilitySweep StabilitySweep::full() {
  StabilitySweep s;
  s.boundaries = {BoundaryKind::kCNL, BoundaryKind::kCNS, BoundaryKind::kCV};
  s.sigma_n_kPa = {1.0, 10.0, 100.0, 1e3, 1e4};
  s.density_index = {0.01, 0.25, 0.5, 0.75, 0.99};
  s.ocr = {1.0, 1.5, 2.0, 4.0, 10.0};
  s.psi = {-0.3, -0.15, 0.0, 0.05, 0.15};
  s.kappa_r = {0.05, 0.25, 0.5, 1.0};
  s.d_gamma = {1e-6, 1e-5, 1e-4, 1e-3, 1e-2};
  s.gamma_total = 0.2;
  s.max_increments = 1000;
  s.cycles = 1000;
  s.budget_seconds = 10.0;
  return s;
}

namespace {
// The declared diagnostic of `role` (its index in the model's diagnostics), or -1.
int diagnostic_index(const models::ModelSpec& spec, models::DiagnosticRole role) {
  const auto& d = spec.declaration.diagnostics;
  for (std::size_t i = 0; i < d.size(); ++i)
    if (d[i].role == role) return int(i);
  return -1;
}
}  // namespace

DensityAxis density_axis_of(const models::ModelSpec& spec) {
  // a model with the density limits e_d and e_i is placed by its density index
  const bool has_limits = diagnostic_index(spec, models::DiagnosticRole::kMinVoidRatio) >= 0 &&
                          diagnostic_index(spec, models::DiagnosticRole::kMaxVoidRatio) >= 0;
  if (!has_limits && models::find_initial_input(spec.declaration.initial, "OCR"))
    return DensityAxis::kOverconsolidationRatio;
  if (!has_limits && diagnostic_index(spec, models::DiagnosticRole::kCriticalVoidRatio) >= 0)
    return DensityAxis::kStateParameter;
  if (!has_limits && spec.declaration.layout.void_ratio < 0) return DensityAxis::kNone;
  return DensityAxis::kDensityIndex;
}

const char* column_of(DensityAxis axis) {
  return axis == DensityAxis::kOverconsolidationRatio ? "OCR"
         : axis == DensityAxis::kStateParameter       ? "psi"
         : axis == DensityAxis::kNone                 ? "density_none"
                                                      : "density_index";
}

const char* label_of(DensityAxis axis) {
  return axis == DensityAxis::kOverconsolidationRatio ? "overconsolidation ratio OCR"
         : axis == DensityAxis::kStateParameter       ? "state parameter psi = e0 - e_c"
         : axis == DensityAxis::kNone                 ? "no density (the model has no void ratio)"
                                                      : "density index I = (e0 - e_d)/(e_i - e_d)";
}

const std::vector<double>& StabilitySweep::densities(DensityAxis axis) const {
  static const std::vector<double> one_level{0.0};
  return axis == DensityAxis::kOverconsolidationRatio ? ocr
         : axis == DensityAxis::kStateParameter       ? psi
         : axis == DensityAxis::kNone                 ? one_level
                                                      : density_index;
}

std::vector<StabilityPoint> StabilitySweep::points(const models::ModelSpec& spec) const {
  // A continuum model ignores kappa_r: one value instead of identical copies.
  const std::vector<double> kappas = spec.uses_roughness ? kappa_r : std::vector<double>{1.0};
  std::vector<StabilityPoint> out;
  for (auto bc : boundaries)
    for (double s : sigma_n_kPa)
      for (double i : densities(density_axis_of(spec))) {
        for (double k : kappas)
          for (double dg : d_gamma) out.push_back({bc, s, i, k, dg, PathKind::kMonotonic});
        out.push_back({bc, s, i, 1.0, cyclic_amplitude / cyclic_per_quarter, PathKind::kCyclic});
      }
  return out;
}

namespace {

// The value of the diagnostic declared with `role` (diagnostics come in their declared order).
double by_role(const models::ModelSpec& spec, const std::vector<models::NamedValue>& values,
               models::DiagnosticRole role) {
  const int i = diagnostic_index(spec, role);
  return i >= 0 && std::size_t(i) < values.size() ? values[std::size_t(i)].value : NAN;
}

// Any void ratio the model admits at this stress: the limits scale together with pressure
// (Bauer, eq. 5.13), so a geometric scan with a ratio below e_i/e_d lands inside them.
models::StateVector any_admissible_state(const models::Model& m, double sigma_n, double K0) {
  constexpr double kFirst = 1e-3, kLast = 20.0, kRatio = 1.1;
  for (double e = kFirst; e < kLast; e *= kRatio) {
    try {
      return m.initial_state({sigma_n, K0, e});
    } catch (const InputError&) {
    }
  }
  throw InputError(
      fmt::format("{}: no void ratio in [{:g}, {:g}] is admissible at sigma_n = {:g} kPa", m.name(),
                  kFirst, kLast, sigma_n));
}

driver::Path path_of(const StabilityPoint& p, const StabilitySweep& sw) {
  driver::BoundaryCondition bc{p.boundary, kCnsStiffnessPerSigma * p.sigma_n_kPa};
  if (p.path == PathKind::kCyclic)
    return driver::cyclic_path(bc, sw.cyclic_amplitude, sw.cycles, driver::ShearDirection::kX,
                               sw.cyclic_per_quarter);
  const int n =
      std::max(1, std::min(sw.max_increments, int(std::lround(sw.gamma_total / p.d_gamma))));
  return driver::monotonic_path(bc, n * p.d_gamma, driver::ShearDirection::kX, n);
}

Outcome outcome_of_status(const std::string& status) {
  if (status == "complete") return Outcome::kComplete;
  if (status.rfind("failed: domain error", 0) == 0) return Outcome::kDomainError;
  if (status.rfind("failed: no convergence", 0) == 0) return Outcome::kNoConvergence;
  if (status.rfind("interrupted", 0) == 0) return Outcome::kBudgetExceeded;
  return Outcome::kOtherError;
}

bool finite_history(const models::Model& m, const driver::ElementTestResult& r) {
  for (const auto& row : r.rows) {
    const auto st = m.stress(row.state);
    if (!row.state.allFinite() || !std::isfinite(st.sigma_n) || !std::isfinite(st.tau_x) ||
        !std::isfinite(row.eps_n))
      return false;
  }
  return true;
}

// Walks the point's path under a wall-clock budget: the driver's interrupt flag is raised from
// the per-increment callback, so the run stops cleanly after the increment in progress.
void walk(const models::Model& m, const models::StateVector& s0, const StabilityPoint& p,
          const StabilitySweep& sw, StabilityResult& out) {
  const auto path = path_of(p, sw);
  std::atomic<bool> over_budget{false};
  const auto t0 = Clock::now();
  driver::RunSettings rs;
  rs.integrator.max_substeps = sw.max_substeps;
  rs.interrupt = &over_budget;
  rs.on_increment = [&](long, long) {
    if (std::chrono::duration<double>(Clock::now() - t0).count() > sw.budget_seconds)
      over_budget = true;
  };
  const auto r = driver::run_element_test(m, s0, path, rs);
  out.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  for (const auto& seg : path) out.increments_planned += seg.increments;
  out.increments = r.increments;
  out.rate_evaluations = r.counters.rate_evaluations;
  out.rejected_substeps = r.counters.rejected_substeps;
  out.domain_cutbacks = r.counters.domain_cutbacks;
  out.outcome = finite_history(m, r) ? outcome_of_status(r.status) : Outcome::kNonFinite;
  out.message = out.outcome == Outcome::kBudgetExceeded
                    ? fmt::format("budget of {:g} s exceeded; {}", sw.budget_seconds, r.status)
                    : r.status;
  const auto st = m.stress(r.rows.back().state);
  out.sigma_n_end_kPa = st.sigma_n;
  out.tau_end_kPa = st.tau_x;
  out.e_end = m.void_ratio(r.rows.back().state);
}

// Builds the model, finds the limits and the start; throws InputError if the start is refused.
models::StateVector prepare(const models::ModelSpec& spec, const models::Model& m,
                            const models::ModelInputs& in, const StabilityPoint& p,
                            StabilityResult& out) {
  const double K0 = models::offer(spec, in, {}).K0;
  if (density_axis_of(spec) == DensityAxis::kNone) {  // no void ratio to place
    out.e_d = out.e_c = out.e_i = out.e0 = NAN;
    return m.initial_state({p.sigma_n_kPa, K0, NAN});
  }
  if (density_axis_of(spec) == DensityAxis::kOverconsolidationRatio) {
    // the model turns the OCR into e0 (its asymptotic state boundary surface) or into its
    // preconsolidation (modified Cam clay, whose e0 is a default label); no e_d, e_i
    out.e_d = out.e_c = out.e_i = NAN;
    const auto s0 = m.initial_state(
        models::offer(spec, in, {{"sigma_n_kPa", p.sigma_n_kPa}, {"K0", K0}, {"OCR", p.density}}));
    out.e0 = m.void_ratio(s0);
    return s0;
  }
  if (density_axis_of(spec) == DensityAxis::kStateParameter) {
    // e_c at sigma_n0 from the model's own diagnostic (of any admissible start), then e0 = e_c +
    // psi
    out.e_d = out.e_i = NAN;
    const auto probe = m.initial_state({p.sigma_n_kPa, K0, 1.0});
    out.e_c = by_role(spec, m.diagnostics(probe), models::DiagnosticRole::kCriticalVoidRatio);
    out.e0 = out.e_c + p.density;
    return m.initial_state({p.sigma_n_kPa, K0, out.e0});
  }
  const auto lim = limiting_void_ratios_at(spec, m, p.sigma_n_kPa, K0);
  out.e_d = lim[0];
  out.e_c = lim[1];
  out.e_i = lim[2];
  out.e0 = out.e_d + p.density * (out.e_i - out.e_d);
  return m.initial_state({p.sigma_n_kPa, K0, out.e0});
}

void fail(StabilityResult& out, Outcome o, const std::string& message) {
  out.outcome = o;
  out.message = message;
}

}  // namespace

std::array<double, 3> limiting_void_ratios_at(const models::ModelSpec& spec, const models::Model& m,
                                              double sigma_n, double K0) {
  using models::DiagnosticRole;
  const auto d = m.diagnostics(any_admissible_state(m, sigma_n, K0));
  const std::array<double, 3> lim{by_role(spec, d, DiagnosticRole::kMinVoidRatio),
                                  by_role(spec, d, DiagnosticRole::kCriticalVoidRatio),
                                  by_role(spec, d, DiagnosticRole::kMaxVoidRatio)};
  if (!std::isfinite(lim[0]) || !std::isfinite(lim[2]))
    throw InputError(
        fmt::format("{} reports no limiting void ratios (e_d, e_i); the stability map "
                    "needs them to place e0",
                    m.name()));
  return lim;
}

StabilityResult run_stability_point(const models::ModelSpec& spec,
                                    const models::ModelInputs& inputs, const StabilityPoint& p,
                                    const StabilitySweep& sw) {
  StabilityResult out;
  out.point = p;
  try {
    models::ModelInputs in = inputs;
    in.roughness.kappa_r = p.kappa_r;
    const auto model = spec.make(in);
    models::StateVector s0;
    try {
      s0 = prepare(spec, *model, in, p, out);
    } catch (const InputError& e) {
      fail(out, Outcome::kInadmissibleStart, e.what());
    }
    out.sigma_n_end_kPa = p.sigma_n_kPa;
    out.e_end = out.e0;
    if (out.outcome != Outcome::kInadmissibleStart) walk(*model, s0, p, sw, out);
  } catch (const std::exception& e) {
    fail(out, Outcome::kOtherError, e.what());
  }
  if (out.outcome != Outcome::kComplete) out.reason = classify_reason(out.message);
  return out;
}

std::vector<StabilityResult> run_stability_sweep(const models::ModelSpec& spec,
                                                 const models::ModelInputs& inputs,
                                                 const StabilitySweep& sweep) {
  std::vector<StabilityResult> out;
  for (const auto& p : sweep.points(spec))
    out.push_back(run_stability_point(spec, inputs, p, sweep));
  return out;
}

std::string classify_reason(const std::string& message) {
  // The stable fragments of the messages thrown by the models, the integrator and the driver,
  // most specific first; the step-size underflow names its last rejection, so it is prefixed.
  static const std::vector<std::pair<std::string, std::string>> kClasses{
      {"budget of", "wall-clock budget"},
      {"not admissible", "initial state outside the domain"},
      {"no void ratio", "no admissible void ratio at this stress"},
      {"outside (e_d, e_i)", "void ratio left (e_d, e_i)"},
      {"at or below e_d", "void ratio at e_d"},
      {"contact lost", "contact lost (no compression)"},
      {"Matsuoka-Nakai", "stress ratio outside the Matsuoka-Nakai cone"},
      {"not finite", "non-finite state"},
      {"more than", "substep cap per increment"},
      {"Newton did not reach", "Newton did not converge"},
      {"normal row has slope", "normal row lost its slope"},
  };
  std::string prefix;
  if (message.find("substep below") != std::string::npos) prefix = "substep underflow: ";
  for (const auto& [fragment, cls] : kClasses)
    if (message.find(fragment) != std::string::npos) return prefix + cls;
  return prefix.empty() ? "unclassified" : "substep underflow";
}

}  // namespace iwb::analysis
