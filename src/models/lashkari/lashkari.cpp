// lashkari: Lashkari's (2013) state-parameter elasto-plastic sand-structure interface model (seed
// 3.3.5, Table 3.5; EP2 of chapter 4), on the interface's strains (u / d_s). Equations and the
// readings of the garbled 3.86-3.95 in README.md (docs/derivations/lashkari_2013.md):
//
//   f = ||tau|| - eta sigma_n,   e_c = e_0 - lambda ln(sigma_n / p_ref),   psi = e - e_c
//   K_s = K_s0 sqrt(sigma_n / p_ref),  K_n = K_n0 sqrt(sigma_n / p_ref)        (kPa per unit
//   strain) K_p = h0 K_s (M^b / eta - 1),  M^b = M exp(-n^b psi)                          (3.89) d
//   = A (M^d - eta),  M^d = M exp(n^d psi),  A = A0 s + (A1 - A0 s) eta / M^b,  s = sqrt(p_ref /
//   sigma_n) plastic strain: d eps_c^p = Lambda d (contraction positive), d gamma^p = Lambda along
//   tau Lambda = (d||tau|| - eta d sigma_n) / K_p,  d eta = K_p Lambda / sigma_n     (3.93,
//   consistency)
//
// A rate-form model (integrated by the workbench's integrator). With P = eta K_p = h0 K_s (M^b -
// eta) the multiplier for a strain rate (eps_c, gamma_t along tau) is
//   Lambda = eta (K_s gamma_t - eta K_n eps_c) / (P + eta K_s - eta^2 K_n d),
// regular at eta = 0 (no plastic flow at the start), loading when it is positive.
#include <fmt/core.h>

#include <cmath>
#include <memory>

#include "common/errors.hpp"
#include "models/registry.hpp"
#include "models/traction/traction_model.hpp"

namespace iwb::models {

namespace {

const ParameterTable& lashkari_table() {
  static const ParameterTable t{
      "lashkari",
      {{"K_s0_kPa",
        "kPa",
        {0.0, true},
        {kUnbounded, true},
        "shear stiffness per unit shear strain at p_ref",
        "eq. 3.86, Table 3.5 (kPa, not the printed MPa: README.md)",
        ParameterRole::kMaterial,
        CalibrationBox{1e2, 1e6, true}},
       {"K_n0_kPa",
        "kPa",
        {0.0, true},
        {kUnbounded, true},
        "normal stiffness per unit normal strain at p_ref",
        "eq. 3.86, Table 3.5"},
       {"A0",
        "-",
        {0.0, true},
        {kUnbounded, true},
        "dilatancy factor at the start (times sqrt(p_ref / sigma_n))",
        "eq. 3.95",
        ParameterRole::kMaterial,
        CalibrationBox{0.3, 30.0, true}},
       {"A1", "-", {0.0, true}, {kUnbounded, true}, "dilatancy factor at the peak", "eq. 3.95"},
       {"h0",
        "-",
        {0.0, true},
        {kUnbounded, true},
        "plastic hardening factor",
        "eq. 3.89",
        ParameterRole::kMaterial,
        CalibrationBox{0.05, 5.0, true}},
       {"M",
        "-",
        {0.0, true},
        {5.0, true},
        "critical interface stress ratio tau / sigma_n",
        "eq. 3.89",
        ParameterRole::kMaterial,
        CalibrationBox{0.3, 1.2, false}},
       {"e_c0",
        "-",
        {0.0, true},
        {5.0, true},
        "critical void ratio at p_ref (Table 3.5's 'initial void ratio': README.md)",
        "eq. 3.83",
        ParameterRole::kMaterial,
        CalibrationBox{0.3, 1.5, false}},
       {"lambda",
        "-",
        {0.0, true},
        {2.0, true},
        "slope of the critical state line, e against ln sigma_n",
        "eq. 3.83"},
       {"n_b",
        "-",
        {0.0, false},
        {kUnbounded, true},
        "state dependence of the bounding ratio M^b",
        "eq. 3.89",
        ParameterRole::kMaterial,
        CalibrationBox{0.0, 4.0, false}},
       {"n_d",
        "-",
        {0.0, false},
        {kUnbounded, true},
        "state dependence of the dilatancy ratio M^d",
        "eq. 3.94"},
       {"p_ref_kPa",
        "kPa",
        {0.0, true},
        {kUnbounded, true},
        "reference stress (not printed by the seed: 100 kPa)",
        "eq. 3.83"}}};
  return t;
}

struct LashkariParameters {
  double K_s0, K_n0, A0, A1, h0, M, e_c0, lambda, n_b, n_d, p_ref;
};

LashkariParameters read(const ModelInputs& in) {
  const auto& v = require_table(in, "lashkari");
  validate(lashkari_table(), v, in.source + " [lashkari]");
  return {v.at("K_s0_kPa"), v.at("K_n0_kPa"), v.at("A0"),  v.at("A1"),  v.at("h0"),       v.at("M"),
          v.at("e_c0"),     v.at("lambda"),   v.at("n_b"), v.at("n_d"), v.at("p_ref_kPa")};
}

// State: [T_n, tau_x, tau_y, e, eta]: the traction (T_n = -sigma_n), the void ratio, the stress
// ratio at which the yield surface stands.
enum : int { kE = 3, kEta = 4, kSize = 5 };

// A stress ratio this close below eta counts as on the surface (the integrator's drift is 1e-6).
constexpr double kOnSurface = 1e-5;

class Lashkari final : public TractionModel<Lashkari> {
 public:
  explicit Lashkari(LashkariParameters p) : p_(p) {}
  std::string_view name() const override { return "lashkari"; }
  int state_size() const override { return kSize; }
  std::vector<std::string> state_names() const override {
    return {"T_n", "tau_x", "tau_y", "e", "eta"};
  }
  StateVector initial_state(const InitialState& in) const override {
    StateVector s = unsheared(in.sigma_n, kSize);
    s(kE) = in.e0;
    if (!(in.e0 > 0.0))
      throw InputError(
          fmt::format("e0 = {} is not admissible for lashkari: a void ratio > 0", in.e0));
    return s;
  }
  double void_ratio(const StateVector& s) const override { return s(kE); }
  std::string domain_violation(const StateVector& s) const override {
    if (!s.allFinite()) return "non-finite state";
    if (!(-s(kTractionN) > 0.0))
      return fmt::format("sigma_n = {:.6g} kPa: contact lost", -s(kTractionN));
    if (!(s(kE) > 0.0)) return fmt::format("void ratio e = {:.6g}", s(kE));
    return {};
  }
  StateVector error_scale(const StateVector& s) const override {
    StateVector e = traction_error_scale(s, 1e-3);
    e(kE) = std::abs(s(kE));
    return e;
  }
  std::vector<NamedValue> diagnostics(const StateVector& s) const override {
    const double sigma = -s(kTractionN), tau = std::hypot(s(kTractionX), s(kTractionY));
    const double psi = s(kE) - critical_void_ratio(sigma);
    return {{"e_c", critical_void_ratio(sigma)},
            {"psi", psi},
            {"M_b", p_.M * std::exp(-p_.n_b * psi)},
            {"M_d", p_.M * std::exp(p_.n_d * psi)},
            {"f_yield", tau - s(kEta) * sigma}};
  }
  friend class TractionModel<Lashkari>;

 private:
  LashkariParameters p_;

  double critical_void_ratio(double sigma_n) const {
    return p_.e_c0 - p_.lambda * std::log(sigma_n / p_.p_ref);
  }

  template <class S>
  void rate_of(const StateVectorT<S>& s, const InterfaceStrainT<S>& d, StateVectorT<S>& ds) const {
    using std::exp;
    using std::log;
    using std::sqrt;
    ds = StateVectorT<S>::Zero(kSize);
    const S sigma = -s(kTractionN), eta = s(kEta), e = s(kE);
    const S root = sqrt(sigma / p_.p_ref);
    const S K_s = p_.K_s0 * root, K_n = p_.K_n0 * root;
    const S eps_c = -d.eps_n;  // contraction positive
    // the shear direction: tau's, or the shear rate's from an unsheared state
    const S tau = safe_sqrt(S(s(kTractionX) * s(kTractionX) + s(kTractionY) * s(kTractionY)));
    const S rate = safe_sqrt(S(d.gamma_x * d.gamma_x + d.gamma_y * d.gamma_y));
    S nx = S(1.0), ny = S(0.0);
    if (value_of(tau) > 0.0)
      nx = s(kTractionX) / tau, ny = s(kTractionY) / tau;
    else if (value_of(rate) > 0.0)
      nx = d.gamma_x / rate, ny = d.gamma_y / rate;
    const S gamma_t = nx * d.gamma_x + ny * d.gamma_y;
    const S psi = e - (p_.e_c0 - p_.lambda * log(sigma / p_.p_ref));
    const S M_b = p_.M * exp(-p_.n_b * psi), M_d = p_.M * exp(p_.n_d * psi);
    const S A =
        p_.A0 / root + (p_.A1 - p_.A0 / root) * eta / M_b;  // s = sqrt(p_ref / sigma) = 1 / root
    const S dil = A * (M_d - eta);
    const S P = p_.h0 * K_s * (M_b - eta);  // eta K_p
    // Loading: on the surface (the stress ratio at eta, to the integrator's drift) and the trial
    // moving outwards. Then Lambda = eta N / Den and d eta = P N / (sigma Den), regular at eta = 0.
    const S N = K_s * gamma_t - eta * K_n * eps_c;
    const S Den = P + eta * K_s - eta * eta * K_n * dil;
    const bool on_surface = value_of(tau) >= value_of(eta * sigma) * (1.0 - kOnSurface);
    const bool loading = on_surface && value_of(N) > 0.0 && value_of(Den) > 0.0;
    const S lambda = loading ? S(eta * N / Den) : S(0.0);
    const S dsigma = K_n * (eps_c - lambda * dil);
    ds(kTractionN) = -dsigma;
    ds(kTractionX) = K_s * (d.gamma_x - lambda * nx);
    ds(kTractionY) = K_s * (d.gamma_y - lambda * ny);
    ds(kE) = (1.0 + e) * d.eps_n;
    ds(kEta) = loading ? S(P * N / (sigma * Den)) : S(0.0);
  }
};

}  // namespace

ModelSpec lashkari_spec() {
  ModelDeclaration d;
  d.listing_order = 22;  // after mc (20) and hyperbolic (21)
  d.layout.components = traction_components();
  d.layout.components.push_back({"e", "-", ComponentKind::kVoidRatio});
  d.layout.components.push_back({"eta", "-", ComponentKind::kHardening});
  d.layout.void_ratio = kE;
  d.initial = {
      {"sigma_n_kPa", "kPa", "initial normal stress (compression positive)"},
      {"e0", "-", "initial void ratio (psi = e0 - e_c at sigma_n0: dense below e_c, loose above)"}};
  d.diagnostics = {
      {"e_c", "-", "critical void ratio at sigma_n (eq. 3.83)", DiagnosticRole::kCriticalVoidRatio},
      {"psi", "-", "state parameter e - e_c (eq. 3.84)"},
      {"M_b", "-", "bounding stress ratio M exp(-n_b psi) (eq. 3.89): the peak"},
      {"M_d", "-", "dilatancy stress ratio M exp(n_d psi) (eq. 3.94): no volume change"},
      {"f_yield", "kPa", "||tau|| - eta sigma_n: 0 while loading", DiagnosticRole::kYieldFunction}};
  d.example_parameters = "table_4_7_lashkari.toml";
  d.plan_rank = 6;
  d.example_start = {{"sigma_n_kPa", 100.0}, {"e0", 0.7}};
  return {"lashkari",
          "Lashkari (2013) state-parameter elasto-plastic sand-structure interface model (bounding "
          "and dilatancy ratios in psi)",
          "seed 3.82-3.95, Table 3.5 (3.94 read d = A (M^d - eta); README.md)",
          false,
          {&lashkari_table()},
          [](const ModelInputs& in) { return std::make_unique<Lashkari>(read(in)); },
          d};
}

}  // namespace iwb::models
