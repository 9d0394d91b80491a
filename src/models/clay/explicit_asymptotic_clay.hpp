#pragma once
// Masin's (2013) clay hypoplasticity with explicitly defined asymptotic states (seed 6.2.3, eqs.
// 6.11-6.20, ERRATA 11, 12, 14), written once over an algebra policy, tension positive. The same
// frame as hypoplastic Cam clay (f_s, L, A: ERRATA 13),
//
//   T_rate = f_s L : D - (f_d / f_d^A) (f_s L + T x 1 / lambda*) : d ||D||,
//
// with the Matsuoka-Nakai asymptotic state boundary surface:
//   f_d = (2p / p_e*)^alpha_f,  f_d^A = 2^alpha_f (1 - F_m)^(alpha_f / omega) (6.11, 6.14) omega =
//   -ln(cos^2 phi_c) / ln 2 + 0.3 (F_m - sin^2 phi_c)                (6.15, ERRATA 12) alpha_f =
//   ln[(lambda* - kappa*)/(lambda* + kappa*) (3 + a_f^2)/(a_f sqrt3)] / ln 2     (6.12) a_f = sqrt3
//   (3 - sin phi_c) / (2 sqrt2 sin phi_c)                                     (6.13) F_m = (9 I3 +
//   I1 I2) / (I3 + I1 I2),  I2 = (T:T - I1^2)/2                        (6.16, 6.17) d^A = -T^* + 1
//   [2/3 - (cos 3theta + 1)/4 F_m^(1/4)] (F_m^(xi/2) - sin^xi phi_c)/(1 - sin^xi phi_c)
//                                                                           (6.19, ERRATA 11)
//   xi = 1.7 + 3.9 sin^2 phi_c                                                            (6.20)
// T^* = T / tr T - 1/3 and cos 3theta as in von Wolffersdorff's law (eq. 5.11: -1 in triaxial
// compression). At F_m = sin^2 phi_c, d is deviatoric and f_d^A = 1: the critical state is
// Matsuoka-Nakai's cone at phi_c with p_e* = 2p. Rough walls, Stutz & Masin (eqs. 6.23-6.28):
// nu_r for a shear stiffness scaled by kappa_r, phi_c kappa_r in a_f, omega and d^A (xi keeps
// phi_c: the seed does not modify it).
#include <fmt/core.h>

#include <cmath>
#include <string>
#include <vector>

#include "models/clay/hypoplastic_cam_clay.hpp"

namespace iwb::models {

struct ExplicitAsymptoticClayConstants {
  ClayParameters p;
  double nu_ratio;  // nu_r / (1 - 2 nu_r)
  double fs_per_p;  // f_s / p with nu_r (eq. 6.9)
  double alpha_f;   // eq. 6.12 with a_f (or a_fm, eq. 6.26)
  double sin2_phi;  // sin^2 (phi_c kappa_r)
  double omega_0;   // -ln(cos^2 (phi_c kappa_r)) / ln 2
  double xi;        // eq. 6.20
  double sin_xi;    // sin^xi (phi_c kappa_r)
};

ExplicitAsymptoticClayConstants make_explicit_asymptotic_clay_constants(const ClayParameters& p,
                                                                        const Roughness& r);

struct ExplicitAsymptoticClayLaw {
  using Constants = ExplicitAsymptoticClayConstants;

  template <class Ops, class S>
  static ClayTangent<Ops, S> tangent(const typename Ops::template Tensor<S>& T, const S& e,
                                     const Constants& c) {
    using std::exp;
    using std::log;
    using std::pow;
    using std::sqrt;
    using Tensor = typename Ops::template Tensor<S>;
    const S tr = compressed_trace<Ops, S>(T);
    const Tensor unit = Ops::template unit<S>();
    const S p = -tr / 3.0;
    // 0 for an isotropic stress up to round-off, which may be of either sign; there its powers
    // (F_m^(1/4) has an infinite slope at 0) are taken as 0 with a zero derivative
    S F_m = models::matsuoka_nakai<Ops, S>(T);
    if (!(value_of(F_m) > 0.0)) F_m = S(0.0);
    const auto power = [](const S& x, double k) {
      return value_of(x) > 0.0 ? S(pow(x, k)) : S(0.0);
    };
    const S p_e = exp((c.p.N - log(1.0 + e)) / c.p.lambda_star);                   // eq. 6.7
    const S omega = c.omega_0 + 0.3 * (F_m - c.sin2_phi);                          // ERRATA 12
    const S f_d = pow(2.0 * p / p_e, c.alpha_f);                                   // eq. 6.11
    const S f_dA = pow(2.0, c.alpha_f) * exp(c.alpha_f / omega * log(1.0 - F_m));  // eq. 6.14
    const Tensor t_dev = T / tr - unit / 3.0;
    const S volumetric = (2.0 / 3.0 - (lode_cos3<Ops, S>(t_dev) + 1.0) / 4.0 * power(F_m, 0.25)) *
                         (power(F_m, c.xi / 2.0) - c.sin_xi) /
                         (1.0 - c.sin_xi);  // eq. 6.19, ERRATA 11
    const Tensor d_A = -t_dev + volumetric * unit;
    const Tensor d = d_A / safe_sqrt(Ops::contract(d_A, d_A));  // eq. 6.18
    return masin_tangent<Ops, S>(T, S(c.fs_per_p * p), S(f_d / f_dA), d, c.nu_ratio,
                                 c.p.lambda_star);
  }

  template <class Ops, class S>
  static typename Ops::template Tensor<S> rate(const typename Ops::template Tensor<S>& T,
                                               const S& e,
                                               const typename Ops::template Tensor<S>& D,
                                               const Constants& c) {
    return rate_of<Ops, S>(tangent<Ops, S>(T, e, c), D);
  }

  // cos 3theta of the normalised deviator (eq. 5.11), 0 where it vanishes.
  template <class Ops, class S>
  static S lode_cos3(const typename Ops::template Tensor<S>& t_dev) {
    using std::sqrt;
    const S dev2 = Ops::contract(t_dev, t_dev);
    if (!(value_of(dev2) > 1e-300)) return S(0.0);
    S cos3 = -sqrt(6.0) * Ops::trace_of_cube(t_dev) / (dev2 * sqrt(dev2));
    if (value_of(cos3) > 1.0) cos3 = S(1.0);
    if (value_of(cos3) < -1.0) cos3 = S(-1.0);
    return cos3;
  }

  // Any compressed state inside Matsuoka-Nakai's cone (F_m < 1, where f_d^A is defined).
  static std::string domain_violation(const StressInvariants& s, double e, const Constants& c);
  static std::string initial_violation(const StressInvariants& s, double e, const Constants& c);
  // The void ratio at which p_e* is `ocr` times its value on the ASBS at these invariants, where
  // f_d = f_d^A: p_e*(ASBS) = p / (1 - F_m)^(1/omega). Then f_d / f_d^A = ocr^(-alpha_f).
  static double void_ratio_at(const StressInvariants& s, double ocr, const Constants& c);
  // mean_stress_kPa, p_e_kPa, F_m (sin^2 phi_c at the critical state), f_d / f_d^A
  static std::vector<NamedValue> diagnostics(const StressInvariants& s, double e,
                                             const Constants& c);
};

}  // namespace iwb::models
