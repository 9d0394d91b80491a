#include "models/clay/hypoplastic_cam_clay.hpp"

namespace iwb::models {

namespace {

// How far outside the ASBS a start may lie and still be taken for "on it" (a hand-computed e0 of a
// normally consolidated start rounds a few 1e-4 either way).
constexpr double kAsbsTolerance = 0.01;

double hvorslev_pressure(double e, const ClayParameters& p) {
  return std::exp((p.N - std::log(1.0 + e)) / p.lambda_star);
}

// p_e* over the ASBS pressure at the same stress ratio, p (M^2 + eta^2)/M^2: 1 on the ASBS.
double overconsolidation(const StressInvariants& s, double e,
                         const HypoplasticCamClayConstants& c) {
  const double M2 = c.M * c.M;
  return hvorslev_pressure(e, c.p) / (s.mean_stress * (M2 + s.eta2) / M2);
}

}  // namespace

HypoplasticCamClayConstants make_hypoplastic_cam_clay_constants(const ClayParameters& p,
                                                                const Roughness& r) {
  const double sin_phi = std::sin(p.phi_c * r.kappa_r);  // eq. 6.22 (kappa_r = 1: eq. 6.10)
  const double nu = poisson_ratio_on_wall(p, r);         // Stutz & Masin: nu_r (6.23-6.25)
  return {p, 6.0 * sin_phi / (3.0 - sin_phi), nu / (1.0 - 2.0 * nu),
          1.5 * (1.0 / p.lambda_star + 1.0 / p.kappa_star) * (1.0 - 2.0 * nu) / (1.0 + nu)};
}

std::string HypoplasticCamClayLaw::initial_violation(const StressInvariants& s, double e,
                                                     const Constants& c) {
  const double ocr = overconsolidation(s, e, c);
  if (!(ocr > 1.0 - kAsbsTolerance))
    return fmt::format(
        "outside the asymptotic state boundary surface: e = {:.6g} above the normal compression "
        "line at p = {:.6g} kPa, q/p = {:.4g} (OCR = {:.4g}); the largest e0 at this stress is "
        "{:.4f} (on the ASBS; or give OCR >= 1)",
        e, s.mean_stress, std::sqrt(s.eta2), ocr, void_ratio_at(s, 1.0, c));
  return {};
}

double HypoplasticCamClayLaw::void_ratio_at(const StressInvariants& s, double ocr,
                                            const Constants& c) {
  const double M2 = c.M * c.M;
  return std::exp(c.p.N - c.p.lambda_star * std::log(ocr * s.mean_stress * (M2 + s.eta2) / M2)) -
         1.0;
}

std::vector<NamedValue> HypoplasticCamClayLaw::diagnostics(const StressInvariants& s, double e,
                                                           const Constants& c) {
  return {{"mean_stress_kPa", s.mean_stress},
          {"p_e_kPa", hvorslev_pressure(e, c.p)},
          {"OCR", overconsolidation(s, e, c)}};
}

}  // namespace iwb::models
