#pragma once
// The hypoplastic family as one class over a kinematics policy (how the element's strain maps onto
// the algebra) and a rate law (von Wolffersdorff's for sand, Masin's for clay: anything with a
// tangent L, N and a domain, see VonWolffersdorffLaw). State: the packed stress tensor, the void
// ratio and, with intergranular strain, the packed delta; the intergranular strain is written once
// (intergranular_strain.hpp) over the law's L and N.
#include <fmt/core.h>

#include <array>
#include <cmath>
#include <optional>
#include <string>

#include "common/errors.hpp"
#include "models/hypoplastic/intergranular_strain.hpp"
#include "models/hypoplastic/kinematics.hpp"
#include "models/hypoplastic/von_wolffersdorff.hpp"
#include "models/model.hpp"

namespace iwb::models {

// The external variables a law reads (Masin & Khalili's temperature and suction): its
// `kExternals`, none for the others.
template <class Law>
constexpr auto law_externals() {
  if constexpr (requires { Law::kExternals; })
    return Law::kExternals;
  else
    return std::array<External, 0>{};
}

template <class Kinematics, class Law = VonWolffersdorffLaw>
class HypoplasticModel final : public Model {
  using Ops = typename Kinematics::Ops;
  using Constants = typename Law::Constants;
  static constexpr int kVoidRatio = Ops::kPackedSize;
  // A law that reads external variables keeps their values after e, the net stress first (the
  // stress a test applies; the law derives its effective stress) and gives e's rate itself.
  static constexpr auto kExternals = law_externals<Law>();
  static constexpr int kExternalCount = int(kExternals.size());
  static constexpr int kFirstExternal = kVoidRatio + 1;
  static constexpr int kDelta =
      kFirstExternal + kExternalCount;  // first intergranular strain component

 public:
  // tr 1 of the element's algebra: 3 for tensors and reduced vectors, 1 for Gutjahr's 1D vectors.
  static double trace_of_unit() { return value_of(Ops::trace(Ops::template unit<double>())); }

  HypoplasticModel(std::string name, Kinematics kin, const Constants& constants,
                   std::optional<IntergranularStrainParameters> igs = std::nullopt)
      : name_(std::move(name)), kin_(kin), c_(constants), igs_(igs) {
    if (kExternalCount > 0 && igs_)
      throw InputError(fmt::format(
          "{}: the intergranular strain is not defined for a law that reads temperature "
          "or suction",
          name_));
  }

  std::string_view name() const override { return name_; }
  int state_size() const override { return Ops::kPackedSize * (igs_ ? 2 : 1) + 1 + kExternalCount; }
  std::vector<std::string> state_names() const override {
    auto names = Kinematics::component_names();
    names.push_back("e");
    for (External x : kExternals) names.push_back(external_key(x));
    if (igs_)
      for (const auto& t : Kinematics::component_names()) names.push_back("delta" + t.substr(1));
    return names;
  }
  bool has_second_shear_direction() const override { return Kinematics::kSecondShearDirection; }
  bool reads_external(External slot) const override {
    for (External x : kExternals)
      if (x == slot) return true;
    return false;
  }
  const Constants& constants() const { return c_; }

  StateVector initial_state(const InitialState& init) const override {
    const StateVector s = start_of(init);
    std::string why = domain_violation(s);
    if (why.empty() && init.outside_boundary == OutsideBoundary::kRefuse) why = outside_boundary(s);
    if (!why.empty())
      throw InputError(
          fmt::format("{} is not admissible for {}: {}", described(init, s), name_, why));
    return s;
  }

  std::vector<std::string> initial_warnings(const InitialState& init) const override {
    if (init.outside_boundary != OutsideBoundary::kWarn) return {};
    const StateVector s = start_of(init);
    if (!domain_violation(s).empty()) return {};  // initial_state refuses it
    const std::string why = outside_boundary(s);
    if (why.empty()) return {};
    return {fmt::format("{} is taken as given for {}, though {}", described(init, s), name_, why)};
  }

  void rate(const StateVector& s, const InterfaceStrain& d, StateVector& ds) const override {
    rate_impl<double>(s, d, ds);
  }
  void rate(const StateVectorT<Dual>& s, const InterfaceStrainT<Dual>& d,
            StateVectorT<Dual>& ds) const override {
    rate_impl<Dual>(s, d, ds);
  }

  InterfaceStress stress(const StateVector& s) const override {
    return kin_.stress(Ops::template unpack<double>(s, 0));
  }
  double void_ratio(const StateVector& s) const override { return s(kVoidRatio); }

  std::string domain_violation(const StateVector& s) const override {
    if (!s.allFinite()) return "state is not finite (NaN or inf)";
    const auto T = law_stress(s);
    const double tr = Ops::trace(T);
    if (!(tr < -kMinimumPressure_kPa))
      return fmt::format("no compression: tr T = {:.6g} kPa (contact lost)", tr);
    return Law::domain_violation(stress_invariants<Ops>(T), s(kVoidRatio), c_);
  }

  // Stress and intergranular strain each against their own largest component; e is a scalar.
  void flush_negligible_components(StateVector& s) const override {
    flush_negligible(s.head(Ops::kPackedSize));
    if (igs_) flush_negligible(s.segment(kDelta, Ops::kPackedSize));
  }

  StateVector error_scale(const StateVector& s) const override {
    const auto t = Ops::template unpack<double>(s, 0);
    StateVector scale = StateVector::Constant(state_size(), std::sqrt(Ops::contract(t, t)));
    scale(kVoidRatio) = std::abs(s(kVoidRatio));
    // T_K and s follow their path exactly (their rate is the given increment); 1 K or 1 kPa keeps
    // a zero suction from dividing by zero
    for (int i = 0; i < kExternalCount; ++i)
      scale(kFirstExternal + i) = std::max(std::abs(s(kFirstExternal + i)), 1.0);
    if (igs_) scale.tail(Ops::kPackedSize).setConstant(igs_->R);  // delta is measured against R
    return scale;
  }

  std::vector<NamedValue> diagnostics(const StateVector& s) const override {
    const auto t = Ops::template unpack<double>(s, 0);
    if constexpr (kExternalCount > 0) {
      return Law::template diagnostics_at<Ops>(t, s(kVoidRatio), externals_of<double>(s), c_);
    } else {
      auto out = Law::diagnostics(stress_invariants<Ops>(t), s(kVoidRatio), c_);
      if (igs_) {
        const auto delta = Ops::template unpack<double>(s, kDelta);
        out.push_back({"rho", std::sqrt(Ops::contract(delta, delta)) / igs_->R});
      }
      return out;
    }
  }

 private:
  // The state the inputs give, not yet checked against the law's domain.
  StateVector start_of(const InitialState& init) const {
    StateVector s(state_size());
    Ops::template pack<double>(kin_.initial_stress(init), s, 0);
    s(kVoidRatio) = init.e0;
    if constexpr (kExternalCount > 0)
      for (int i = 0; i < kExternalCount; ++i) {
        const auto given = init.named.find(external_key(kExternals[std::size_t(i)]));
        s(kFirstExternal + i) = given != init.named.end()
                                    ? given->second
                                    : Law::initial_external(kExternals[std::size_t(i)], c_);
      }
    // a law that knows its asymptotic state boundary surface may be given the density as an OCR
    // (from the invariants, or from the stress tensor where the surface needs the principal ratio)
    if (const auto ocr = init.named.find("OCR"); ocr != init.named.end()) {
      const auto T = Ops::template unpack<double>(s, 0);
      if constexpr (kExternalCount > 0)
        s(kVoidRatio) =
            Law::template void_ratio_at_state<Ops>(T, externals_of<double>(s), ocr->second, c_);
      else if constexpr (requires { Law::void_ratio_at(StressInvariants{}, 1.0, c_); })
        s(kVoidRatio) = Law::void_ratio_at(stress_invariants<Ops>(T), ocr->second, c_);
      else if constexpr (requires { Law::template void_ratio_at_stress<Ops>(T, 1.0, c_); })
        s(kVoidRatio) = Law::template void_ratio_at_stress<Ops>(T, ocr->second, c_);
    }
    if (igs_)
      Ops::template pack<double>(initial_intergranular_strain(init), s, kDelta);
    else if (init.delta)
      throw InputError(
          fmt::format("{} has no intergranular strain; an initial delta is meaningless "
                      "for it (use {}-igs)",
                      name_, name_));
    return s;
  }

  // Why a start lies outside the law's state boundary surface (clay: looser than the surface at
  // its stress), from the invariants, the stress tensor or, with externals, the whole state as
  // the law needs; empty inside it or for a law without one.
  std::string outside_boundary(const StateVector& s) const {
    const auto T = Ops::template unpack<double>(s, 0);
    const double e = s(kVoidRatio);
    if constexpr (requires { Law::initial_violation(StressInvariants{}, 0.0, c_); })
      return Law::initial_violation(stress_invariants<Ops>(T), e, c_);
    else if constexpr (requires {
                         Law::template initial_violation_at_state<Ops>(T, 0.0,
                                                                       externals_of<double>(s), c_);
                       })
      return Law::template initial_violation_at_state<Ops>(T, e, externals_of<double>(s), c_);
    else if constexpr (requires { Law::template initial_violation_at_stress<Ops>(T, 0.0, c_); })
      return Law::template initial_violation_at_stress<Ops>(T, e, c_);
    else
      return {};
  }

  std::string described(const InitialState& init, const StateVector& s) const {
    return fmt::format("initial state (sigma_n0 = {:g} kPa, K0 = {:g}, e0 = {:g})", init.sigma_n,
                       init.K0, s(kVoidRatio));
  }

  template <class S>
  void rate_impl(const StateVectorT<S>& s, const InterfaceStrainT<S>& d,
                 StateVectorT<S>& ds) const {
    const auto T = Ops::template unpack<S>(s, 0);
    const auto D = kin_.template stretching<S>(d);
    const S e = s(kVoidRatio);
    ds.resize(state_size());
    if constexpr (kExternalCount > 0) {
      // the externals' rates are their given increments; the law gives the stress's and e's
      std::array<S, kExternalCount> dx;
      for (int i = 0; i < kExternalCount; ++i)
        ds(kFirstExternal + i) = dx[std::size_t(i)] = d.external_of(kExternals[std::size_t(i)]);
      const auto r = Law::template rate<Ops, S>(T, e, D, externals_of<S>(s), dx, c_);
      Ops::template pack<S>(r.net_stress, ds, 0);
      ds(kVoidRatio) = r.void_ratio;
    } else {
      mechanical_rate<S>(s, T, D, e, ds);
    }
  }

  template <class S>
  void mechanical_rate(const StateVectorT<S>& s, const typename Ops::template Tensor<S>& T,
                       const typename Ops::template Tensor<S>& D, const S& e,
                       StateVectorT<S>& ds) const {
    ds(kVoidRatio) = (1.0 + e) * Ops::trace(D);  // ERRATA item 6
    if (!igs_) {
      Ops::template pack<S>(Law::template rate<Ops, S>(T, e, D, c_), ds, 0);
      return;
    }
    // the intergranular strain needs the law's split L : D + N ||D|| (a Law without `tangent`,
    // Barodesy, is never built with it: make_member)
    if constexpr (requires { Law::template tangent<Ops, S>(T, e, c_); }) {
      const auto delta = Ops::template unpack<S>(s, kDelta);
      const auto r = intergranular_strain_rate<Ops, S>(Law::template tangent<Ops, S>(T, e, c_),
                                                       delta, D, *igs_);
      Ops::template pack<S>(r.stress, ds, 0);
      Ops::template pack<S>(kin_.template intergranular<S>(r.delta), ds, kDelta);
    }
  }

  template <class S>
  std::array<S, kExternalCount> externals_of(const StateVectorT<S>& s) const {
    std::array<S, kExternalCount> x;
    for (int i = 0; i < kExternalCount; ++i) x[std::size_t(i)] = s(kFirstExternal + i);
    return x;
  }

  // The stress the law's domain is about: the effective stress of a law with suction, else the
  // state's.
  typename Ops::template Tensor<double> law_stress(const StateVector& s) const {
    const auto T = Ops::template unpack<double>(s, 0);
    if constexpr (kExternalCount > 0)
      return Law::template effective_stress<Ops, double>(T, externals_of<double>(s), c_);
    else
      return T;
  }

  // Given [delta_n, delta_x, delta_y] or the seed's default, as the stretching-shaped tensor of
  // the element's algebra (delta_x is a tensor component, hence gamma = 2 delta_x).
  typename Ops::template Tensor<double> initial_intergranular_strain(
      const InitialState& init) const {
    const auto d = init.delta.value_or(init.delta_along_compression
                                           ? compression_intergranular_strain(igs_->R)
                                           : seed_initial_intergranular_strain(igs_->R));
    return kin_.template intergranular<double>(
        kin_.template stretching<double>(InterfaceStrain{d[0], 2.0 * d[1], 2.0 * d[2]}));
  }

  std::string name_;
  Kinematics kin_;
  Constants c_;
  std::optional<IntergranularStrainParameters> igs_;
};

}  // namespace iwb::models
