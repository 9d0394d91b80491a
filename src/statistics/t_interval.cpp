#include "statistics/t_interval.hpp"

#include <boost/math/distributions/students_t.hpp>
#include <cmath>

namespace iwb::statistics {

double t_quantile(int degrees_of_freedom, double confidence) {
  const boost::math::students_t t{double(degrees_of_freedom)};
  return boost::math::quantile(t, 0.5 * (1.0 + confidence));
}

std::optional<double> t_half_width(double sd, int n, double confidence) {
  if (n < 2) return std::nullopt;
  return t_quantile(n - 1, confidence) * sd / std::sqrt(double(n));
}

std::optional<int> values_needed(double sd, double half_width, int at_most, double confidence) {
  if (!(sd > 0.0) || !std::isfinite(sd) || !(half_width > 0.0)) return std::nullopt;
  for (int n = 2; n <= at_most; ++n)
    if (*t_half_width(sd, n, confidence) <= half_width) return n;
  return std::nullopt;
}

}  // namespace iwb::statistics
