#include "coarse_graining/band_measures.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace iwb::coarse_graining {

namespace {
template <class F>
void each_in(const std::vector<double>& z, Span span, F f) {
  for (std::size_t i = 0; i < z.size(); ++i)
    if (z[i] >= span.lo && z[i] <= span.hi) f(i);
}

// The height where `values` crosses `level` between points i and j, linearly.
double crossing(const std::vector<double>& z, const std::vector<double>& v, std::size_t i,
                std::size_t j, double level) {
  const double t = (level - v[i]) / (v[j] - v[i]);
  return z[i] + t * (z[j] - z[i]);
}
}  // namespace

double mean_over(const std::vector<double>& z, const std::vector<double>& values, Span span) {
  double sum = 0.0;
  int n = 0;
  each_in(z, span, [&](std::size_t i) { sum += values[i], ++n; });
  return n ? sum / n : std::numeric_limits<double>::quiet_NaN();
}

double relative_spread(const std::vector<double>& z, const std::vector<double>& values, Span span) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  each_in(z, span,
          [&](std::size_t i) { lo = std::min(lo, values[i]), hi = std::max(hi, values[i]); });
  return (hi - lo) / std::abs(mean_over(z, values, span));
}

double integral(const std::vector<double>& values, double h) {
  if (values.size() < 2) return 0.0;
  double sum = 0.5 * (values.front() + values.back());
  for (std::size_t i = 1; i + 1 < values.size(); ++i) sum += values[i];
  return sum * h;
}

double peak_width_at_half_maximum(const std::vector<double>& z, const std::vector<double>& rate,
                                  Span search) {
  std::size_t peak = z.size();
  each_in(z, search, [&](std::size_t i) {
    if (peak == z.size() || rate[i] > rate[peak]) peak = i;
  });
  if (peak == z.size() || !(rate[peak] > 0.0)) return 0.0;
  const double half = 0.5 * rate[peak];
  std::size_t lo = peak, hi = peak;
  while (lo > 0 && rate[lo - 1] > half) --lo;
  while (hi + 1 < z.size() && rate[hi + 1] > half) ++hi;
  const double z_lo = lo > 0 ? crossing(z, rate, lo - 1, lo, half) : z[lo];
  const double z_hi = hi + 1 < z.size() ? crossing(z, rate, hi, hi + 1, half) : z[hi];
  return z_hi - z_lo;
}

double velocity_band_width(const std::vector<double>& z, const std::vector<double>& r,
                           double from) {
  double z90 = -1.0, z10 = -1.0;
  for (std::size_t i = 1; i < z.size(); ++i) {
    if (z[i] < from) continue;
    if (z90 < 0.0 && r[i] < 0.9)
      z90 = r[i - 1] >= 0.9 && z[i - 1] >= from ? crossing(z, r, i - 1, i, 0.9) : z[i];
    if (z10 < 0.0 && r[i] < 0.1)
      z10 = r[i - 1] >= 0.1 && z[i - 1] >= from ? crossing(z, r, i - 1, i, 0.1) : z[i];
  }
  return z90 < 0.0 || z10 < 0.0 ? -1.0 : z10 - z90;
}

BinnedProfile bin_means(const std::vector<double>& z, const std::vector<double>& values,
                        double from, double bin) {
  std::vector<double> sum, count;
  for (std::size_t i = 0; i < z.size(); ++i) {
    if (z[i] < from) continue;
    const auto k = std::size_t((z[i] - from) / bin);
    if (k >= sum.size()) sum.resize(k + 1, 0.0), count.resize(k + 1, 0.0);
    sum[k] += values[i], count[k] += 1.0;
  }
  BinnedProfile out;
  for (std::size_t k = 0; k < sum.size(); ++k)
    if (count[k] > 0.0)
      out.z.push_back(from + (double(k) + 0.5) * bin), out.mean.push_back(sum[k] / count[k]);
  return out;
}

}  // namespace iwb::coarse_graining
