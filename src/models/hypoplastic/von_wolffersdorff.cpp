#include "models/hypoplastic/von_wolffersdorff.hpp"

#include <cmath>

namespace iwb::models {

double coefficient_a(CoefficientARule rule, double phi) {
  const double s = std::sin(phi);
  const double t = std::tan(phi);
  switch (rule) {
    case CoefficientARule::kVonWolffersdorff:  // eq. 5.15
      return std::sqrt(3.0) * (3.0 - s) / (2.0 * std::sqrt(2.0) * s);
    case CoefficientARule::kArnoldHerle:  // eq. 5.21; real for tan phi < 2
      if (!(t < 2.0))
        throw InputError(fmt::format(
            "Arnold & Herle's coefficient a (eq. 5.21) needs phi < 63.4 deg; got {:.4g} deg",
            phi * 180.0 / M_PI));
      return 3.0 * std::sqrt(1.0 / (2.0 * t * t) - 1.0 / 8.0) -
             std::sqrt(3.0) / (2.0 * std::sqrt(2.0));
    case CoefficientARule::kGutjahr1D:  // eq. 3.76
      return 1.0 / t;
  }
  return 0.0;
}

namespace {
// Bisection to double precision: both functions are monotonic on their brackets.
template <class F>
double bisect(F f, double lo, double hi) {
  for (int i = 0; i < 200 && hi - lo > 1e-15 * std::abs(hi); ++i)
    (f(0.5 * (lo + hi)) > 0.0 ? hi : lo) = 0.5 * (lo + hi);
  return 0.5 * (lo + hi);
}
constexpr double kDeg = M_PI / 180.0;
}  // namespace

double simple_shear_critical_ratio(double phi_c) {
  const double a = coefficient_a(CoefficientARule::kVonWolffersdorff, phi_c);
  // F(eta) falls and ||T^*|| a rises with eta: one root in (0, 2) where F is real
  return bisect(
      [a](double eta) {
        return std::sqrt(2.0) * eta / 3.0 * a -
               (std::sqrt(1.0 - eta * eta / 4.0) - eta / (2.0 * std::sqrt(3.0)));
      },
      0.0, 2.0);
}

double friction_angle_of_simple_shear_ratio(double eta) {
  const double lo = 1.0 * kDeg, hi = 89.0 * kDeg;
  if (!(eta > simple_shear_critical_ratio(lo) && eta < simple_shear_critical_ratio(hi)))
    throw InputError(
        fmt::format("critical stress ratio tau/sigma_n = {:.6g} is outside ({:.4g}, "
                    "{:.4g}), what phi_c in (1, 89) deg gives in simple shear",
                    eta, simple_shear_critical_ratio(lo), simple_shear_critical_ratio(hi)));
  return bisect([eta](double phi) { return simple_shear_critical_ratio(phi) - eta; }, lo, hi);
}

VonWolffersdorffConstants make_constants(const HypoplasticParameters& p,
                                         const HypoplasticVariant& v, const Roughness& r,
                                         double trace_of_unit) {
  const RoughnessEffect eff = effect_of(r);
  const double phi_r = std::asin(eff.sin_phi_factor * std::sin(p.phi_c));  // eq. 5.37
  const double a = coefficient_a(v.a_rule, phi_r);
  const double alpha = p.alpha * eff.alpha_factor;
  const double fd_ncl = std::pow((p.ei0 - p.ed0) / (p.ec0 - p.ed0), alpha);
  const double bracket = trace_of_unit + a * a - a * std::sqrt(trace_of_unit) * fd_ncl;
  const double barotropy =
      eff.rate_factor * (p.hs / p.n) * std::pow(p.ei0 / p.ec0, p.beta) / bracket;
  return {p, v.lode, a, alpha, barotropy};
}

std::string VonWolffersdorffLaw::domain_violation(const StressInvariants& s, double e,
                                                  const Constants& c) {
  const double pressure = s.pressure;
  const auto lim = limiting_void_ratios(pressure, c.p);
  if (!(e > lim.e_d && e < lim.e_i))
    return fmt::format("e = {:.6g} outside (e_d, e_i) = ({:.6g}, {:.6g}) at -tr T = {:.6g} kPa", e,
                       lim.e_d, lim.e_i, pressure);
  return {};
}

std::vector<NamedValue> VonWolffersdorffLaw::diagnostics(const StressInvariants& s, double /*e*/,
                                                         const Constants& c) {
  const auto lim = limiting_void_ratios(s.pressure, c.p);
  return {{"mean_stress_kPa", s.mean_stress}, {"e_i", lim.e_i}, {"e_c", lim.e_c}, {"e_d", lim.e_d}};
}

}  // namespace iwb::models
