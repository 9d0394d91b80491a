#include "cycles/cycle_quantities.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "common/errors.hpp"

namespace iwb::cycles {

namespace {

// A cycle counts when the rows end within this many row spacings before its end.
constexpr double kReachedRowSpacings = 1.5;
constexpr double kFinalShare =
    0.2;  // the post-cyclic "final" friction: its last fifth, as a residual
const double kSecantShares[] = {0.1, 0.5};

// A series as a function of the travelled distance s (non-decreasing), linear between rows and
// constant beyond the ends.
class OfTravel {
 public:
  OfTravel(const std::vector<double>& s, const std::vector<double>& y) : s_(s), y_(y) {}
  double at(double s) const {
    if (s <= s_.front()) return y_.front();
    if (s >= s_.back()) return y_.back();
    const auto hi = std::size_t(std::upper_bound(s_.begin(), s_.end(), s) - s_.begin());
    const std::size_t lo = hi - 1;
    const double w = s_[hi] > s_[lo] ? (s - s_[lo]) / (s_[hi] - s_[lo]) : 1.0;
    return y_[lo] + w * (y_[hi] - y_[lo]);
  }

 private:
  const std::vector<double>& s_;
  const std::vector<double>& y_;
};

struct Rows {
  const Path& path;
  const std::vector<double>& s;
  OfTravel u_x() const { return {s, path.u_x_mm}; }
  OfTravel u_n() const { return {s, path.u_n_mm}; }
  OfTravel sigma_n() const { return {s, path.sigma_n_kPa}; }
  OfTravel tau() const { return {s, path.tau_kPa}; }
  std::optional<double> e_band_at(double at) const {
    if (path.e_band.empty()) return std::nullopt;
    return OfTravel(s, path.e_band).at(at);
  }
  // indices of the rows with s in (from, to]
  std::vector<std::size_t> within(double from, double to) const {
    std::vector<std::size_t> out;
    for (std::size_t i = 0; i < s.size(); ++i)
      if (s[i] > from && s[i] <= to) out.push_back(i);
    return out;
  }
};

void check(const Path& p, const Program& program) {
  const std::size_t n = p.u_x_mm.size();
  if (n < 2) throw InputError(fmt::format("a cyclic path needs at least 2 rows; it has {}", n));
  if (p.travel_mm.size() != n || p.u_n_mm.size() != n || p.sigma_n_kPa.size() != n ||
      p.tau_kPa.size() != n || (!p.e_band.empty() && p.e_band.size() != n))
    throw InputError("the series of a cyclic path differ in length");
  if (!std::is_sorted(p.travel_mm.begin(), p.travel_mm.end()))
    throw InputError("the travel of a cyclic path decreases");
  if (!(program.amplitude_mm > 0.0) || program.cycles < 1)
    throw InputError(fmt::format("not a cyclic program: amplitude {:g} mm, {} cycles",
                                 program.amplitude_mm, program.cycles));
}

// The integral of tau du_x between travelled distances a and b: the rows inside, closed by the
// values interpolated at both ends.
double work_between(const Rows& r, double a, double b) {
  std::vector<double> u{r.u_x().at(a)}, t{r.tau().at(a)};
  for (std::size_t i : r.within(a, b))
    if (r.s[i] < b) u.push_back(r.path.u_x_mm[i]), t.push_back(r.path.tau_kPa[i]);
  u.push_back(r.u_x().at(b)), t.push_back(r.tau().at(b));
  double w = 0.0;
  for (std::size_t i = 1; i < u.size(); ++i) w += 0.5 * (t[i] + t[i - 1]) * (u[i] - u[i - 1]);
  return w;
}

// `direction` is the wall's direction after the reversal (-1 after +A): the secant is positive
// when tau follows the wall.
Reversal reversal(const Rows& r, double s_reversal, double amplitude, int direction) {
  Reversal rev;
  rev.u_x_mm = -direction * amplitude;
  rev.tau_kPa = r.tau().at(s_reversal);
  double* secants[] = {&rev.secant_10_kPa_per_mm, &rev.secant_50_kPa_per_mm};
  for (int k = 0; k < 2; ++k) {
    const double du = kSecantShares[k] * amplitude;
    *secants[k] = direction * (r.tau().at(s_reversal + du) - rev.tau_kPa) / du;
  }
  rev.e_band = r.e_band_at(s_reversal);
  return rev;
}

Cycle cycle(const Rows& r, const Program& program, int c, double sigma_n0, double u_n_before) {
  const double A = program.amplitude_mm, start = (c - 1) * 4.0 * A, end = c * 4.0 * A;
  Cycle out;
  out.number = c;
  int rows = 0;
  for (std::size_t i : r.within(start, end)) {
    const double f = r.path.tau_kPa[i] / r.path.sigma_n_kPa[i];
    out.peak_friction_positive = std::max(out.peak_friction_positive, f);
    out.peak_friction_negative = std::max(out.peak_friction_negative, -f);
    out.mean_friction += std::abs(f), ++rows;
  }
  out.mean_friction = rows > 0 ? out.mean_friction / rows : NAN;
  out.sigma_n_end_kPa = r.sigma_n().at(end);
  out.sigma_n_ratio = out.sigma_n_end_kPa / sigma_n0;
  out.u_n_end_mm = r.u_n().at(end);
  out.u_n_increment_mm = out.u_n_end_mm - u_n_before;
  out.dissipated_energy_J_m2 = work_between(r, start, end);
  out.e_band_end = r.e_band_at(end);
  out.at_plus = reversal(r, start + A, A, -1);
  out.at_minus = reversal(r, start + 3.0 * A, A, +1);
  return out;
}

PostCyclic post_cyclic(const Rows& r, double from) {
  PostCyclic p;
  const auto rows = r.within(from, r.s.back());
  for (std::size_t i : rows) {
    const double f = r.path.tau_kPa[i] / r.path.sigma_n_kPa[i];
    if (f > p.peak_friction) p.peak_friction = f, p.u_x_at_peak_mm = r.path.u_x_mm[i];
  }
  const double final_from = r.s.back() - kFinalShare * (r.s.back() - from);
  double sum = 0.0;
  int n = 0;
  for (std::size_t i : rows)
    if (r.s[i] >= final_from) sum += r.path.tau_kPa[i] / r.path.sigma_n_kPa[i], ++n;
  p.final_friction = n > 0 ? sum / n : NAN;
  p.u_n_change_mm = r.path.u_n_mm.back() - r.u_n().at(from);
  return p;
}

}  // namespace

std::vector<double> travel_at_speed(const std::vector<double>& t_s, double speed_mm_s) {
  std::vector<double> s;
  for (double t : t_s) s.push_back(speed_mm_s * (t - t_s.front()));
  return s;
}

CyclicQuantities cyclic_quantities(const Path& path, const Program& program) {
  check(path, program);
  const Rows r{path, path.travel_mm};
  CyclicQuantities q;
  q.sigma_n0_kPa = path.sigma_n_kPa.front();
  double spacing = 0.0;
  for (std::size_t i = 1; i < r.s.size(); ++i) spacing = std::max(spacing, r.s[i] - r.s[i - 1]);
  const double reached = r.s.back() + kReachedRowSpacings * spacing;
  double u_n_before = path.u_n_mm.front();
  for (int c = 1; c <= program.cycles && c * 4.0 * program.amplitude_mm <= reached; ++c) {
    q.cycles.push_back(cycle(r, program, c, q.sigma_n0_kPa, u_n_before));
    u_n_before = q.cycles.back().u_n_end_mm;
  }
  if (program.post_cyclic_mm > 0.0 && r.s.back() > program.cycles_travel_mm())
    q.post_cyclic = post_cyclic(r, program.cycles_travel_mm());
  return q;
}

nlohmann::json to_json(const CyclicQuantities& q) {
  auto opt = [](const std::optional<double>& v) {
    return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
  };
  auto rev = [&opt](const Reversal& r) {
    return nlohmann::json{{"u_x_mm", r.u_x_mm},
                          {"tau_kPa", r.tau_kPa},
                          {"secant_10_kPa_per_mm", r.secant_10_kPa_per_mm},
                          {"secant_50_kPa_per_mm", r.secant_50_kPa_per_mm},
                          {"e_band", opt(r.e_band)}};
  };
  nlohmann::json cycles = nlohmann::json::array();
  for (const auto& c : q.cycles)
    cycles.push_back(
        {{"cycle", c.number},
         {"peak_friction", std::max(c.peak_friction_positive, c.peak_friction_negative)},
         {"peak_friction_positive", c.peak_friction_positive},
         {"peak_friction_negative", c.peak_friction_negative},
         {"mean_friction", c.mean_friction},
         {"sigma_n_end_kPa", c.sigma_n_end_kPa},
         {"sigma_n_ratio", c.sigma_n_ratio},
         {"u_n_end_mm", c.u_n_end_mm},
         {"u_n_increment_mm", c.u_n_increment_mm},
         {"dissipated_energy_J_m2", c.dissipated_energy_J_m2},
         {"e_band_end", opt(c.e_band_end)},
         {"reversal_at_plus", rev(c.at_plus)},
         {"reversal_at_minus", rev(c.at_minus)}});
  nlohmann::json post = nullptr;
  if (q.post_cyclic)
    post = {{"peak_friction", q.post_cyclic->peak_friction},
            {"u_x_at_peak_mm", q.post_cyclic->u_x_at_peak_mm},
            {"final_friction", q.post_cyclic->final_friction},
            {"u_n_change_mm", q.post_cyclic->u_n_change_mm}};
  return {{"sigma_n0_kPa", q.sigma_n0_kPa}, {"cycles", cycles}, {"post_cyclic", post}};
}

}  // namespace iwb::cycles
