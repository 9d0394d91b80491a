#pragma once
// Masin & Khalili's (2012) thermo-mechanical hypoplasticity for variably saturated clay (seed 6.3,
// eqs. 6.29-6.52; the readings of the garbled equations are in README.md), over Masin's (2005)
// law (clay/masin_clay.hpp), tension positive. The state holds the net stress T_net (what a test
// applies), e, the absolute temperature T_K and the suction s:
//
//   T = T_net - chi s 1,  chi = 1 (s < s_e), (s_e/s)^gamma (s >= s_e),  gamma = 0.55 (6.30, 6.31)
//   T_net_rate = T_rate + psi s_rate 1,  psi = d(chi s)/ds = 1 (s < s_e), (1 - gamma) chi
//   T_rate = f_s L : D_m + f_s f_d N ||D_m|| + f_u (H_T + H_s),  D_m = D - alpha_s T_rate_K / 3 1
//   (6.29, 6.32) lambda*(s,T) = lambda* + l_t ln(T/T0) + l_s <ln(s/s_e)>,  N(s,T) likewise with
//   n_t, n_s  (6.44, 6.45)
//     (every coefficient of the base law that depends on lambda*, alpha included, takes
//     lambda*(s,T))
//   H_T = c_i T / (T_K lambda*(s,T)) [n_t - l_t ln(p_e/p_r)] <T_rate_K>                   (6.46,
//   sign: README) H_s = -c_i T / (s lambda*(s,T)) [n_s - l_s ln(p_e/p_r)] <-s_rate>  for s > s_e,
//   else 0      (6.48) c_i = (3 + a^2 - f_d a sqrt3) / (3 + a^2 - f_d^SBS a sqrt3),  f_u = (f_d /
//   f_d^SBS)^(m/alpha)  (6.47, 6.51) e_rate = (1 + e) tr D_m (6.52)
//
// Every term is of degree one in (D, T_rate_K, s_rate) jointly, so the integrators take the
// increments of T and s as they take the strain's. At T = T0, s < s_e and no T or s rate it is
// Masin's (2005) law exactly (the test of the reduction).
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "models/clay/masin_clay.hpp"
#include "models/model.hpp"

namespace iwb::models {

struct ThermoHydroParameters {
  double alpha_s;   // volumetric thermal expansion of the grains, 1/K
  double l_t, n_t;  // temperature dependence of lambda* and N
  double l_s, n_s;  // suction dependence of lambda* and N
  double s_e;       // air-entry (expansion) suction, kPa
  double m;         // collapse exponent of f_u
  double T0;        // reference temperature, K

  static const ParameterTable& table();  // [thermo_hydro]
  static ThermoHydroParameters from(const ParameterValues& v, const std::string& source);
};

struct ThermoHydroClayConstants {
  MasinClayConstants base;
  ThermoHydroParameters th;
};

inline constexpr double kKhaliliGamma = 0.55;  // Khalili & Khabbaz (1998), eq. 6.31

// Khalili's effective stress factor chi and psi = d(chi s)/ds.
template <class S>
struct EffectiveStressFactor {
  S chi, psi;
};

template <class S>
EffectiveStressFactor<S> effective_stress_factor(const S& s, double s_e) {
  using std::pow;
  if (!(value_of(s) > s_e)) return {S(1.0), S(1.0)};
  const S chi = pow(s_e / s, kKhaliliGamma);
  return {chi, (1.0 - kKhaliliGamma) * chi};
}

// lambda*(s, T) and N(s, T) (6.44, 6.45).
template <class S>
struct CompressionLine {
  S lambda, N;
};

template <class S>
CompressionLine<S> compression_line(const S& T_K, const S& s, const ThermoHydroClayConstants& c) {
  using std::log;
  const S heat = log(T_K / c.th.T0);
  const S dry = value_of(s) > c.th.s_e ? S(log(s / c.th.s_e)) : S(0.0);
  return {c.base.p.lambda_star + c.th.l_t * heat + c.th.l_s * dry,
          c.base.p.N + c.th.n_t * heat + c.th.n_s * dry};
}

template <class Ops, class S>
struct ThermoHydroRate {
  typename Ops::template Tensor<S> net_stress;
  S void_ratio;
};

struct ThermoHydroClayLaw {
  using Constants = ThermoHydroClayConstants;
  // The external variables it reads, in the order of its state components after e.
  static constexpr std::array<External, 2> kExternals{External::kTemperature, External::kSuction};

  // T = T_net - chi s 1 at x = {T_K, s} (6.30).
  template <class Ops, class S>
  static typename Ops::template Tensor<S> effective_stress(
      const typename Ops::template Tensor<S>& T_net, const std::array<S, 2>& x,
      const Constants& c) {
    return T_net -
           (effective_stress_factor<S>(x[1], c.th.s_e).chi * x[1]) * Ops::template unit<S>();
  }

  // x = {T_K, s}, dx = their rates (increments over the pseudo-time of D).
  template <class Ops, class S>
  static ThermoHydroRate<Ops, S> rate(const typename Ops::template Tensor<S>& T_net, const S& e,
                                      const typename Ops::template Tensor<S>& D,
                                      const std::array<S, 2>& x, const std::array<S, 2>& dx,
                                      const Constants& c) {
    using std::exp;
    using std::log;
    using Tensor = typename Ops::template Tensor<S>;
    const auto [T_K, s] = x;
    const auto [dT, ds] = dx;
    const Tensor unit = Ops::template unit<S>();
    const auto factor = effective_stress_factor<S>(s, c.th.s_e);
    const Tensor T = effective_stress<Ops, S>(T_net, x, c);
    const auto line = compression_line<S>(T_K, s, c);
    const auto parts = masin_clay_parts<Ops, S>(T, e, line.lambda, line.N, c.base);
    const Tensor D_m = D - (c.th.alpha_s * dT / 3.0) * unit;  // 6.32
    Tensor T_rate = rate_of<Ops, S>(parts.tangent, D_m);
    const bool heating = value_of(dT) > 0.0, wetting = value_of(ds) < 0.0 && value_of(s) > c.th.s_e;
    if (heating || wetting) {
      const S f_d_sbs = state_boundary_pyknotropy<Ops, S>(T, parts, line.lambda);
      const double a = c.base.a, a3 = a * std::sqrt(3.0);
      const S c_i = (3.0 + a * a - parts.f_d * a3) / (3.0 + a * a - f_d_sbs * a3);  // 6.47
      const S f_u = exp(c.th.m / parts.alpha * log(parts.f_d / f_d_sbs));           // 6.51
      const S ln_pe = log(parts.p_e);                                               // p_r = 1 kPa
      S h = S(0.0);
      if (heating) h += (c.th.n_t - c.th.l_t * ln_pe) * dT / T_K;  // 6.46
      if (wetting) h += (c.th.n_s - c.th.l_s * ln_pe) * ds / s;    // 6.48: <-s_rate> = -ds
      T_rate += (f_u * c_i * h / line.lambda) * T;
    }
    return {T_rate + (factor.psi * ds) * unit, (1.0 + e) * Ops::trace(D_m)};  // 6.30, 6.52
  }

  // The value of an external variable where a test does not give it: T0 and no suction.
  static double initial_external(External slot, const Constants& c) {
    return slot == External::kTemperature ? c.th.T0 : 0.0;
  }

  // States where the effective stress is compressed with F_m < 1.
  static std::string domain_violation(const StressInvariants& effective, double e,
                                      const Constants& c) {
    return MasinClayLaw::domain_violation(effective, e, c.base);
  }
  // The void ratio at overconsolidation `ocr` at this net stress, temperature and suction.
  template <class Ops>
  static double void_ratio_at_state(const typename Ops::template Tensor<double>& T_net,
                                    const std::array<double, 2>& x, double ocr,
                                    const Constants& c) {
    const auto line = compression_line<double>(x[0], x[1], c);
    return MasinClayLaw::void_ratio_at_stress_with<Ops>(effective_stress<Ops, double>(T_net, x, c),
                                                        ocr, line.lambda, line.N, c.base);
  }
  // Why a start lies outside the state boundary surface of its temperature and suction, at its
  // effective stress (6.30, 6.44, 6.45, 6.49): the base law's test with lambda*(s,T) and N(s,T).
  template <class Ops>
  static std::string initial_violation_at_state(const typename Ops::template Tensor<double>& T_net,
                                                double e, const std::array<double, 2>& x,
                                                const Constants& c) {
    const auto line = compression_line<double>(x[0], x[1], c);
    return MasinClayLaw::initial_violation_at_stress_with<Ops>(
        effective_stress<Ops, double>(T_net, x, c), e, line.lambda, line.N, c.base);
  }
  // mean_stress_kPa (effective), p_e_kPa (at this T and s), F_m, chi, f_d / f_d^SBS
  template <class Ops>
  static std::vector<NamedValue> diagnostics_at(const typename Ops::template Tensor<double>& T_net,
                                                double e, const std::array<double, 2>& x,
                                                const Constants& c) {
    const auto T = effective_stress<Ops, double>(T_net, x, c);
    const auto line = compression_line<double>(x[0], x[1], c);
    const auto parts = masin_clay_parts<Ops, double>(T, e, line.lambda, line.N, c.base);
    const auto inv = stress_invariants<Ops>(T);
    return {{"mean_stress_kPa", inv.mean_stress},
            {"p_e_kPa", parts.p_e},
            {"F_m", inv.F_m},
            {"chi", effective_stress_factor<double>(x[1], c.th.s_e).chi},
            {"f_d_over_f_dSBS",
             parts.f_d / state_boundary_pyknotropy<Ops, double>(T, parts, line.lambda)}};
  }
};

}  // namespace iwb::models
