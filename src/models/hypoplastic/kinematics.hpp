#pragma once
// How an interface element's strain maps onto each algebra's stretching, and how its stresses are
// read back: the only place the three element types differ apart from the algebra itself.
#include <Eigen/Core>
#include <array>
#include <string>

#include "algebra/ops.hpp"
#include "models/model.hpp"

namespace iwb::models {

// Reduced 4-vectors [sigma_n, sigma_p, tau_x, tau_y] (seed 5.2, 5.4). HvWE keeps the in-plane
// strain zero (eq. 5.4) and sigma_p free; AH and AHE put eps_n on the whole diagonal of D and
// start from sigma_p = sigma_n (eqs. 5.16-5.19), which keeps sigma_p = sigma_n for ever.
template <class OpsT>
struct ReducedInterfaceKinematics {
  using Ops = OpsT;
  bool isotropic_in_plane = false;

  template <class S>
  typename Ops::template Tensor<S> stretching(const InterfaceStrainT<S>& d) const {
    return {d.eps_n, isotropic_in_plane ? d.eps_n : S(0.0), 0.5 * d.gamma_x, 0.5 * d.gamma_y};
  }
  typename Ops::template Tensor<double> initial_stress(const InitialState& s) const {
    const double k0 = isotropic_in_plane ? 1.0 : s.K0;
    return {-s.sigma_n, -k0 * s.sigma_n, 0.0, 0.0};
  }
  InterfaceStress stress(const typename Ops::template Tensor<double>& t) const {
    return {-t(0), -t(1), t(2), t(3)};
  }
  static std::vector<std::string> component_names() { return {"T_n", "T_p", "T_x", "T_y"}; }
  // The reduced intergranular strain has delta_p = 0 (eq. 5.48), also for AHE whose stretching
  // carries eps_n in plane: its in-plane part loads no intergranular strain.
  template <class S>
  typename Ops::template Tensor<S> intergranular(typename Ops::template Tensor<S> delta) const {
    delta(1) = S(0.0);
    return delta;
  }
  static constexpr bool kSecondShearDirection = true;
};

// Full 3x3 tensors driven in simple shear: lateral strains zero, D_11 = eps_n, D_12 = gamma_x/2,
// D_13 = gamma_y/2 (seed 5.2, ERRATA item 3).
struct SimpleShearKinematics {
  using Ops = algebra::Tensor3Ops;

  template <class S>
  typename Ops::template Tensor<S> stretching(const InterfaceStrainT<S>& d) const {
    typename Ops::template Tensor<S> D = Ops::template Tensor<S>::Zero();
    D(0, 0) = d.eps_n;
    D(0, 1) = D(1, 0) = 0.5 * d.gamma_x;
    D(0, 2) = D(2, 0) = 0.5 * d.gamma_y;
    return D;
  }
  Ops::Tensor<double> initial_stress(const InitialState& s) const {
    return Eigen::Vector3d(-s.sigma_n, -s.K0 * s.sigma_n, -s.K0 * s.sigma_n).asDiagonal();
  }
  InterfaceStress stress(const Ops::Tensor<double>& t) const {
    return {-t(0, 0), -t(1, 1), t(0, 1), t(0, 2)};
  }
  static std::vector<std::string> component_names() {
    return {"T_11", "T_22", "T_33", "T_12", "T_13", "T_23"};
  }
  // In simple shear D_22 = D_33 = D_23 = 0, so the lateral intergranular strain stays as it
  // starts (zero): nothing to project.
  template <class S>
  typename Ops::template Tensor<S> intergranular(
      const typename Ops::template Tensor<S>& delta) const {
    return delta;
  }
  static constexpr bool kSecondShearDirection = true;
};

// Gutjahr's 1D vectors [sigma_n, tau] and [eps_n, gamma] (eqs. 3.73, 3.74): one shear direction.
struct ShearPlaneKinematics {
  using Ops = algebra::ShearPlaneOps;

  template <class S>
  typename Ops::template Tensor<S> stretching(const InterfaceStrainT<S>& d) const {
    return {d.eps_n, d.gamma_x};
  }
  Ops::Tensor<double> initial_stress(const InitialState& s) const { return {-s.sigma_n, 0.0}; }
  InterfaceStress stress(const Ops::Tensor<double>& t) const { return {-t(0), {}, t(1), 0.0}; }
  static std::vector<std::string> component_names() { return {"T_n", "T_x"}; }
  // hp1d has no -igs variant; the shared model class still names the projection.
  template <class S>
  typename Ops::template Tensor<S> intergranular(
      const typename Ops::template Tensor<S>& delta) const {
    return delta;
  }
  static constexpr bool kSecondShearDirection = false;
};

}  // namespace iwb::models
