#pragma once
// Masin's (2005) clay hypoplasticity (seed 6.3, eqs. 6.33-6.43 at T = T0, s = 0; ERRATA 14, and
// the items of the issue 19 closing note), written once over an algebra policy, tension positive:
//
//   T_rate = f_s L : D + f_s f_d N ||D||,   L = 3 (c_1 I + c_2 a^2 T^ x T^),   N = L : (-Y m /
//   ||m||) c_1 = 2 (3 + a^2 - 2^alpha a sqrt3) / (9 r),   c_2 = 1 + (1 - c_1) 3 / a^2 (6.34) a =
//   sqrt3 (3 - sin phi_c) / (2 sqrt2 sin phi_c)                                  (6.35, ERRATA 14)
//   alpha = ln[(lambda* - kappa*)/(lambda* + kappa*) (3 + a^2)/(a sqrt3)] / ln 2 (6.36) Y = (1 - k)
//   F_m (1 - sin^2 phi_c) / ((1 - F_m) sin^2 phi_c) + k,   k = sqrt3 a / (3 + a^2)
//        (6.38 with ERRATA 14, written through Matsuoka-Nakai's F_m = (9 I3 + I1 I2)/(I3 + I1 I2):
//         (I1 I2 + 9 I3) / I3 = -8 F_m / (1 - F_m); Y = 1 on the cone F_m = sin^2 phi_c, k at p
//         only)
//   m = -(a/F) [T^ + T^* - (T^/3) (6 T^:T^ - 1) / ((F/a)^2 + T^:T^)] (6.39) F: von Wolffersdorff's
//   (6.40 = 5.10);   f_s = 3p / lambda* (3 + a^2 - 2^alpha a sqrt3)^-1    (6.41) f_d = (2p /
//   p_e)^alpha,   p_e = p_r exp[(N - ln(1+e)) / lambda*],  p_r = 1 kPa         (6.42, 6.43)
//
// The thermo-hydro model (src/models/thermo_hydro) evaluates the same law with lambda*(s, T) and
// N(s, T) (6.44, 6.45): every coefficient that depends on lambda* is computed per evaluation.
// The state boundary surface: f_d^SBS = ||f_s A^-1 : N||^-1 with A = f_s L + T x 1 / lambda*
// (6.49, 6.50 with the sign of ERRATA 13; A is inverted as the matrix of its action on the
// packed components, which serves every algebra). Rough walls (6.2.4): phi_c kappa_r in a, Y
// and F_m's cone; Stutz & Masin's scheme also scales r by kappa_r (eq. 6.24's role).
#include <Eigen/Dense>
#include <cmath>
#include <string>
#include <vector>

#include "models/hypoplastic/von_wolffersdorff.hpp"
#include "models/parameters.hpp"
#include "models/roughness/roughness.hpp"

namespace iwb::models {

struct MasinClayParameters {
  double phi_c;        // critical state friction angle, rad
  double lambda_star;  // slope of the isotropic NCL, ln(1+e) against ln p
  double kappa_star;   // slope of the isotropic unloading line
  double N;            // ln(1+e) on the isotropic NCL at p = 1 kPa
  double r;            // ratio of bulk to shear stiffness at the isotropic state (Masin 2005)

  static const ParameterTable& table();  // [clay_hypoplasticity]
  static MasinClayParameters from(const ParameterValues& v, const std::string& source);
};

struct MasinClayConstants {
  MasinClayParameters p;  // phi_c and r as the wall's roughness scheme modifies them
  double a;               // eq. 6.35
  double k;               // sqrt3 a / (3 + a^2): Y at the isotropic state
  double sin2_phi;
};

MasinClayConstants make_masin_clay_constants(const MasinClayParameters& p, const Roughness& r);

// The coefficients that depend on lambda* (6.34, 6.36, 6.41).
template <class S>
struct MasinCoefficients {
  S alpha, c1, c2, fs_per_p;
};

template <class S>
MasinCoefficients<S> masin_coefficients(const S& lambda, const MasinClayConstants& c) {
  using std::exp;
  using std::log;
  const double a = c.a, kappa = c.p.kappa_star;
  const S alpha = log((lambda - kappa) / (lambda + kappa) * (3.0 + a * a) / (a * std::sqrt(3.0))) /
                  std::log(2.0);
  const S denominator = 3.0 + a * a - exp(alpha * std::log(2.0)) * a * std::sqrt(3.0);  // 2^alpha
  const S c1 = 2.0 * denominator / (9.0 * c.p.r);
  return {alpha, c1, 1.0 + (1.0 - c1) * 3.0 / (a * a), 3.0 / (lambda * denominator)};
}

// The law's parts at one state for given lambda*, N: the tangent (L and f_s f_d N, as von
// Wolffersdorff's) and what the thermo-hydro terms read of it.
template <class Ops, class S>
struct MasinClayParts {
  using Tensor = typename Ops::template Tensor<S>;
  HypoplasticTangent<Ops, S> tangent;
  S alpha, f_d, p_e;
};

template <class Ops, class S>
MasinClayParts<Ops, S> masin_clay_parts(const typename Ops::template Tensor<S>& T, const S& e,
                                        const S& lambda, const S& N, const MasinClayConstants& c) {
  using std::exp;
  using std::log;
  using std::pow;
  using Tensor = typename Ops::template Tensor<S>;
  const S tr = compressed_trace<Ops, S>(T);
  const Tensor unit = Ops::template unit<S>();
  const S p = -tr / 3.0;
  const auto k = masin_coefficients<S>(lambda, c);
  const Tensor t_hat = T / tr;
  const Tensor t_dev = t_hat - unit / 3.0;
  const S F = detail::stress_function<Ops, S>(t_dev, LodeRule::kStandard);
  const S tt = Ops::contract(t_hat, t_hat);
  const Tensor m = (-c.a / F) * (t_hat + t_dev -
                                 (t_hat / 3.0) * ((6.0 * tt - 1.0) / ((F / c.a) * (F / c.a) + tt)));
  S F_m = models::matsuoka_nakai<Ops, S>(T);
  if (!(value_of(F_m) > 0.0)) F_m = S(0.0);  // isotropic up to round-off
  const S Y = (1.0 - c.k) * F_m * (1.0 - c.sin2_phi) / ((1.0 - F_m) * c.sin2_phi) + c.k;
  const S p_e = exp((N - log(1.0 + e)) / lambda);
  const S f_d = exp(k.alpha * log(2.0 * p / p_e));  // (2p/p_e)^alpha: alpha depends on T and s
  HypoplasticTangent<Ops, S> h{3.0 * k.fs_per_p * p, k.c1, k.c2 * c.a * c.a, t_hat, Tensor()};
  h.N = f_d * h.L((-Y / safe_sqrt(Ops::contract(m, m))) * m);
  return {h, k.alpha, f_d, p_e};
}

// f_d on the state boundary surface at this stress (6.49): ||f_s A^-1 : N||^-1, with f_s N =
// tangent.N / f_d and A : X = f_s L : X + T tr X / lambda* (6.50, ERRATA 13's sign).
template <class Ops, class S>
S state_boundary_pyknotropy(const typename Ops::template Tensor<S>& T,
                            const MasinClayParts<Ops, S>& parts, const S& lambda) {
  constexpr int n = Ops::kPackedSize;
  using Tensor = typename Ops::template Tensor<S>;
  using Packed = Eigen::Matrix<S, n, 1>;
  Eigen::Matrix<S, n, n> A;
  for (int j = 0; j < n; ++j) {
    Packed basis = Packed::Zero();
    basis(j) = S(1.0);
    const Tensor X = Ops::template unpack<S>(basis, 0);
    Packed column;
    Ops::template pack<S>(parts.tangent.L(X) + (Ops::trace(X) / lambda) * T, column, 0);
    A.col(j) = column;
  }
  Packed fs_N;
  Ops::template pack<S>(parts.tangent.N / parts.f_d, fs_N, 0);
  const Packed x = A.partialPivLu().solve(fs_N);
  const Tensor X = Ops::template unpack<S>(x, 0);
  return 1.0 / safe_sqrt(Ops::contract(X, X));
}

struct MasinClayLaw {
  using Constants = MasinClayConstants;

  template <class Ops, class S>
  static HypoplasticTangent<Ops, S> tangent(const typename Ops::template Tensor<S>& T, const S& e,
                                            const Constants& c) {
    return masin_clay_parts<Ops, S>(T, e, S(c.p.lambda_star), S(c.p.N), c).tangent;
  }

  template <class Ops, class S>
  static typename Ops::template Tensor<S> rate(const typename Ops::template Tensor<S>& T,
                                               const S& e,
                                               const typename Ops::template Tensor<S>& D,
                                               const Constants& c) {
    return rate_of<Ops, S>(tangent<Ops, S>(T, e, c), D);
  }

  // Any compressed state with F_m < 1 (no tension in any direction), where F and Y are defined.
  static std::string domain_violation(const StressInvariants& s, double e, const Constants& c);
  // The void ratio at which p_e is `ocr` times its value on the state boundary surface at this
  // stress: p_e(SBS) = 2p / (f_d^SBS)^(1/alpha).
  template <class Ops>
  static double void_ratio_at_stress(const typename Ops::template Tensor<double>& T, double ocr,
                                     const Constants& c) {
    return void_ratio_at_stress_with<Ops>(T, ocr, c.p.lambda_star, c.p.N, c);
  }
  template <class Ops>
  static double void_ratio_at_stress_with(const typename Ops::template Tensor<double>& T,
                                          double ocr, double lambda, double N, const Constants& c) {
    const double p = -Ops::trace(T) / 3.0;
    const auto parts =
        masin_clay_parts<Ops, double>(T, std::exp(N) - 1.0, lambda, N, c);  // any e: f_d cancels
    const double p_e =
        ocr * 2.0 * p /
        std::pow(state_boundary_pyknotropy<Ops, double>(T, parts, lambda), 1.0 / parts.alpha);
    return std::exp(N - lambda * std::log(p_e)) - 1.0;
  }
  // Why a start (T, e) lies outside the state boundary surface at its stress, empty inside it:
  // e above e_SBS, the void ratio of void_ratio_at_stress at OCR 1 (f_d = f_d^SBS, 6.49).
  template <class Ops>
  static std::string initial_violation_at_stress(const typename Ops::template Tensor<double>& T,
                                                 double e, const Constants& c) {
    return initial_violation_at_stress_with<Ops>(T, e, c.p.lambda_star, c.p.N, c);
  }
  template <class Ops>
  static std::string initial_violation_at_stress_with(
      const typename Ops::template Tensor<double>& T, double e, double lambda, double N,
      const Constants& c) {
    return outside_state_boundary(e, void_ratio_at_stress_with<Ops>(T, 1.0, lambda, N, c), lambda,
                                  masin_coefficients<double>(lambda, c).alpha);
  }
  // The message for a start at e where the surface lies at e_sbs, empty within the tolerance.
  static std::string outside_state_boundary(double e, double e_sbs, double lambda, double alpha);
  // mean_stress_kPa, p_e_kPa, F_m
  static std::vector<NamedValue> diagnostics(const StressInvariants& s, double e,
                                             const Constants& c);
};

}  // namespace iwb::models
