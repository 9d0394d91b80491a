#include "comparison/replay/quantities.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "common/errors.hpp"
#include "comparison/replay/metrics.hpp"

namespace iwb::comparison {

namespace {

std::vector<double> travel(const std::vector<double>& u_x, std::size_t n) {
  std::vector<double> s(n, 0.0);
  for (std::size_t i = 1; i < n; ++i) s[i] = s[i - 1] + std::abs(u_x[i] - u_x[i - 1]);
  return s;
}

// Least-squares slope of y against x over the rows where `in` holds.
std::optional<double> slope(const std::vector<double>& x, const std::vector<double>& y,
                            const std::vector<bool>& in) {
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < in.size(); ++i)
    if (in[i]) n += 1, sx += x[i], sy += y[i], sxx += x[i] * x[i], sxy += x[i] * y[i];
  const double d = n * sxx - sx * sx;
  if (n < 2 || !(d > 0.0)) return std::nullopt;
  return (n * sxy - sx * sy) / d;
}

// The height a band inside the wall zone gained, from the zone's void ratio: the zone is a fixed
// height h above the wall, so what a band inside it gains pushes grains at e0 out of its top, and
// h (1 + e0) / (h - dh) = 1 + e gives dh = h (e - e0) / (1 + e). Averaged over `in` (the last
// fifth: e_band scatters from row to row by ~0.005 as grains cross the zone's top).
std::optional<double> zone_dilation(const Curve& c, std::size_t n, const std::vector<bool>& in) {
  if (c.e_band == nullptr || c.e_band->size() < n || !(c.wall_zone_mm > 0.0)) return std::nullopt;
  const auto& e = *c.e_band;
  double sum = 0.0;
  int count = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (in[i]) sum += c.wall_zone_mm * (e[i] - e[0]) / (1.0 + e[i]), ++count;
  if (count == 0) return std::nullopt;
  return sum / count;
}

// The lowest normal stress on the way less the first row's: what a contractive interface under
// CNS (or CV) loses before it dilates again, which the stress at the end does not show (a loose
// specimen lost 8 % at 1.8 mm and was back at sigma_n0 by 10 mm: data/grains/README.md). Taken
// on a running mean over kLowestWindowRows rows (0.2 mm at the campaigns' 0.02 mm rows): the
// DEM's rows scatter by 0.1-0.4 kPa from the servo, and the least of 500 such rows would lie
// ~1 kPa below the curve they scatter about; a replay's rows are the DEM's, so both are read
// alike.
constexpr std::size_t kLowestWindowRows = 11;

double lowest_change(const std::vector<double>& sigma, std::size_t n) {
  const std::size_t w = std::min(kLowestWindowRows, n);
  double window = 0.0, lowest = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    window += sigma[i];
    if (i >= w) window -= sigma[i - w];
    if (i + 1 >= w) lowest = std::min(lowest, window / double(w) - sigma[0]);
  }
  return lowest;
}

// The friction |tau| / sigma_n along the travel, over the rows every series has, and its peak.
struct FrictionPath {
  std::vector<double> s, friction;
  std::size_t peak = 0;
};

FrictionPath friction_path(const Curve& c) {
  const std::size_t n =
      std::min({c.u_x_mm.size(), c.tau_kPa.size(), c.sigma_n_kPa.size(), c.u_n_mm.size()});
  FrictionPath f;
  if (n < 2) return f;
  f.friction.resize(n);
  for (std::size_t i = 0; i < n; ++i) f.friction[i] = std::abs(c.tau_kPa[i]) / c.sigma_n_kPa[i];
  f.s = travel(c.u_x_mm, n);
  for (std::size_t i = 1; i < n; ++i)
    if (f.friction[i] > f.friction[f.peak]) f.peak = i;
  return f;
}

}  // namespace

const std::vector<QuantityInfo>& quantity_table() {
  static const std::vector<QuantityInfo> t = {
      {"peak_friction", "peak friction tau/sigma_n", "", 0.10, 0.01, false},
      {"u_x_at_peak", "displacement to the peak u_x", "mm", 0.30, 0.05, true},
      {"residual_friction", "residual friction tau/sigma_n (last fifth)", "", 0.05, 0.01, false},
      {"end_of_path_friction", "end-of-path friction |tau|/sigma_n (last fifth of a cyclic run)",
       "", 0.05, 0.01, false},
      {"total_dilation", "total dilation u_n at the end", "mm", 0.20, 0.02, true},
      {"dilation_rate", "dilation rate du_n/du_x (last fifth)", "", 0.20, 0.01, false},
      {"sigma_n_change", "normal stress change at the end", "kPa", 0.20, 1.0, false},
      // floor 5 kPa, a tenth of the 50 kPa the campaigns start from: a dense run's lowest is 0
      // (it gains from the start) where hvwe dips by 0.5-2.8 kPa before it dilates (the CNS cells
      // of data/reference); with a floor of 2 kPa every one of them "broke" on a loss of 1-6 % of
      // sigma_n0, which is not the loss pile fatigue is about
      {"sigma_n_lowest", "lowest normal stress on the way, less the first", "kPa", 0.20, 5.0,
       false},
      {"wall_zone_dilation", "dilation of the wall zone (its void ratio, last fifth)", "mm", 0.20,
       0.02, true},
      // issue 59: the states the residual and the dilation are meant to reach, where a run that
      // stopped on the way resolves them (statistics/steady_state.hpp); judged like the residual
      // and the total dilation, and always shown as extrapolated
      {"critical_state_friction", "critical-state friction tau/sigma_n (extrapolated)", "", 0.05,
       0.01, false},
      {"critical_state_dilation", "critical-state dilation u_n (extrapolated)", "mm", 0.20, 0.02,
       true},
  };
  return t;
}

std::string tolerances_text(const std::vector<std::pair<std::string, double>>& keyed) {
  std::string out;
  for (const auto& [key, t] : keyed)
    out += fmt::format("{}{} {:g} %", out.empty() ? "" : ", ", key, 100.0 * t);
  return out;
}

std::string default_tolerances_text() {
  std::vector<std::pair<std::string, double>> keyed;
  for (const auto& q : quantity_table()) keyed.emplace_back(q.key, q.tolerance);
  return tolerances_text(keyed);
}

const QuantityInfo& quantity(const std::string& key) {
  for (const auto& q : quantity_table())
    if (key == q.key) return q;
  throw std::logic_error(fmt::format("no quantity of interest '{}'", key));
}

std::vector<std::string> judged_quantities(driver::BoundaryKind boundary, bool cyclic) {
  std::vector<std::string> k = {"peak_friction", "u_x_at_peak",
                                cyclic ? "end_of_path_friction" : "residual_friction"};
  if (boundary != driver::BoundaryKind::kCV) k.insert(k.end(), {"total_dilation", "dilation_rate"});
  if (boundary != driver::BoundaryKind::kCNL)
    k.insert(k.end(), {"sigma_n_change", "sigma_n_lowest"});
  if (boundary != driver::BoundaryKind::kCV) k.push_back("wall_zone_dilation");
  if (cyclic) return k;
  k.push_back("critical_state_friction");
  if (boundary != driver::BoundaryKind::kCV) k.push_back("critical_state_dilation");
  return k;
}

bool is_extrapolated(const std::string& key) {
  return key == "critical_state_friction" || key == "critical_state_dilation";
}

std::optional<statistics::SteadyState> friction_steady_state(const Curve& c, double d50_mm) {
  const auto f = friction_path(c);
  if (f.s.size() < 2) return std::nullopt;
  return statistics::residual_steady_state(f.s, f.friction, f.peak, d50_mm);
}

std::map<std::string, std::optional<double>> evaluate_quantities(
    const Curve& c, const std::vector<std::string>& keys) {
  std::map<std::string, std::optional<double>> out;
  for (const auto& k : keys) out[k] = std::nullopt;
  const auto path = friction_path(c);
  const std::size_t n = path.s.size();
  if (n < 2) return out;
  const auto& friction = path.friction;
  const auto& s = path.s;
  std::vector<bool> last(n);
  double sum = 0.0;
  int count = 0;
  for (std::size_t i = 0; i < n; ++i)
    if ((last[i] = s[i] >= (1.0 - kResidualWindowShare) * s.back())) sum += friction[i], ++count;
  const std::size_t peak = path.peak;
  const auto settled = [&](const std::vector<double>& y) -> std::optional<double> {
    const auto fit = statistics::fit_decay(s, y, s[peak]);
    return fit && fit->resolved() ? std::optional<double>(fit->steady) : std::nullopt;
  };
  const std::map<std::string, std::optional<double>> all = {
      {"peak_friction", friction[peak]},
      {"u_x_at_peak", c.u_x_mm[peak]},
      {"residual_friction", count > 0 ? std::optional<double>(sum / count) : std::nullopt},
      {"end_of_path_friction", count > 0 ? std::optional<double>(sum / count) : std::nullopt},
      {"total_dilation", c.u_n_mm[n - 1] - c.u_n_mm[0]},
      {"dilation_rate", slope(s, c.u_n_mm, last)},
      {"sigma_n_change", c.sigma_n_kPa[n - 1] - c.sigma_n_kPa[0]},
      {"sigma_n_lowest", lowest_change(c.sigma_n_kPa, n)},
      {"wall_zone_dilation", zone_dilation(c, n, last)},
      {"critical_state_friction", settled(friction)},
      {"critical_state_dilation",
       settled(std::vector<double>(c.u_n_mm.begin(), c.u_n_mm.begin() + long(n)))},
  };
  for (const auto& k : keys) out[k] = all.at(k);
  return out;
}

}  // namespace iwb::comparison
