#pragma once
// von Wolffersdorff's (1996) hypoplastic rate, written once over an algebra policy (src/algebra/
// ops.hpp) so the 3D model, the reduced interface models and Gutjahr's 1D model share it:
//
//   T_rate = f_c f_s / (T^:T^) [F^2 D + a^2 T^ (T^:D) + f_d a F (T^ + T^*) ||D||]
//
// seed eqs. 5.7-5.15 with ERRATA items 4-6 (f_s applied once, -tr T in the exponents), tension
// positive. The variants differ only in data: the Lode-angle rule, the coefficient a, and the
// roughness effect (a_r, alpha_r, f_c). With ShearPlaneOps F = 1 and the formula is Gutjahr's
// eq. 3.75 (derivation in src/models/hp1d/README.md).
#include <fmt/core.h>

#include <cmath>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "common/scalar.hpp"
#include "models/hypoplastic/parameters.hpp"
#include "models/model.hpp"
#include "models/roughness/roughness.hpp"

namespace iwb::models {

// Smallest mean pressure (-tr T) the rate accepts. Under extension a hypoplastic stress decays
// towards zero without reaching it; below this the element has lost contact and relative error
// control is meaningless, so it is reported as leaving the domain rather than as a tolerance
// underflow at 1e-30 kPa.
inline constexpr double kMinimumPressure_kPa = 1e-6;

// tr T of a compressed state; DomainError (contact lost) otherwise. Every hypoplastic law starts
// here.
template <class Ops, class S>
S compressed_trace(const typename Ops::template Tensor<S>& T) {
  const S tr = Ops::trace(T);
  if (!(value_of(tr) < -kMinimumPressure_kPa))
    throw DomainError(
        fmt::format("no compression: tr T = {:.6g} kPa (contact lost)", value_of(tr)));
  return tr;
}

// T_rate = L : D + N ||D|| of a law's tangent (any type with L(X) and N).
template <class Ops, class S, class Tangent>
typename Ops::template Tensor<S> rate_of(const Tangent& h,
                                         const typename Ops::template Tensor<S>& D) {
  return h.L(D) + safe_sqrt(Ops::contract(D, D)) * h.N;
}

enum class LodeRule {
  kStandard,  // cos 3theta from T^* (eq. 5.11)
  kZero,      // cos 3theta = 0 (Arnold & Herle 2006, ERRATA item 8)
};

enum class CoefficientARule {
  kVonWolffersdorff,  // eq. 5.15
  kArnoldHerle,  // eq. 5.21 with tan psi = tan phi (the interface stress ratio at critical state)
  kGutjahr1D,    // eq. 3.76, a = 1 / tan phi
};

struct HypoplasticVariant {
  LodeRule lode = LodeRule::kStandard;
  CoefficientARule a_rule = CoefficientARule::kVonWolffersdorff;
};

double coefficient_a(CoefficientARule rule, double phi);

// tau/sigma_n at the critical state of von Wolffersdorff's model in simple shear (vw3d, hvwe):
// stationary stress with sigma_p = sigma_n and cos 3theta = 0, the root eta of
// ||T^*|| = F/a, i.e. sqrt2 eta a / 3 = sqrt(1 - eta^2/4) - eta / (2 sqrt3) (von Wolffersdorff
// 1996). Not tan(phi_c): 0.52322 for phi_c = 28 deg. phi_c in rad.
double simple_shear_critical_ratio(double phi_c);
// Its inverse: the phi_c (rad) whose critical simple-shear ratio is `eta`; InputError outside the
// range phi_c in [1, 89] deg gives.
double friction_angle_of_simple_shear_ratio(double eta);

// Everything in the rate that does not change along a path.
struct VonWolffersdorffConstants {
  HypoplasticParameters p;
  LodeRule lode;
  double a;          // a, or a_r for a rough wall (eq. 5.37)
  double alpha;      // alpha, or alpha kappa_r^2 (Gutjahr, eq. 5.38)
  double barotropy;  // f_c (h_s/n) (e_i0/e_c0)^beta / [tr1 + a^2 - a sqrt(tr1)
                     // ((e_i0-e_d0)/(e_c0-e_d0))^alpha]
};

// trace_of_unit = tr 1 of the algebra: 3 for tensors and reduced vectors, 1 for Gutjahr's 1D
// vectors; it turns eq. 5.12's bracket (3 + a^2 - sqrt3 a ...) into eq. 3.77's (1 + a^2 - a ...),
// both of which put the isotropic (normal) compression line at e = e_i.
VonWolffersdorffConstants make_constants(const HypoplasticParameters& p,
                                         const HypoplasticVariant& v, const Roughness& r,
                                         double trace_of_unit);

template <class S>
struct LimitingVoidRatios {
  S e_i, e_c, e_d;
};

// Bauer's compression law, eq. 5.13 with ERRATA item 5; `pressure` = -tr T.
template <class S>
LimitingVoidRatios<S> limiting_void_ratios(const S& pressure, const HypoplasticParameters& p) {
  using std::exp;
  using std::pow;
  const S g = exp(-pow(pressure / p.hs, p.n));
  return {p.ei0 * g, p.ec0 * g, p.ed0 * g};
}

namespace detail {
// Matsuoka-Nakai stress function F (eq. 5.10) with cos 3theta from eq. 5.11 or set to zero.
template <class Ops, class S>
S stress_function(const typename Ops::template Tensor<S>& t_dev, LodeRule lode) {
  using std::sqrt;
  const S dev2 = Ops::contract(t_dev, t_dev);
  const S tan_psi = sqrt(3.0) * safe_sqrt(dev2);
  S cos3 = S(0.0);
  if (lode == LodeRule::kStandard && value_of(dev2) > 1e-300) {
    cos3 = -sqrt(6.0) * Ops::trace_of_cube(t_dev) / (dev2 * sqrt(dev2));
    if (value_of(cos3) > 1.0) cos3 = S(1.0);
    if (value_of(cos3) < -1.0) cos3 = S(-1.0);
  }
  const S t2 = tan_psi * tan_psi;
  const S denominator = 2.0 + sqrt(2.0) * tan_psi * cos3;
  const S radicand = t2 / 8.0 + (2.0 - t2) / denominator;
  if (!(value_of(denominator) > 0.0) || !(value_of(radicand) >= 0.0))
    throw DomainError(fmt::format("stress ratio outside the Matsuoka-Nakai cone (tan psi = {:.4g})",
                                  value_of(tan_psi)));
  return sqrt(radicand) - tan_psi / (2.0 * sqrt(2.0));
}
}  // namespace detail

// The rate split into its linear part L : X and the tensor N of T_rate = L : D + N ||D|| (eq.
// 5.6), so the intergranular strain (intergranular_strain.hpp) can interpolate between them
// without writing the formula a second time.
template <class Ops, class S>
struct HypoplasticTangent {
  using Tensor = typename Ops::template Tensor<S>;
  S scale;       // f_c f_b f_e / (T^:T^)
  S F2;          // F^2
  S a2;          // a^2 (Masin's clay: c_2 a^2, which depends on temperature and suction)
  Tensor t_hat;  // T^
  Tensor N;      // scale f_d a F (T^ + T^*)

  Tensor L(const Tensor& X) const {  // L : X = scale [F^2 X + a^2 T^ (T^:X)]
    return scale * (F2 * X + (a2 * Ops::contract(t_hat, X)) * t_hat);
  }
};

template <class Ops, class S>
HypoplasticTangent<Ops, S> von_wolffersdorff_tangent(const typename Ops::template Tensor<S>& T,
                                                     const S& e,
                                                     const VonWolffersdorffConstants& c) {
  using std::pow;
  using Tensor = typename Ops::template Tensor<S>;
  const S tr = compressed_trace<Ops, S>(T);
  const Tensor unit = Ops::template unit<S>();
  const double tr_unit = value_of(Ops::trace(unit));
  const Tensor t_hat = T / tr;
  const Tensor t_dev = t_hat - unit / tr_unit;

  const S pressure = -tr;
  const auto lim = limiting_void_ratios(pressure, c.p);
  if (!(value_of(e) > value_of(lim.e_d)))
    throw DomainError(
        fmt::format("e = {:.6g} at or below e_d = {:.6g}", value_of(e), value_of(lim.e_d)));
  const S f_d = pow((e - lim.e_d) / (lim.e_c - lim.e_d), c.alpha);  // eq. 5.14 / 5.38
  const S f_e = pow(lim.e_c / e, c.p.beta);                         // f_e = (e_c/e)^beta
  const S ratio = pressure / c.p.hs;
  const S f_b = c.barotropy * (1.0 + lim.e_i) / lim.e_i * ratio / pow(ratio, c.p.n);  // eq. 5.12
  S F = S(1.0);
  if constexpr (Ops::kHasLodeAngle) F = detail::stress_function<Ops, S>(t_dev, c.lode);

  const S scale = f_b * f_e / Ops::contract(t_hat, t_hat);
  const Tensor N = (scale * f_d * c.a * F) * (t_hat + t_dev);
  return {scale, F * F, c.a * c.a, t_hat, N};
}

// What a rate law's domain and diagnostics read of a stress: -tr T, the mean stress -tr T / tr 1
// and eta^2 = (3/2) ||T*||^2 / p^2 (q/p squared; 0 in Gutjahr's 1D algebra's isotropic sense).
struct StressInvariants {
  double pressure;     // -tr T, kPa
  double mean_stress;  // -tr T / tr 1, kPa
  double eta2;         // (q / p)^2
  double F_m = NAN;    // Matsuoka-Nakai's (9 I3 + I1 I2)/(I3 + I1 I2), eq. 6.16; NaN in 1D (no I3)
};

// Matsuoka-Nakai's F_m (eq. 6.16, with the seed's I2 = (T:T - I1^2)/2): 0 for an isotropic stress,
// sin^2 phi on the cone of friction angle phi. I3 from Cayley-Hamilton with tr(T^3) from the
// deviator s = T - m 1 (tr T^3 = tr s^3 + 3 m s:s + 3 m^3): the seed's reduced operators give
// tr(X^3) right only for deviatoric X (algebra/ops.hpp), and this way all three algebras agree.
template <class Ops, class S>
S matsuoka_nakai(const typename Ops::template Tensor<S>& T) {
  const auto unit = Ops::template unit<S>();
  const S I1 = Ops::trace(T);
  const S m = I1 / 3.0;
  const typename Ops::template Tensor<S> s = T - m * unit;
  const S ss = Ops::contract(s, s);
  const S TT = ss + 3.0 * m * m;
  const S I2 = 0.5 * (TT - I1 * I1);
  const S cube = Ops::trace_of_cube(s) + 3.0 * m * ss + 3.0 * m * m * m;
  const S I3 = (I1 * I1 * I1 - 3.0 * I1 * TT + 2.0 * cube) / 6.0;
  return (9.0 * I3 + I1 * I2) / (I3 + I1 * I2);
}

template <class Ops>
StressInvariants stress_invariants(const typename Ops::template Tensor<double>& T) {
  const auto unit = Ops::template unit<double>();
  const double tr_unit = Ops::trace(unit);
  const double pressure = -Ops::trace(T);
  const double p = pressure / tr_unit;
  const typename Ops::template Tensor<double> deviator = T + p * unit;
  StressInvariants s{pressure, p, 1.5 * Ops::contract(deviator, deviator) / (p * p)};
  if constexpr (Ops::kHasLodeAngle) s.F_m = matsuoka_nakai<Ops, double>(T);
  return s;
}

// von Wolffersdorff's law as a rate law of HypoplasticModel (hypoplastic_model.hpp): what the
// model class asks of any hypoplastic law, sand or clay (src/models/README.md, section 4).
struct VonWolffersdorffLaw {
  using Constants = VonWolffersdorffConstants;

  template <class Ops, class S>
  static HypoplasticTangent<Ops, S> tangent(const typename Ops::template Tensor<S>& T, const S& e,
                                            const Constants& c);
  template <class Ops, class S>
  static typename Ops::template Tensor<S> rate(const typename Ops::template Tensor<S>& T,
                                               const S& e,
                                               const typename Ops::template Tensor<S>& D,
                                               const Constants& c);
  // Why a compressed state (-tr T > 0) with void ratio e is outside the law's domain, (e_d, e_i)
  // at that pressure; empty inside.
  static std::string domain_violation(const StressInvariants& s, double e, const Constants& c);
  // mean_stress_kPa, e_i, e_c, e_d (the order the declarations state).
  static std::vector<NamedValue> diagnostics(const StressInvariants& s, double e,
                                             const Constants& c);
};

template <class Ops, class S>
typename Ops::template Tensor<S> von_wolffersdorff_rate(const typename Ops::template Tensor<S>& T,
                                                        const S& e,
                                                        const typename Ops::template Tensor<S>& D,
                                                        const VonWolffersdorffConstants& c) {
  return rate_of<Ops, S>(von_wolffersdorff_tangent<Ops, S>(T, e, c), D);
}

template <class Ops, class S>
HypoplasticTangent<Ops, S> VonWolffersdorffLaw::tangent(const typename Ops::template Tensor<S>& T,
                                                        const S& e, const Constants& c) {
  return von_wolffersdorff_tangent<Ops, S>(T, e, c);
}

template <class Ops, class S>
typename Ops::template Tensor<S> VonWolffersdorffLaw::rate(
    const typename Ops::template Tensor<S>& T, const S& e,
    const typename Ops::template Tensor<S>& D, const Constants& c) {
  return von_wolffersdorff_rate<Ops, S>(T, e, D, c);
}

}  // namespace iwb::models
