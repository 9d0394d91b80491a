#pragma once
// Masin's (2012) hypoplastic Cam clay (seed 6.2.2, eqs. 6.5-6.10, ERRATA 13), written once over an
// algebra policy like von Wolffersdorff's law, tension positive:
//
//   T_rate = f_s L : D - (f_d / f_d^A) (f_s L + T x 1 / lambda*) : d ||D||
//   f_s L : X = f_s [X + nu / (1 - 2 nu) tr(X) 1],   f_s = (3p/2) (1/lambda* + 1/kappa*) (1 -
//   2nu)/(1 + nu) f_d / f_d^A = (p / p_e*) (M^2 + eta^2) / M^2,     p_e* = exp[(N - ln(1+e)) /
//   lambda*] kPa d ~ 3 T* + (eta^2 - M^2) (p/3) 1 (normal to the modified Cam clay ellipse),  eta =
//   q / p
//
// The ASBS is modified Cam clay's ellipse p (M^2 + eta^2)/M^2 = p_e*: on it f_d / f_d^A = 1, and
// on the isotropic normal compression line the rate gives d ln(1+e) = -lambda* d ln p; at the
// critical state (eta = M) d is deviatoric and p_e* = 2p. Rough walls (Arnold & Herle's scheme
// for clay, eq. 6.22): M from phi_c kappa_r.
#include <fmt/core.h>

#include <cmath>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "common/scalar.hpp"
#include "models/clay/parameters.hpp"
#include "models/hypoplastic/von_wolffersdorff.hpp"
#include "models/roughness/roughness.hpp"

namespace iwb::models {

struct HypoplasticCamClayConstants {
  ClayParameters p;
  double M;         // critical stress ratio q/p (eq. 6.22; 6.10 for kappa_r = 1)
  double nu_ratio;  // nu / (1 - 2 nu)
  double fs_per_p;  // f_s / p = (3/2) (1/lambda* + 1/kappa*) (1 - 2 nu)/(1 + nu)  (eq. 6.9)
};

HypoplasticCamClayConstants make_hypoplastic_cam_clay_constants(const ClayParameters& p,
                                                                const Roughness& r);

// The rate split as L : D + N ||D||, for the intergranular strain (as HypoplasticTangent).
template <class Ops, class S>
struct ClayTangent {
  using Tensor = typename Ops::template Tensor<S>;
  S f_s;
  double nu_ratio;
  Tensor N;

  Tensor L(const Tensor& X) const {  // f_s L : X, isotropic elasticity (eq. 6.6)
    return f_s * (X + (nu_ratio * Ops::trace(X)) * Ops::template unit<S>());
  }
};

// The frame both of Masin's clay laws share (eqs. 6.3-6.6, ERRATA 13): L and f_s, and
// N = -(f_d / f_d^A) (f_s L + T x 1 / lambda*) : d for the law's own f_d / f_d^A and direction d.
template <class Ops, class S>
ClayTangent<Ops, S> masin_tangent(const typename Ops::template Tensor<S>& T, const S& f_s,
                                  const S& f_d_ratio, const typename Ops::template Tensor<S>& d,
                                  double nu_ratio, double lambda_star) {
  using Tensor = typename Ops::template Tensor<S>;
  const ClayTangent<Ops, S> h{f_s, nu_ratio, Tensor()};
  const Tensor A_d = h.L(d) + (Ops::trace(d) / lambda_star) * T;  // A : d, eq. 6.4 (ERRATA 13)
  return {f_s, nu_ratio, -f_d_ratio * A_d};
}

struct HypoplasticCamClayLaw {
  using Constants = HypoplasticCamClayConstants;

  template <class Ops, class S>
  static ClayTangent<Ops, S> tangent(const typename Ops::template Tensor<S>& T, const S& e,
                                     const Constants& c) {
    using std::exp;
    using std::log;
    using Tensor = typename Ops::template Tensor<S>;
    const Tensor unit = Ops::template unit<S>();
    const S p = -compressed_trace<Ops, S>(T) / 3.0;
    const Tensor deviator = T + p * unit;
    const S eta2 = 1.5 * Ops::contract(deviator, deviator) / (p * p);
    const double M2 = c.M * c.M;
    const S f_s = c.fs_per_p * p;
    const S p_e = exp((c.p.N - log(1.0 + e)) / c.p.lambda_star);           // eq. 6.7, p_r = 1 kPa
    const S f_d_ratio = p / p_e * (M2 + eta2) / M2;                        // f_d / f_d^A (eq. 6.5)
    const Tensor d_raw = 3.0 * deviator + ((eta2 - M2) * p / 3.0) * unit;  // eq. 6.8, ERRATA 13
    const Tensor d = d_raw / safe_sqrt(Ops::contract(d_raw, d_raw));
    return masin_tangent<Ops, S>(T, f_s, f_d_ratio, d, c.nu_ratio, c.p.lambda_star);
  }

  template <class Ops, class S>
  static typename Ops::template Tensor<S> rate(const typename Ops::template Tensor<S>& T,
                                               const S& e,
                                               const typename Ops::template Tensor<S>& D,
                                               const Constants& c) {
    return rate_of<Ops, S>(tangent<Ops, S>(T, e, c), D);
  }

  // Any compressed state: the ASBS is asymptotic, and a change of stress path carries the state
  // across it for a while (an oedometric loading from an isotropic-like start reaches OCR 0.99).
  static std::string domain_violation(const StressInvariants&, double, const Constants&) {
    return {};
  }
  // A start outside the ASBS (an e0 above the normal compression line): no loading history puts
  // a clay there, so it is refused as an input mistake.
  static std::string initial_violation(const StressInvariants& s, double e, const Constants& c);
  // The void ratio at which a state of these invariants has overconsolidation `ocr`:
  // p_e* = ocr p (M^2 + eta^2)/M^2, ln(1+e) = N - lambda* ln p_e*.
  static double void_ratio_at(const StressInvariants& s, double ocr, const Constants& c);
  // mean_stress_kPa, p_e_kPa (Hvorslev's equivalent pressure), OCR = p_e* / p_ASBS (1 on the ASBS).
  static std::vector<NamedValue> diagnostics(const StressInvariants& s, double e,
                                             const Constants& c);
};

}  // namespace iwb::models
