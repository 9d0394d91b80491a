#include "statistics/group_tests.hpp"

#include <algorithm>
#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <numeric>

#include "statistics/t_interval.hpp"

namespace iwb::statistics {

namespace {

double two_sided_p(double t, double dof) {
  const boost::math::students_t dist{dof};
  return 2.0 * boost::math::cdf(boost::math::complement(dist, std::abs(t)));
}

double t_quantile_real(double dof) {
  const boost::math::students_t dist{dof};
  return boost::math::quantile(dist, 0.5 * (1.0 + kConfidence));
}

}  // namespace

Sample describe(const std::vector<double>& v) {
  Sample s;
  s.n = int(v.size());
  if (v.empty()) return s;
  s.mean = std::accumulate(v.begin(), v.end(), 0.0) / double(v.size());
  double ss = 0.0;
  for (double x : v) ss += (x - s.mean) * (x - s.mean);
  s.sd = v.size() > 1 ? std::sqrt(ss / double(v.size() - 1)) : 0.0;
  return s;
}

std::optional<Difference> compare_groups(const Sample& a, const Sample& b) {
  Difference d;
  d.effect = b.mean - a.mean;
  if (a.n >= 2 && b.n == 1) {  // one run against the group's prediction interval
    const double scale = a.sd * std::sqrt(1.0 + 1.0 / a.n);
    if (!(scale > 0.0)) return std::nullopt;
    d.degrees_of_freedom = a.n - 1;
    d.standard_error = scale;
    d.half_width = t_quantile_real(d.degrees_of_freedom) * scale;
    d.p_value = two_sided_p(d.effect / scale, d.degrees_of_freedom);
    d.prediction_interval = true;
    return d;
  }
  if (a.n < 2 || b.n < 2) return std::nullopt;
  const double va = a.sd * a.sd / a.n, vb = b.sd * b.sd / b.n, se2 = va + vb;
  if (!(se2 > 0.0)) return std::nullopt;
  d.degrees_of_freedom = se2 * se2 / (va * va / (a.n - 1) + vb * vb / (b.n - 1));
  d.standard_error = std::sqrt(se2);
  d.half_width = t_quantile_real(d.degrees_of_freedom) * d.standard_error;
  d.p_value = two_sided_p(d.effect / std::sqrt(se2), d.degrees_of_freedom);
  return d;
}

double equivalence_p_value(const Difference& d, double margin) {
  const boost::math::students_t dist{d.degrees_of_freedom};
  // H0 effect <= -margin is rejected by a large t_low, H0 effect >= margin by a small t_high
  const double t_low = (d.effect + margin) / d.standard_error;
  const double t_high = (d.effect - margin) / d.standard_error;
  const double p_low = boost::math::cdf(boost::math::complement(dist, t_low));
  const double p_high = boost::math::cdf(dist, t_high);
  return std::max(p_low, p_high);
}

std::vector<double> benjamini_hochberg(const std::vector<double>& p) {
  const std::size_t m = p.size();
  std::vector<std::size_t> order(m);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return p[i] < p[j]; });
  std::vector<double> adjusted(m);
  double running = 1.0;
  for (std::size_t k = m; k-- > 0;) {
    const std::size_t i = order[k];
    running = std::min(running, p[i] * double(m) / double(k + 1));
    adjusted[i] = running;
  }
  return adjusted;
}

std::optional<int> seeds_to_resolve(const Sample& a, const Sample& b, double effect, double alpha,
                                    int at_most) {
  if (!(std::abs(effect) > 0.0)) return std::nullopt;
  for (int n = 2; n <= at_most; ++n) {
    const Sample sa{n, a.mean, a.sd}, sb{n, b.mean, b.sd};
    const auto d = compare_groups(sa, sb);
    if (d && d->p_value <= alpha) return n;
  }
  return std::nullopt;
}

std::optional<int> seeds_to_show_equal(const Sample& a, const Sample& b, double effect,
                                       double margin, double alpha, int at_most) {
  if (!(std::abs(effect) < margin)) return std::nullopt;
  for (int n = 2; n <= at_most; ++n) {
    const Sample sa{n, a.mean, a.sd}, sb{n, b.mean, b.sd};
    const auto d = compare_groups(sa, sb);
    if (d && equivalence_p_value(*d, margin) <= alpha) return n;
  }
  return std::nullopt;
}

}  // namespace iwb::statistics
