#include "statistics/local_rate.hpp"

#include <algorithm>
#include <cmath>

#include "statistics/group_tests.hpp"
#include "statistics/t_interval.hpp"

namespace iwb::statistics {

namespace {

// The least-squares slope of the rows with from <= s < to; nullopt with fewer than 3 rows.
std::optional<double> slope_between(const std::vector<double>& s, const std::vector<double>& y,
                                    double from, double to) {
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < s.size(); ++i)
    if (s[i] >= from && s[i] < to)
      n += 1, sx += s[i], sy += y[i], sxx += s[i] * s[i], sxy += s[i] * y[i];
  const double d = n * sxx - sx * sx;
  if (n < 3 || !(d > 0.0)) return std::nullopt;
  return (n * sxy - sx * sy) / d;
}

}  // namespace

std::optional<LocalRate> local_rate(const std::vector<double>& s, const std::vector<double>& y,
                                    double centre, double half_span, double block) {
  if (s.size() < 2 || !(block > 0.0) || !(half_span > 0.0)) return std::nullopt;
  const double length = std::min(2.0 * half_span, s.back() - s.front());
  LocalRate out;
  out.from = std::clamp(centre - half_span, s.front(), s.back() - length);
  out.to = out.from + length;
  const int blocks = int(length / block + 1e-9);
  if (blocks < 3) return std::nullopt;
  const double width = length / blocks;
  std::vector<double> slopes;
  for (int b = 0; b < blocks; ++b) {
    // the last block keeps its last row (to = the span's end, inclusive)
    const double hi =
        b == blocks - 1 ? std::nextafter(out.to, INFINITY) : out.from + (b + 1) * width;
    const auto k = slope_between(s, y, out.from + b * width, hi);
    if (!k) return std::nullopt;
    slopes.push_back(*k);
  }
  const Sample sample = describe(slopes);
  out.rate = sample.mean;
  out.blocks = sample.n;
  out.half_width = t_half_width(sample.sd, sample.n).value_or(0.0);
  return out;
}

}  // namespace iwb::statistics
