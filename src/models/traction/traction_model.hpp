#pragma once
// What the reference interface models of seed 3.3 (mc, hyperbolic) share: their state begins with
// the interface traction [T_n, tau_x, tau_y] (T_n = -sigma_n, every model's component 0), they have
// no void ratio and no in-plane stress, and they evaluate one template on double and Dual
// (CRTP: Derived::rate_of, and Derived::update_of for a closed-form return). The physics stays in
// each model's folder.
#include <fmt/core.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "common/errors.hpp"
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
  bool updates_by_increment() const override { return closed_form(); }
  void update(const StateVector& s, const InterfaceStrain& d, StateVector& out) const override {
    if constexpr (closed_form())
      self().update_of(s, d, out);
    else
      Model::update(s, d, out);
  }
  void update(const StateVectorT<Dual>& s, const InterfaceStrainT<Dual>& d,
              StateVectorT<Dual>& out) const override {
    if constexpr (closed_form())
      self().update_of(s, d, out);
    else
      Model::update(s, d, out);
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
  // For a law whose strength or stiffness needs sigma_n > 0 (hyperbolic, api-tz): the start and
  // the states it admits; `why` says what needs compression.
  StateVector unsheared_in_compression(double sigma_n, int size, std::string_view why) const {
    if (!(sigma_n > 0.0))
      throw InputError(
          fmt::format("sigma_n_kPa = {} is not admissible for {}: {}", sigma_n, name(), why));
    return unsheared(sigma_n, size);
  }
  static std::string compression_violation(const StateVector& s, std::string_view why) {
    if (!s.allFinite()) return "non-finite state";
    if (!(-s(kTractionN) > 0.0))
      return fmt::format("sigma_n = {:.6g} kPa: {}", -s(kTractionN), why);
    return {};
  }
  // The stresses' error scale (their magnitude, at least 1 kPa) and `other` for the rest.
  static StateVector traction_error_scale(const StateVector& s, double other) {
    StateVector e = StateVector::Constant(s.size(), other);
    e.head(3).setConstant(std::max(1.0, std::abs(s(kTractionN))));
    return e;
  }

 private:
  const Derived& self() const { return static_cast<const Derived&>(*this); }
  // A model whose increment is a closed-form return (mc, api-tz) defines update_of on double and
  // Dual; the integrator then calls update instead of integrating the rate. Asked here, where
  // Derived is complete and this class its friend.
  static constexpr bool closed_form() {
    return requires(const Derived& m, const StateVector& s, const InterfaceStrain& d,
                    StateVector& out) {
      m.update_of(s, d, out);
    };
  }
};

}  // namespace iwb::models
