#include "calibration/objectives.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <charconv>
#include <cmath>

#include "calibration/calibrate.hpp"
#include "common/errors.hpp"

namespace iwb::calibration {

const char* to_string(ObjectiveGroup g) {
  switch (g) {
    case ObjectiveGroup::kOedometer:
      return "oedometer";
    case ObjectiveGroup::kShear:
      return "shear";
    case ObjectiveGroup::kDilatancy:
      return "dilatancy";
    case ObjectiveGroup::kCyclic:
      return "cyclic";
  }
  return "?";
}

const char* describe(ObjectiveGroup g) {
  switch (g) {
    case ObjectiveGroup::kOedometer:
      return "the oedometer tests' e-paths, row by row";
    case ObjectiveGroup::kShear:
      return "the simple-shear paths, row by row: tau and e (CNL), tau and sigma_n (CV)";
    case ObjectiveGroup::kDilatancy:
      return "per CNL simple-shear test, the peak dilatancy rate d eps_n/d gamma and the total "
             "dilation (e at the end)";
    case ObjectiveGroup::kCyclic:
      return "the cyclic simple-shear paths, row by row: tau and e (CNL), tau and sigma_n (CV)";
  }
  return "?";
}

namespace {

std::string group_names() {
  std::string s;
  for (const auto g : kObjectiveGroups) s += (s.empty() ? "" : ", ") + std::string(to_string(g));
  return s;
}

}  // namespace

ObjectiveGroup objective_group(const std::string& name, const std::string& where) {
  for (const auto g : kObjectiveGroups)
    if (name == to_string(g)) return g;
  throw InputError(fmt::format("{}: unknown objective group '{}'; the groups are {}", where, name,
                               group_names()));
}

ObjectiveWeights parse_weights(const std::vector<std::string>& items) {
  ObjectiveWeights w;
  std::vector<ObjectiveGroup> named;
  for (const auto& item : items) {
    const auto eq = item.find('=');
    if (eq == std::string::npos)
      throw InputError(
          fmt::format("--weight {}: expected GROUP=WEIGHT (groups: {})", item, group_names()));
    const auto g = objective_group(item.substr(0, eq), "--weight " + item);
    if (std::find(named.begin(), named.end(), g) != named.end())
      throw InputError(fmt::format("--weight {}: group '{}' weighted twice", item, to_string(g)));
    named.push_back(g);
    const std::string text = item.substr(eq + 1);
    double v = 0.0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(v) || v < 0.0)
      throw InputError(fmt::format(
          "--weight {}: the weight must be a finite number >= 0 (1 counts each residual as one "
          "measurement)",
          item));
    w[g] = v;
  }
  if (std::all_of(w.weight.begin(), w.weight.end(), [](double v) { return v == 0.0; }))
    throw InputError("--weight: every objective group has weight 0; nothing would be fitted");
  return w;
}

double peak_dilatancy_rate(const std::vector<double>& gamma, const std::vector<double>& e,
                           std::size_t rows) {
  rows = std::min({rows, gamma.size(), e.size()});
  double best = -INFINITY;
  for (std::size_t i = 0; i < rows; ++i) {
    std::size_t lo = i, hi = i;
    while (lo > 0 && gamma[i] - gamma[lo - 1] <= kRateWindowGamma / 2) --lo;
    while (hi + 1 < rows && gamma[hi + 1] - gamma[i] <= kRateWindowGamma / 2) ++hi;
    if (hi - lo < 2) lo = i > 0 ? i - 1 : 0, hi = std::min(rows - 1, lo + 2);
    if (hi - lo < 2) continue;
    double mx = 0.0, my = 0.0;
    const double n = double(hi - lo + 1);
    for (std::size_t j = lo; j <= hi; ++j) mx += gamma[j] / n, my += e[j] / n;
    double sxy = 0.0, sxx = 0.0;
    for (std::size_t j = lo; j <= hi; ++j)
      sxy += (gamma[j] - mx) * (e[j] - my), sxx += (gamma[j] - mx) * (gamma[j] - mx);
    if (sxx > 0.0) best = std::max(best, sxy / sxx / (1.0 + e.front()));
  }
  return best;
}

namespace {

double or_declared(double measured, double declared) {
  return measured > 0.0 ? measured : declared;
}

// The group whose residuals are a test's path, row by row.
ObjectiveGroup path_group(soil_test::SoilTestKind k) {
  switch (k) {
    case soil_test::SoilTestKind::kOedometer:
      return ObjectiveGroup::kOedometer;
    case soil_test::SoilTestKind::kSimpleShear:
      return ObjectiveGroup::kShear;
    case soil_test::SoilTestKind::kCyclicShear:
      return ObjectiveGroup::kCyclic;
  }
  return ObjectiveGroup::kShear;
}

void append_path_residuals(ObjectiveGroup g, const soil_test::SoilTest& t, const Simulated& s,
                           std::vector<double>& r) {
  const double declared_stress = kStressRatioScale * t.sigma0_kPa;
  const double tau_scale = or_declared(t.scales.tau_kPa, declared_stress);
  const double sigma_scale = or_declared(t.scales.sigma_n_kPa, declared_stress);
  const double e_scale = or_declared(t.scales.e, kVoidRatioScale);
  const bool oedometer = t.kind == soil_test::SoilTestKind::kOedometer;
  if (g != path_group(t.kind)) return;
  for (std::size_t i = 1; i < t.rows(); ++i) {
    const bool reached = i < s.rows();
    const auto add = [&](const std::vector<double>& model, double measured, double scale) {
      r.push_back(reached ? (model[i] - measured) / scale : kUnreachedResidual);
    };
    if (oedometer) {
      add(s.e, t.e[i], e_scale);
      continue;
    }
    add(s.tau_kPa, t.tau_kPa[i], tau_scale);
    if (t.boundary == driver::BoundaryKind::kCV)
      add(s.sigma_n_kPa, t.sigma_n_kPa[i], sigma_scale);
    else
      add(s.e, t.e[i], e_scale);
  }
}

void append_dilatancy_residuals(const soil_test::SoilTest& t, const Simulated& s,
                                std::vector<double>& r) {
  if (t.kind != soil_test::SoilTestKind::kSimpleShear || t.boundary != driver::BoundaryKind::kCNL)
    return;
  if (s.rows() < t.rows()) {  // a peak and an end the model did not reach
    r.insert(r.end(), 2, kUnreachedResidual);
    return;
  }
  const double rate_scale = or_declared(t.scales.dilatancy_rate, kDilatancyRateScale);
  const double e_scale = or_declared(t.scales.e, kVoidRatioScale);
  r.push_back((peak_dilatancy_rate(t.control, s.e, s.rows()) -
               peak_dilatancy_rate(t.control, t.e, t.rows())) /
              rate_scale);
  r.push_back((s.e.back() - t.e.back()) / e_scale);
}

}  // namespace

void append_group_residuals(ObjectiveGroup g, const soil_test::SoilTest& t, const Simulated& s,
                            std::vector<double>& r) {
  if (g == ObjectiveGroup::kDilatancy)
    append_dilatancy_residuals(t, s, r);
  else
    append_path_residuals(g, t, s, r);
}

}  // namespace iwb::calibration
