#include "statistics/equal_scatter.hpp"

#include <algorithm>
#include <boost/math/distributions/fisher_f.hpp>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace iwb::statistics {

namespace {

double mean(const std::vector<double>& v) {
  return std::accumulate(v.begin(), v.end(), 0.0) / double(v.size());
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

void require_groups(const std::vector<std::vector<double>>& groups, std::size_t at_least) {
  if (groups.size() < at_least)
    throw std::invalid_argument("equal-scatter statistics need at least two groups");
  for (const auto& g : groups)
    if (g.size() < 2)
      throw std::invalid_argument("a group of fewer than two values has no scatter");
}

}  // namespace

EqualScatterTest brown_forsythe(const std::vector<std::vector<double>>& groups) {
  require_groups(groups, 2);
  std::vector<std::vector<double>> z;
  for (const auto& g : groups) {
    const double m = median(g);
    std::vector<double> zi;
    for (const double y : g) zi.push_back(std::abs(y - m));
    z.push_back(zi);
  }
  EqualScatterTest t;
  t.groups = int(groups.size());
  double all = 0.0;
  for (const auto& zi : z)
    t.values += int(zi.size()), all += std::accumulate(zi.begin(), zi.end(), 0.0);
  const double grand = all / t.values;
  double between = 0.0, within = 0.0;
  for (const auto& zi : z) {
    const double m = mean(zi);
    between += double(zi.size()) * (m - grand) * (m - grand);
    for (const double x : zi) within += (x - m) * (x - m);
  }
  const int k = t.groups, n = t.values;
  if (!(within > 0.0)) return t;  // no spread within any group: nothing to test against
  t.statistic = double(n - k) / double(k - 1) * between / within;
  t.p_value = boost::math::cdf(
      boost::math::complement(boost::math::fisher_f(double(k - 1), double(n - k)), t.statistic));
  return t;
}

PooledSd pooled_sd(const std::vector<std::vector<double>>& groups) {
  require_groups(groups, 1);
  double squares = 0.0;
  PooledSd out;
  for (const auto& g : groups) {
    const double m = mean(g);
    for (const double x : g) squares += (x - m) * (x - m);
    out.degrees_of_freedom += int(g.size()) - 1;
  }
  out.sd = std::sqrt(squares / out.degrees_of_freedom);
  return out;
}

}  // namespace iwb::statistics
