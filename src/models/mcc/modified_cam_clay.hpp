#pragma once
// Modified Cam clay (Roscoe & Burland 1968; seed 8.3, eqs. 8.16-8.20), written once over an
// algebra policy (full 3x3 tensors or the seed's reduced interface vectors). Inside, compression
// is positive: sigma = -T, strain increment de = -dD. With p = tr sigma / 3, s = dev sigma,
// q = sqrt(3/2 s:s):
//
//   f = q^2 / M^2 + p (p - p_c) = 0           the ellipse (8.18; the seed writes p_0 for p_c)
//   K = p / kappa, G = 3 K (1 - 2 nu) / (2 (1 + nu))        (8.19: the seed's D^e = diag(p/kappa,
//   3G)) dp_c / p_c = d eps_v^p / (lambda - kappa)              (8.20: H = p p_c (2p - p_c)/(lambda
//   - kappa))
//
// lambda and kappa are slopes against ln p of the volumetric (natural) strain, as 8.19 and 8.20
// write them (no 1 + e): Table 8.1's lambda_MCC, kappa_MCC. Associated flow, n = df/dsigma =
// (2p - p_c)/3 1 + 3 s / M^2.
//
// The increment is an implicit (backward Euler, closest point) return, exact in the volumetric
// elasticity: p = p_n exp(d eps_v^e / kappa). G is taken at the end of the increment (G = g p,
// g = 3 (1 - 2 nu)/(2 kappa (1 + nu))). Isotropic elasticity makes the deviatoric return radial,
// s = s^tr(p) / (1 + 6 G dlambda / M^2), s^tr(p) = s_n + 2 g p de_dev, which leaves three scalar
// unknowns x = (ln p, ln p_c, dlambda) and three equations:
//   r1 = ln p - ln p_n - (de_v - dlambda (2p - p_c)) / kappa
//   r2 = ln p_c - ln p_c,n - dlambda (2p - p_c) / (lambda - kappa)
//   r3 = f(p, q, p_c) / p_c,n^2
// solved by Newton with the exact Jacobian; f = 0 to round-off at the end of every plastic
// increment. On dual numbers one more Newton step from the converged values carries the exact
// derivative of the increment (implicit function theorem), the consistent tangent.
#include <fmt/core.h>

#include <Eigen/Dense>
#include <cmath>
#include <string>
#include <type_traits>
#include <utility>

#include "common/errors.hpp"
#include "common/scalar.hpp"

namespace iwb::models {

struct CamClayParameters {
  double lambda;  // slope of the isotropic normal compression line, eps_v against ln p
  double kappa;   // slope of the unloading-reloading line, eps_v against ln p
  double M;       // critical state stress ratio q / p
  double nu;      // Poisson's ratio of the elasticity

  // G / p = 3 (1 - 2 nu) / (2 kappa (1 + nu))
  double shear_per_p() const { return 3.0 * (1.0 - 2.0 * nu) / (2.0 * kappa * (1.0 + nu)); }
};

// A stress point of the model: tension-positive stress tensor and the preconsolidation pressure.
template <class Ops, class S>
struct CamClayPoint {
  typename Ops::template Tensor<S> T;
  S p_c;
};

// p, s and q of a tension-positive stress, compression positive.
template <class Ops, class S>
struct CamClayInvariants {
  using Tensor = typename Ops::template Tensor<S>;
  S p;
  Tensor s;
  S q;

  explicit CamClayInvariants(const Tensor& T) {
    const Tensor sigma = -T;
    p = Ops::trace(sigma) / 3.0;
    s = sigma - p * Ops::template unit<S>();
    q = safe_sqrt(S(1.5 * Ops::contract(s, s)));
  }
};

// The yield function f = q^2 / M^2 + p (p - p_c), kPa^2.
template <class S>
S cam_clay_yield(const S& p, const S& q, const S& p_c, double M) {
  return q * q / (M * M) + p * (p - p_c);
}

namespace detail {

inline constexpr int kCamClayNewtonIterations = 50;

template <class Ops, class S>
typename Ops::template Tensor<double> values_of_tensor(const typename Ops::template Tensor<S>& t) {
  return t.unaryExpr([](const S& x) { return value_of(x); });
}

// One increment's data: the start's p, s and p_c, the strain increment's volumetric and deviatoric
// parts (compression positive), and the residual r(x) of the return at x = (ln p, ln p_c, dlambda).
template <class Ops, class S>
struct CamClayReturn {
  using Tensor = typename Ops::template Tensor<S>;
  CamClayInvariants<Ops, S> start;
  S p_c;
  S de_v;
  Tensor de_dev;
  CamClayParameters c;

  // s^tr(p) = s_n + 2 g p de_dev
  Tensor trial_deviator(const S& p) const { return start.s + (2.0 * c.shear_per_p() * p) * de_dev; }
  S radial_scale(const S& p, const S& dl) const {
    return 1.0 + 6.0 * c.shear_per_p() * p * dl / (c.M * c.M);
  }
  Tensor stress(const S& p, const S& dl) const {
    return -(p * Ops::template unit<S>() + trial_deviator(p) / radial_scale(p, dl));
  }

  Eigen::Matrix<S, 3, 1> residual(const S& u, const S& w, const S& dl) const {
    using std::exp;
    using std::log;
    const S p = exp(u), pc = exp(w);
    const S eps_vp = dl * (2.0 * p - pc);
    const Tensor a = trial_deviator(p);
    const S q = safe_sqrt(S(1.5 * Ops::contract(a, a))) / radial_scale(p, dl);
    return {u - log(start.p) - (de_v - eps_vp) / c.kappa,
            w - log(p_c) - eps_vp / (c.lambda - c.kappa),
            cam_clay_yield(p, q, pc, c.M) / (p_c * p_c)};
  }
};

// The Jacobian dr/dx of CamClayReturn::residual at x, on values.
template <class Ops>
Eigen::Matrix3d cam_clay_jacobian(const CamClayReturn<Ops, double>& r, const Eigen::Vector3d& x) {
  const auto& c = r.c;
  const double g = c.shear_per_p(), M2 = c.M * c.M, lk = c.lambda - c.kappa;
  const double p = std::exp(x(0)), pc = std::exp(x(1)), dl = x(2), pc2 = r.p_c * r.p_c;
  const auto a = r.trial_deviator(p);
  const double A = std::sqrt(1.5 * Ops::contract(a, a));
  const double dA_dp =
      A > 0.0
          ? 1.5 * Ops::contract(a, typename Ops::template Tensor<double>(2.0 * g * r.de_dev)) / A
          : 0.0;
  const double scale = r.radial_scale(p, dl), q = A / scale;
  const double dq_dp = dA_dp / scale - A / (scale * scale) * 6.0 * g * dl / M2;
  const double dq_ddl = -A / (scale * scale) * 6.0 * g * p / M2;
  Eigen::Matrix3d J;
  J << 1.0 + 2.0 * p * dl / c.kappa, -pc * dl / c.kappa, (2.0 * p - pc) / c.kappa,  //
      -2.0 * p * dl / lk, 1.0 + pc * dl / lk, -(2.0 * p - pc) / lk,                 //
      p * (2.0 * q * dq_dp / M2 + 2.0 * p - pc) / pc2, -p * pc / pc2, 2.0 * q * dq_ddl / M2 / pc2;
  return J;
}

// Newton from the trial state (x0); the converged x and its Jacobian. DomainError if it fails.
template <class Ops>
std::pair<Eigen::Vector3d, Eigen::Matrix3d> solve_cam_clay_return(
    const CamClayReturn<Ops, double>& r, Eigen::Vector3d x) {
  for (int it = 0; it < kCamClayNewtonIterations; ++it) {
    const Eigen::Vector3d res = r.residual(x(0), x(1), x(2));
    const Eigen::Matrix3d J = cam_clay_jacobian(r, x);
    const Eigen::Vector3d dx = J.partialPivLu().solve(-res);
    if (!dx.allFinite()) break;
    x += dx;
    // quadratic convergence: a step this small leaves an error of its square
    if ((std::abs(dx(0)) < 1e-13 && std::abs(dx(1)) < 1e-13 &&
         std::abs(dx(2)) <= 1e-13 * std::abs(x(2))) ||
        res.cwiseAbs().maxCoeff() < 1e-15)
      return {x, cam_clay_jacobian(r, x)};
  }
  throw DomainError(fmt::format(
      "modified Cam clay: the return did not converge in {} iterations (p = {:.6g} kPa, "
      "p_c = {:.6g} kPa, dlambda = {:.3g}): the increment is too large",
      kCamClayNewtonIterations, std::exp(x(0)), std::exp(x(1)), x(2)));
}

}  // namespace detail

// One increment dD (tension-positive stretching increment) from `n`: elastic when the trial state
// lies inside the ellipse, else the implicit return above. Throws DomainError when the Newton
// iteration does not converge (the caller cuts the increment).
template <class Ops, class S>
CamClayPoint<Ops, S> cam_clay_increment(const CamClayPoint<Ops, S>& n,
                                        const typename Ops::template Tensor<S>& dD,
                                        const CamClayParameters& c) {
  using std::exp;
  using Tensor = typename Ops::template Tensor<S>;
  const detail::CamClayReturn<Ops, S> ret{
      CamClayInvariants<Ops, S>(n.T), n.p_c, -Ops::trace(dD),
      Tensor(-dD + (Ops::trace(dD) / 3.0) * Ops::template unit<S>()), c};
  const S p_tr = ret.start.p * exp(ret.de_v / c.kappa);
  const CamClayInvariants<Ops, S> trial(ret.stress(p_tr, S(0.0)));
  if (value_of(cam_clay_yield(trial.p, trial.q, n.p_c, c.M)) <= 0.0)
    return {ret.stress(p_tr, S(0.0)), n.p_c};

  const detail::CamClayReturn<Ops, double> on_values{
      CamClayInvariants<Ops, double>(detail::values_of_tensor<Ops, S>(n.T)), value_of(n.p_c),
      value_of(ret.de_v), detail::values_of_tensor<Ops, S>(ret.de_dev), c};
  const auto [x, J] = detail::solve_cam_clay_return<Ops>(
      on_values, {std::log(value_of(p_tr)), std::log(value_of(n.p_c)), 0.0});
  if (!(x(2) >= 0.0))
    throw DomainError(
        fmt::format("modified Cam clay: the return found a negative multiplier ({:.3g})", x(2)));
  Eigen::Matrix<S, 3, 1> xs(S(x(0)), S(x(1)), S(x(2)));
  // On double this leaves x; on dual numbers it adds the derivative -J^-1 dr/d(inputs).
  if constexpr (!std::is_same_v<S, double>) {
    const Eigen::Matrix3d J_inv = J.inverse();
    const Eigen::Matrix<S, 3, 1> r = ret.residual(xs(0), xs(1), xs(2));
    for (int i = 0; i < 3; ++i)
      xs(i) -= J_inv(i, 0) * r(0) + J_inv(i, 1) * r(1) + J_inv(i, 2) * r(2);
  }
  return {ret.stress(exp(xs(0)), xs(2)), exp(xs(1))};
}

// The rate form (the return's limit for a small increment): D^e inside or when unloading, else
// D^ep = D^e - (D^e n)(n : D^e) / (n : D^e n + H), H = p p_c (2p - p_c) / (lambda - kappa).
// `on_surface` is the caller's judgement that f = 0 (to round-off). Returns (dT, dp_c) for the
// stretching D.
template <class Ops, class S>
CamClayPoint<Ops, S> cam_clay_rate(const CamClayPoint<Ops, S>& n,
                                   const typename Ops::template Tensor<S>& D,
                                   const CamClayParameters& c, bool on_surface) {
  using Tensor = typename Ops::template Tensor<S>;
  const Tensor unit = Ops::template unit<S>();
  const CamClayInvariants<Ops, S> inv(n.T);
  const S K = inv.p / c.kappa, G = c.shear_per_p() * inv.p;
  const auto elastic = [&](const Tensor& X) {  // D^e : X, compression positive
    const S tr = Ops::trace(X);
    return Tensor((K * tr) * unit + (2.0 * G) * (X - (tr / 3.0) * unit));
  };
  const Tensor de = -D;
  Tensor dsigma = elastic(de);
  S dpc = S(0.0);
  if (on_surface) {
    const Tensor normal = ((2.0 * inv.p - n.p_c) / 3.0) * unit + (3.0 / (c.M * c.M)) * inv.s;
    const S load = Ops::contract(normal, dsigma);
    if (value_of(load) > 0.0) {
      const S H = inv.p * n.p_c * (2.0 * inv.p - n.p_c) / (c.lambda - c.kappa);
      const Tensor de_normal = elastic(normal);
      const S dl = load / (Ops::contract(normal, de_normal) + H);
      dsigma -= dl * de_normal;
      dpc = n.p_c * dl * (2.0 * inv.p - n.p_c) / (c.lambda - c.kappa);
    }
  }
  return {-dsigma, dpc};
}

}  // namespace iwb::models
