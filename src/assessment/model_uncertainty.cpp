#include "assessment/model_uncertainty.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace iwb::assessment {

namespace {

// y at x on a curve (linear between rows); 0 beyond a curve that stopped early, before its first
// row its first value.
double at(const std::vector<double>& xs, const std::vector<double>& ys, double x) {
  if (xs.empty() || x > xs.back()) return 0.0;
  const auto hi = std::lower_bound(xs.begin(), xs.end(), x);
  if (hi == xs.begin()) return ys.front();
  const std::size_t i = std::size_t(hi - xs.begin());
  const double w = xs[i] > xs[i - 1] ? (x - xs[i - 1]) / (xs[i] - xs[i - 1]) : 1.0;
  return ys[i - 1] + w * (ys[i] - ys[i - 1]);
}

// Mean of ys over x >= from on the rows up to `to` (the reference's end); 0 where a curve has none.
double mean_from(const std::vector<double>& xs, const std::vector<double>& ys, double from,
                 double to) {
  double sum = 0.0;
  int n = 0;
  for (std::size_t i = 0; i < xs.size(); ++i)
    if (xs[i] >= from && xs[i] <= to) sum += ys[i], ++n;
  // a model that stopped before `to` averages its missing rows as 0, like at()
  const bool complete = !xs.empty() && xs.back() >= to * (1.0 - 1e-9);
  return n > 0 && complete ? sum / n : 0.0;
}

ObjectivePoint point(const std::string& name, double u_x, double reference, double model,
                     double floor) {
  return {name, u_x, reference, model,
          std::abs(model - reference) / (kNormalQuantile95 * std::max(std::abs(reference), floor))};
}

double norm_of(const std::vector<ObjectivePoint>& points) {
  std::vector<double> v;
  for (const auto& p : points) v.push_back(p.ua);
  return root_sum_square(v);
}

}  // namespace

double root_sum_square(const std::vector<double>& values) {
  double s = 0.0;
  for (double v : values) s += v * v;
  return std::sqrt(s);
}

TestUncertainty model_uncertainty(const ResponseCurve& ref, const ResponseCurve& m,
                                  double normal_floor) {
  if (ref.u_x.size() < 5 || ref.tau.size() != ref.u_x.size() || ref.normal.size() != ref.u_x.size())
    throw std::invalid_argument(
        "a reference curve needs at least 5 rows of u_x, tau and the normal quantity");
  const double u0 = ref.u_x.front(), u_end = ref.u_x.back();
  const double last_fifth = u0 + 0.8 * (u_end - u0);
  const std::size_t ip =
      std::size_t(std::max_element(ref.tau.begin(), ref.tau.end()) - ref.tau.begin());
  const double u_peak = ref.u_x[ip];
  TestUncertainty out;
  out.peaked = u_peak < last_fifth;
  const double tau_floor = 1e-12;  // shear stresses are far from 0 at every point
  if (out.peaked) {
    const double u_h = u0 + 0.5 * (u_peak - u0), u_s = 0.5 * (u_peak + last_fifth);
    out.shear.push_back(
        point("hardening", u_h, at(ref.u_x, ref.tau, u_h), at(m.u_x, m.tau, u_h), tau_floor));
    const double model_peak = m.tau.empty() ? 0.0 : *std::max_element(m.tau.begin(), m.tau.end());
    out.shear.push_back(point("peak", u_peak, ref.tau[ip], model_peak, tau_floor));
    out.shear.push_back(
        point("softening", u_s, at(ref.u_x, ref.tau, u_s), at(m.u_x, m.tau, u_s), tau_floor));
  } else {
    const double u_h = u0 + 0.5 * (u_end - u0);
    out.shear.push_back(
        point("hardening", u_h, at(ref.u_x, ref.tau, u_h), at(m.u_x, m.tau, u_h), tau_floor));
  }
  out.shear.push_back(point("residual", last_fifth, mean_from(ref.u_x, ref.tau, last_fifth, u_end),
                            mean_from(m.u_x, m.tau, last_fifth, u_end), tau_floor));
  out.normal.push_back(point("normal at peak", u_peak, at(ref.u_x, ref.normal, u_peak),
                             at(m.u_x, m.normal, u_peak), normal_floor));
  out.normal.push_back(
      point("normal at end", u_end, ref.normal.back(), at(m.u_x, m.normal, u_end), normal_floor));
  out.shear_norm = norm_of(out.shear);
  out.normal_norm = norm_of(out.normal);
  return out;
}

}  // namespace iwb::assessment
