#pragma once
// What the reference interface models of seed 3.3 (mc, hyperbolic) share: their state begins with
// the interface traction [T_n, tau_x, tau_y] (T_n = -sigma_n, every model's component 0), they have
// no void ratio and no in-plane stress, and they evaluate one template on double and Dual
// (CRTP: Derived::rate_of). The physics stays in each model's folder.
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "models/declaration.hpp"
#include "models/model.hpp"

namespace iwb::models {

enum TractionComponent : int { kTractionN = 0, kTractionX = 1, kTractionY = 2 };

// The layout's first three components, for a declaration.
inline std::vector<StateComponent> traction_components() {
  return {{"T_n", "kPa", ComponentKind::kStress},
          {"tau_x", "kPa", ComponentKind::kStress},
          {"tau_y", "kPa", ComponentKind::kStress}};
}

template <class Derived>
class TractionModel : public Model {
 public:
  void rate(const StateVector& s, const InterfaceStrain& d, StateVector& ds) const override {
    self().rate_of(s, d, ds);
  }
  void rate(const StateVectorT<Dual>& s, const InterfaceStrainT<Dual>& d,
            StateVectorT<Dual>& ds) const override {
    self().rate_of(s, d, ds);
  }
  InterfaceStress stress(const StateVector& s) const override {
    return {-s(kTractionN), std::nullopt, s(kTractionX), s(kTractionY)};
  }
  double void_ratio(const StateVector&) const override { return std::nan(""); }
  bool has_second_shear_direction() const override { return true; }

 protected:
  // A state of `size` components at sigma_n, unsheared, everything else zero.
  static StateVector unsheared(double sigma_n, int size) {
    StateVector s = StateVector::Zero(size);
    s(kTractionN) = -sigma_n;
    return s;
  }
  // The stresses' error scale (their magnitude, at least 1 kPa) and `other` for the rest.
  static StateVector traction_error_scale(const StateVector& s, double other) {
    StateVector e = StateVector::Constant(s.size(), other);
    e.head(3).setConstant(std::max(1.0, std::abs(s(kTractionN))));
    return e;
  }

 private:
  const Derived& self() const { return static_cast<const Derived&>(*this); }
};

}  // namespace iwb::models
