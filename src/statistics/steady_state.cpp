#include "statistics/steady_state.hpp"

#include <cmath>
#include <tuple>
#include <utility>

#include "statistics/t_interval.hpp"

namespace iwb::statistics {

namespace {

// The decay lengths tried: from a fiftieth of the span (a drop within the first rows) to fifty
// spans (a straight line), 400 log-spaced values; the fit's lambda is then known to 2 %, far
// below what the grains' scatter leaves of it.
constexpr int kLengths = 400;
constexpr double kShortest = 0.02, kLongest = 50.0;

struct Linear {
  double steady, amplitude, sse;
};

// y = a + b exp(-(s - s0) / lambda) by least squares in (a, b).
Linear linear_at(const std::vector<double>& s, const std::vector<double>& y, double s0,
                 double lambda) {
  double n = 0, se = 0, see = 0, sy = 0, sey = 0, syy = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] < s0) continue;
    const double e = std::exp(-(s[i] - s0) / lambda);
    n += 1, se += e, see += e * e, sy += y[i], sey += e * y[i], syy += y[i] * y[i];
  }
  const double d = n * see - se * se;
  if (!(d > 0.0)) return {sy / n, 0.0, syy - sy * sy / n};
  const double b = (n * sey - se * sy) / d, a = (sy - b * se) / n;
  // the sum of squares of the fit: syy - a sy - b sey at the least-squares (a, b)
  return {a, b, syy - a * sy - b * sey};
}

// The line through the window's block means (blocks of `block`, the last one taking the rest): its
// drift over the window and that drift's 95 % t half-width; zeros with fewer than 3 blocks.
std::pair<double, double> window_drift(const std::vector<double>& s, const std::vector<double>& y,
                                       double from, double block) {
  const double end = s.back();
  const int blocks = block > 0.0 ? int((end - from) / block + 1e-9) : 0;
  if (blocks < 3) return {0.0, 0.0};
  const double width = (end - from) / blocks;
  std::vector<double> x, m;
  for (int b = 0; b < blocks; ++b) {
    double sum = 0.0;
    int n = 0;
    for (std::size_t i = 0; i < s.size(); ++i)
      if (s[i] >= from + b * width && (s[i] < from + (b + 1) * width || b == blocks - 1))
        sum += y[i], ++n;
    if (n > 0) x.push_back(from + (b + 0.5) * width), m.push_back(sum / n);
  }
  if (x.size() < 3) return {0.0, 0.0};
  const double k = double(x.size());
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < x.size(); ++i) mx += x[i] / k, my += m[i] / k;
  double sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < x.size(); ++i)
    sxx += (x[i] - mx) * (x[i] - mx), sxy += (x[i] - mx) * (m[i] - my);
  const double slope = sxy / sxx;
  double sse = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double r = m[i] - my - slope * (x[i] - mx);
    sse += r * r;
  }
  const double se = std::sqrt(sse / (k - 2.0) / sxx);
  const int dof = int(x.size()) - 2;
  return {slope * (end - from), t_quantile(dof) * se * (end - from)};
}

}  // namespace

double DecayFit::remaining_at(double s, double s0) const {
  if (s < s0) return amplitude;  // before the fitted rows (a peak late in the window): all of it
  return amplitude * std::exp(-(s - s0) / length);
}

std::optional<DecayFit> fit_decay(const std::vector<double>& s, const std::vector<double>& y,
                                  double s0) {
  int rows = 0;
  for (double x : s) rows += x >= s0;
  if (rows < 4 || s.back() <= s0) return std::nullopt;
  DecayFit best;
  best.span = s.back() - s0;
  double best_sse = INFINITY;
  for (int k = 0; k < kLengths; ++k) {
    const double lambda =
        best.span * kShortest * std::pow(kLongest / kShortest, double(k) / (kLengths - 1));
    const Linear l = linear_at(s, y, s0, lambda);
    if (l.sse < best_sse)
      best_sse = l.sse, best.steady = l.steady, best.amplitude = l.amplitude, best.length = lambda;
  }
  return best;
}

std::optional<SteadyState> steady_state(const std::vector<double>& s, const std::vector<double>& y,
                                        double s0, double window_from, double block) {
  const auto fit = fit_decay(s, y, s0);
  double sum = 0.0;
  int n = 0;
  for (std::size_t i = 0; i < s.size(); ++i)
    if (s[i] >= window_from) sum += y[i], ++n;
  if (!fit || n == 0) return std::nullopt;
  SteadyState out;
  out.window_mean = sum / n;
  out.remaining = fit->remaining_at(0.5 * (window_from + s.back()), s0);
  std::tie(out.window_drift, out.window_drift_ci) = window_drift(s, y, window_from, block);
  const double allowed = kSteadyShare * std::abs(out.window_mean);
  const bool trend = std::abs(out.window_drift) > std::max(allowed, out.window_drift_ci);
  out.steady = std::abs(out.remaining) <= allowed && !trend;
  if (fit->resolved()) out.extrapolated = fit->steady;
  return out;
}

std::optional<SteadyState> residual_steady_state(const std::vector<double>& s,
                                                 const std::vector<double>& friction,
                                                 std::size_t peak, double d50_mm) {
  if (s.size() < 2 || peak >= s.size()) return std::nullopt;
  return steady_state(s, friction, s[peak], (1.0 - kResidualWindowShare) * s.back(),
                      kSteadyBlockD50 * d50_mm);
}

}  // namespace iwb::statistics
