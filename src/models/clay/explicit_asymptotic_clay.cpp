#include "models/clay/explicit_asymptotic_clay.hpp"

namespace iwb::models {

namespace {

// How far outside the ASBS a start may lie and still be taken for "on it" (as hcc).
constexpr double kAsbsTolerance = 0.01;

double hvorslev_pressure(double e, const ClayParameters& p) {
  return std::exp((p.N - std::log(1.0 + e)) / p.lambda_star);
}

// f_d / f_d^A: 1 on the ASBS, below inside it.
double asbs_ratio(const StressInvariants& s, double e, const ExplicitAsymptoticClayConstants& c) {
  const double omega = c.omega_0 + 0.3 * (s.F_m - c.sin2_phi);
  return std::pow(2.0 * s.mean_stress / hvorslev_pressure(e, c.p), c.alpha_f) /
         (std::pow(2.0, c.alpha_f) * std::pow(1.0 - s.F_m, c.alpha_f / omega));
}

}  // namespace

ExplicitAsymptoticClayConstants make_explicit_asymptotic_clay_constants(const ClayParameters& p,
                                                                        const Roughness& r) {
  const double nu = poisson_ratio_on_wall(p, r);  // Stutz & Masin: nu_r (6.23-6.25)
  const double lk = p.lambda_star + p.kappa_star;
  const double phi = p.phi_c * r.kappa_r;  // eqs. 6.26-6.28 (both schemes: the critical state)
  const double s = std::sin(phi);
  const double a_f = std::sqrt(3.0) * (3.0 - s) / (2.0 * std::sqrt(2.0) * s);  // 6.13 / 6.26
  const double alpha_f =
      std::log((p.lambda_star - p.kappa_star) / lk * (3.0 + a_f * a_f) / (a_f * std::sqrt(3.0))) /
      std::log(2.0);
  const double xi = 1.7 + 3.9 * std::pow(std::sin(p.phi_c), 2);  // 6.20, phi_c unmodified
  return {p,
          nu / (1.0 - 2.0 * nu),
          1.5 * (1.0 / p.lambda_star + 1.0 / p.kappa_star) * (1.0 - 2.0 * nu) / (1.0 + nu),
          alpha_f,
          s * s,
          -std::log(std::cos(phi) * std::cos(phi)) / std::log(2.0),
          xi,
          std::pow(s, xi)};
}

std::string ExplicitAsymptoticClayLaw::domain_violation(const StressInvariants& s, double,
                                                        const Constants&) {
  if (!(s.F_m < 1.0))
    return fmt::format(
        "stress outside Matsuoka-Nakai's cone (F_m = {:.6g}): tension in a direction", s.F_m);
  return {};
}

std::string ExplicitAsymptoticClayLaw::initial_violation(const StressInvariants& s, double e,
                                                         const Constants& c) {
  const double ratio = asbs_ratio(s, e, c);
  if (!(ratio < 1.0 + kAsbsTolerance))
    return fmt::format(
        "outside the asymptotic state boundary surface: e = {:.6g} above the normal compression "
        "line at p = {:.6g} kPa (f_d / f_d^A = {:.4g}); the largest e0 at this stress is {:.4f} "
        "(on the ASBS; or give OCR >= 1)",
        e, s.mean_stress, ratio, void_ratio_at(s, 1.0, c));
  return {};
}

double ExplicitAsymptoticClayLaw::void_ratio_at(const StressInvariants& s, double ocr,
                                                const Constants& c) {
  const double omega = c.omega_0 + 0.3 * (s.F_m - c.sin2_phi);
  const double p_e = ocr * s.mean_stress / std::pow(1.0 - s.F_m, 1.0 / omega);
  return std::exp(c.p.N - c.p.lambda_star * std::log(p_e)) - 1.0;
}

std::vector<NamedValue> ExplicitAsymptoticClayLaw::diagnostics(const StressInvariants& s, double e,
                                                               const Constants& c) {
  return {{"mean_stress_kPa", s.mean_stress},
          {"p_e_kPa", hvorslev_pressure(e, c.p)},
          {"F_m", s.F_m},
          {"f_d_over_f_dA", asbs_ratio(s, e, c)}};
}

}  // namespace iwb::models
