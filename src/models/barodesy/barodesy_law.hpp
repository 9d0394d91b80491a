#pragma once
// Barodesy for clay (Medicus, Fellin & Kolymbas 2012; the improved version of Medicus & Fellin
// 2017 that the seed prints, seed 8.2, eqs. 8.1-8.15 with the corrections of README.md), written
// once over an algebra policy like the hypoplastic laws, tension positive (T, D compression
// negative; X^0 = X / ||X||; delta = tr D^0; sigma = ||T||; p = -tr T / 3):
//
//   T_rate = c3 sigma (f R^0 + g T^0) ||D||                                 (8.1, c4 = 1)
//   R = -exp(alpha D^0),  alpha = ln K / sqrt(3/2 - delta^2/2)             (8.2, 8.3)
//   K = 1 - 1 / (1 + c1 (m - c2)^2),  m = -3 delta / sqrt(6 - 2 delta^2)    (8.4)
//   f = c6 beta delta - 1/2,  g = (1 - c6) beta delta + ((1+e)/(1+e_c))^c5 - 1/2   (8.5, 8.6)
//   (1+e)/(1+e_c) = (2p / p_e)^lambda*,  p_e = exp((N - ln(1+e)) / lambda*)     (8.7)
//   beta = -1 / (c3 Lambda) + (2^(c5 lambda*) - 1) / sqrt3                   (8.8, corrected)
//   Lambda = -(lambda* - kappa*) delta / (2 sqrt3) + (lambda* + kappa*) / 2  (8.9, corrected)
//
// with the constants of BarodesyConstants (8.10-8.15). The exponential is the algebra's series
// (algebra/exponential.hpp): the matrix exponential on 3x3 tensors, the reduced operators' own on
// the interface vectors, where it does not stay in the embedding (README.md: reduced != 3D).
#include <cmath>
#include <string>
#include <vector>

#include "algebra/exponential.hpp"
#include "common/scalar.hpp"
#include "models/hypoplastic/von_wolffersdorff.hpp"
#include "models/model.hpp"
#include "models/roughness/roughness.hpp"

namespace iwb::models {

struct BarodesyParameters {
  double lambda_star;  // slope of the isotropic NCL, ln(1+e) against ln p
  double
      kappa_star;  // slope of isotropic unloading, ln(1+e) against ln p (approximately: README.md)
  double phi_c;    // critical state friction angle, rad
  double N;        // ln(1+e) on the isotropic NCL at p = 1 kPa
  double G0_over_p;  // shear modulus over mean stress at an isotropic state (Table 8.1's G0/p_ini)
};

struct BarodesyConstants {
  BarodesyParameters p;
  double K_c;  // (1 - sin phi) / (1 + sin phi), phi = phi_c kappa_r: sigma_3 / sigma_1 at the
               // critical state
  double c1, c2, c3, c5, c6;
  double c3_shear, c3_unloading;  // the two entries of eq. 8.12, c3 their max (both negative)
};

// The constants (8.10-8.15) for the wall `r` (Arnold & Herle's scheme for clay, eq. 6.22: phi_c
// kappa_r wherever phi_c enters).
BarodesyConstants make_barodesy_constants(const BarodesyParameters& p, const Roughness& r);

struct BarodesyLaw {
  using Constants = BarodesyConstants;

  template <class Ops, class S>
  static typename Ops::template Tensor<S> rate(const typename Ops::template Tensor<S>& T,
                                               const S& e,
                                               const typename Ops::template Tensor<S>& D,
                                               const Constants& c) {
    using std::exp;
    using std::log;
    using std::pow;
    using std::sqrt;
    using Tensor = typename Ops::template Tensor<S>;
    const S norm_D = safe_sqrt(S(Ops::contract(D, D)));
    if (!(value_of(norm_D) > 0.0)) return Tensor(0.0 * T);
    const Tensor D0 = D / norm_D;
    const S delta = Ops::trace(D0);
    const S R_norm_T = sqrt(S(Ops::contract(T, T)));
    const Tensor T0 = T / R_norm_T;
    const S x = safe_sqrt(
        S(1.5 - 0.5 * delta * delta));  // |D0_1 - D0_2| of a triaxial D0; 0 when isotropic
    // alpha -> 0 for an isotropic D^0 (K -> 1 as fast as x -> 0): R^0 = -1/sqrt3 there
    S alpha = S(0.0);
    if (value_of(x) > kIsotropicStretching) {
      const S m = -1.5 * delta / x;
      const S K = 1.0 - 1.0 / (1.0 + c.c1 * (m - c.c2) * (m - c.c2));
      alpha = log(K) / x;
    }
    const Tensor R = -algebra::exponential<Ops, S>(Tensor(alpha * D0));
    const Tensor R0 = R / sqrt(S(Ops::contract(R, R)));
    const S p = -Ops::trace(T) / 3.0;
    const S p_e = exp((c.p.N - log(1.0 + e)) / c.p.lambda_star);
    const S density = pow(2.0 * p / p_e, c.p.lambda_star * c.c5);  // ((1+e)/(1+e_c))^c5
    const S Lambda = -(c.p.lambda_star - c.p.kappa_star) / (2.0 * std::sqrt(3.0)) * delta +
                     (c.p.lambda_star + c.p.kappa_star) / 2.0;
    const S beta =
        -1.0 / (c.c3 * Lambda) + (std::pow(2.0, c.c5 * c.p.lambda_star) - 1.0) / std::sqrt(3.0);
    const S f = c.c6 * beta * delta - 0.5;
    const S g = (1.0 - c.c6) * beta * delta + density - 0.5;
    return Tensor((c.c3 * R_norm_T * norm_D) * (f * R0 + g * T0));
  }

  // Any compressed state (p > 0).
  static std::string domain_violation(const StressInvariants& s, double e, const Constants& c);
  // The void ratio OCR times looser in p_e than the state boundary surface at T: the asymptotic
  // state of the proportional stretching whose R^0 is T^0. For an axisymmetric T (every start
  // here), K = sigma_minor / sigma_major of T inverts eq. 8.4 on its compression branch (m >= c2)
  // to delta, and there (1+e)/(1+e_c) = (1 - delta (beta + 1/(lambda* c3)))^(1/c5) keeps T^0 and
  // the ratio constant (README.md). OCR 1 is the isotropic NCL at K = 1, the oedometric
  // asymptote at K0, e_c at K_c.
  template <class Ops>
  static double void_ratio_at_stress(const typename Ops::template Tensor<double>& T, double ocr,
                                     const Constants& c) {
    const double p = -Ops::trace(T) / 3.0;
    const auto s = (T + p * Ops::template unit<double>()).eval();
    const double q = std::sqrt(1.5 * Ops::contract(s, s));
    // tr s^3 < 0: one principal compression larger than the other two (triaxial compression)
    const bool compression = Ops::trace_of_cube(s) < 0.0;
    const double K =
        compression ? (p - q / 3.0) / (p + 2.0 * q / 3.0) : (p - 2.0 * q / 3.0) / (p + q / 3.0);
    return void_ratio_at_ratio(K, p, ocr, c);
  }
  static double void_ratio_at_ratio(double K, double p, double ocr, const Constants& c);
  // mean_stress_kPa, p_e_kPa, p_e / p
  static std::vector<NamedValue> diagnostics(const StressInvariants& s, double e,
                                             const Constants& c);

  // Below this |D0_1 - D0_2|-like measure D^0 is isotropic for alpha (alpha ~ x there).
  static constexpr double kIsotropicStretching = 1e-9;
};

}  // namespace iwb::models
