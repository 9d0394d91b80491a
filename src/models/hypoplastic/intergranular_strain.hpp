#pragma once
// Niemunis & Herle's (1997) intergranular strain, written once over an algebra policy (like the
// von Wolffersdorff rate it wraps), so vw3d, hvwe, hvwe-exact and ahe share it: seed eqs.
// 5.42-5.48 with ERRATA item 10. With the hypoplastic tangent T_rate = L:D + N ||D||,
//
//   rho = ||delta|| / R,  delta^ = delta / ||delta|| (0 for delta = 0)             eqs. 5.43, 5.44
//   T_rate = [rho^chi m_T + (1 - rho^chi) m_R] L:D
//            + rho^chi (1 - m_T) L:delta^ (delta^:D) + rho^chi N (delta^:D)    for delta^:D > 0
//            + rho^chi (m_R - m_T) L:delta^ (delta^:D)                         for delta^:D <= 0
//   delta_rate = D - rho^beta_r delta^ (delta^:D)  for delta^:D > 0,  D otherwise    eq. 5.46
//
// ERRATA 10 caps rho at 1. We cap it in the stiffness interpolation only: there rho^chi > 1
// would put the stiffness factor outside [m_T, m_R]. The evolution keeps the uncapped rho, so an
// intergranular strain beyond R (the seed's initial value, or an explicit step's overshoot)
// decays back onto ||delta|| = R instead of staying outside for ever (with rho capped,
// d||delta||/dt = (delta^:D)(1 - rho^beta_r) would be 0 there).
// Both branches agree where delta^:D = 0, so M:D is continuous; its derivative is not.
#include <array>
#include <cmath>
#include <string>

#include "common/scalar.hpp"
#include "models/hypoplastic/von_wolffersdorff.hpp"
#include "models/parameters.hpp"

namespace iwb::models {

struct IntergranularStrainParameters {
  double R;       // size of the elastic range in strain space (radius of ||delta||)
  double m_R;     // stiffness factor after a 180 deg reversal
  double m_T;     // stiffness factor after a 90 deg change of direction
  double beta_r;  // rate of evolution of delta towards ||delta|| = R
  double chi;     // exponent of the stiffness interpolation in rho

  static const ParameterTable& table();  // TOML table [intergranular_strain]
  // Validates bounds and m_T <= m_R; errors name `source`.
  static IntergranularStrainParameters from(const ParameterValues& values,
                                            const std::string& source);
};

// Seed 5.6 (after Arnold 2008): after oedometric loading start from delta_n = 0,
// delta_x = delta_y = R / sqrt(3), as [delta_n, delta_x, delta_y] tensor components. Note its
// norm with the interface weights is 2R/sqrt(3) > R (README of src/models/hypoplastic).
std::array<double, 3> seed_initial_intergranular_strain(double R);
// After vertical (oedometric) compression alone: delta = R along -e_n, [-R, 0, 0], rho = 1. The
// start of a soil test's cell, which was consolidated by compressing it vertically: its first
// shear is then a 90 deg turn (m_T), a later reversal 180 deg (m_R).
std::array<double, 3> compression_intergranular_strain(double R);

template <class Ops, class S>
struct IntergranularRates {
  typename Ops::template Tensor<S> stress;
  typename Ops::template Tensor<S> delta;
};

// Over any hypoplastic tangent: a type with `Tensor L(const Tensor&) const` and `Tensor N`
// (T_rate = L : D + N ||D||): von Wolffersdorff's HypoplasticTangent, the clay laws' tangents.
template <class Ops, class S, class Tangent>
IntergranularRates<Ops, S> intergranular_strain_rate(const Tangent& h,
                                                     const typename Ops::template Tensor<S>& delta,
                                                     const typename Ops::template Tensor<S>& D,
                                                     const IntergranularStrainParameters& p) {
  using std::pow;
  using Tensor = typename Ops::template Tensor<S>;
  const S norm = safe_sqrt(Ops::contract(delta, delta));
  const S rho = norm / p.R;
  if (!(value_of(norm) > 0.0))  // delta = 0: no direction, the reversal stiffness m_R L
    return {p.m_R * h.L(D), D};
  const Tensor dir = delta / norm;
  const S along = Ops::contract(dir, D);
  const S rho_chi = pow(value_of(rho) < 1.0 ? rho : S(1.0), p.chi);  // capped (ERRATA 10)
  const Tensor stiff = (rho_chi * p.m_T + (1.0 - rho_chi) * p.m_R) * h.L(D);
  if (value_of(along) > 0.0)
    return {stiff + (rho_chi * (1.0 - p.m_T) * along) * h.L(dir) + (rho_chi * along) * h.N,
            D - (pow(rho, p.beta_r) * along) * dir};
  return {stiff + (rho_chi * (p.m_R - p.m_T) * along) * h.L(dir), D};
}

}  // namespace iwb::models
