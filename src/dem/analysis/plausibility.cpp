#include "dem/analysis/plausibility.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

namespace iwb::dem {

namespace {

using Series = std::vector<double>;

PlausibilityCheck check(std::string name, double value, std::string comparison, double limit,
                        std::string measures) {
  const bool passed = comparison == "<="   ? value <= limit
                      : comparison == ">=" ? value >= limit
                                           : value > limit;
  return {std::move(name),    value, std::move(comparison), limit, passed && !std::isnan(value),
          std::move(measures)};
}

double mean(const Series& x) {
  if (x.empty()) return NAN;
  double s = 0.0;
  for (double v : x) s += v;
  return s / double(x.size());
}

// The wall's path along the rows: from the start of shear (u_x = 0) through every row, so that
// the reversals of cyclic shear count.
double travelled(const Series& ux) {
  if (ux.empty()) return NAN;
  double t = std::abs(ux.front());
  for (std::size_t i = 1; i < ux.size(); ++i) t += std::abs(ux[i] - ux[i - 1]);
  return t;
}

double non_finite_cells(const io::CsvTable& t) {
  double n = 0;
  for (const auto& row : t.rows)
    for (double v : row) n += std::isfinite(v) ? 0 : 1;
  return n;
}

double min_of(const Series& x) {
  return x.empty() ? NAN : *std::min_element(x.begin(), x.end());
}

// CNL and CNS: the wall's sigma_n against sigma_n0 + K u_n (K = 0 under CNL), the mean deviation
// over the shear stage relative to sigma_n0. The mean, not the largest excursion: the servo
// corrects the plate continuously and the stiffer grains are, the larger its instantaneous swings
// (data/convergence: up to 1.2 sigma_n0 at stiffness level ~2000) while the mean stays put.
PlausibilityCheck normal_stress_held(const Asked& a, const Series& un, const Series& sigma) {
  const bool cns = a.boundary == driver::BoundaryKind::kCNS;
  Series deviation;
  for (std::size_t i = 0; i < sigma.size(); ++i)
    deviation.push_back(sigma[i] - (a.sigma_n0_kPa + (cns ? a.K_kPa_per_mm * un[i] : 0.0)));
  auto c = check("normal_stress_held", std::abs(mean(deviation)) / a.sigma_n0_kPa,
                 "<=", kNormalStressHeld,
                 cns ? "|mean of sigma_n - (sigma_n0 + K u_n)| over the shear stage / sigma_n0"
                     : "|mean of sigma_n - sigma_n0| over the shear stage / sigma_n0");
  c.warning_limit = kNormalStressWarning;
  return c;
}

// CV: the plate is held, so u_n must stay at zero.
PlausibilityCheck normal_displacement_held(const Asked& a, const Series& un) {
  double worst = un.empty() ? NAN : 0.0;
  for (double u : un) worst = std::max(worst, std::abs(u));
  return check("normal_displacement_held", worst, "<=", kNormalDisplacementHeldD50 * a.d50_mm,
               "largest |u_n| over the shear stage (mm)");
}

}  // namespace

Asked asked_by(const Scene& s) {
  return {s.shear.travel_m() * 1e3,    s.outputs.timeseries_every_m * 1e3,
          2 * s.shear.cycles,          s.boundary.kind,
          s.boundary.sigma_n_Pa / 1e3, s.boundary.K_Pa_per_m * 1e-6,
          s.particles.d50_m * 1e3};
}

std::vector<PlausibilityCheck> plausibility_checks(const Asked& a, const io::CsvTable& ts) {
  const Series ux = ts.values("u_x_mm"), un = ts.values("u_n_mm"), sigma = ts.values("sigma_n_kPa");
  const double travel = travelled(ux), slack = (kTravelRows + a.reversals) * a.row_every_mm;
  std::vector<PlausibilityCheck> checks = {
      check("finite_values", non_finite_cells(ts), "<=", 0.0,
            "cells of timeseries.csv that are not finite numbers"),
      check("rows", double(ts.rows.size()),
            ">=", std::max(double(kMinRows), kMinRowShare * a.travel_mm / a.row_every_mm),
            fmt::format("rows of timeseries.csv (one every {:g} mm of {:g} mm)", a.row_every_mm,
                        a.travel_mm)),
      check("displacement_reached", travel, ">=", a.travel_mm - slack,
            fmt::format("wall displacement along the rows (mm; asked {:g})", a.travel_mm)),
      check("displacement_not_overshot", travel, "<=", a.travel_mm + slack,
            fmt::format("wall displacement along the rows (mm; asked {:g})", a.travel_mm)),
      check("contact_stress_positive", min_of(sigma), ">", 0.0,
            "smallest sigma_n on the wall (kPa)")};
  checks.push_back(a.boundary == driver::BoundaryKind::kCV ? normal_displacement_held(a, un)
                                                           : normal_stress_held(a, un, sigma));
  return checks;
}

std::optional<std::string> failure_reason(const std::vector<PlausibilityCheck>& checks) {
  std::string reason;
  for (const auto& c : checks)
    if (!c.passed)
      reason += fmt::format("{}{} = {:.6g}, must be {} {:.6g} ({})", reason.empty() ? "" : "; ",
                            c.name, c.value, c.comparison, c.limit, c.measures);
  return reason.empty() ? std::nullopt : std::optional<std::string>(reason);
}

std::vector<std::string> plausibility_warnings(const std::vector<PlausibilityCheck>& checks) {
  std::vector<std::string> out;
  for (const auto& c : checks)
    if (c.passed && c.value > c.warning_limit)  // false for a NaN warning level
      out.push_back(fmt::format(
          "plausibility: {} = {:.3g} is within the limit {:g} but above {:g}: the boundary "
          "condition held only loosely ({})",
          c.name, c.value, c.limit, c.warning_limit, c.measures));
  return out;
}

nlohmann::json to_json(const std::vector<PlausibilityCheck>& checks) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& c : checks) {
    nlohmann::json j = {{"name", c.name},   {"value", c.value},   {"comparison", c.comparison},
                        {"limit", c.limit}, {"passed", c.passed}, {"measures", c.measures}};
    if (!std::isnan(c.warning_limit)) j["warning_limit"] = c.warning_limit;
    out.push_back(j);
  }
  return out;
}

}  // namespace iwb::dem
