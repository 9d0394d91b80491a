// hyperbolic: Clough & Duncan's (1971) non-linear elastic interface model (seed 3.3.2, Table 3.2):
// tau rises along the hyperbola tau = u / (1/K_si + R_f u / tau_f) (eq. 3.51), the tangent
// K_s = K_si (1 - R_f tau / tau_f)^2 (eq. 3.52) with K_si = K_I gamma_w (sigma_n / p_a)^n_HY
// (eq. 3.49) and tau_f = sigma_n tan(delta) (eq. 3.50); unloading and reloading below the largest
// stress level reached are elastic with K_ur = K_I,ur gamma_w (sigma_n / p_a)^n_HY (Duncan & Chang
// 1970; the seed states no unloading rule); at the failure stress (stress level 1) the shear
// stiffness is 0. The normal stress is linear elastic and uncoupled (eq. 3.53): the model has no
// dilatancy. Stiffnesses are per unit displacement, so the rate on strains scales by the element's
// d_s (ModelInputs::shear_zone_mm). README.md says what was re-derived.
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "common/errors.hpp"
#include "models/registry.hpp"
#include "models/traction/traction_model.hpp"

namespace iwb::models {

namespace {

const ParameterTable& hyperbolic_table() {
  static const ParameterTable t{
      "hyperbolic",
      {{"K_I",
        "-",
        {0.0, true},
        {kUnbounded, true},
        "dimensionless stiffness number of the initial shear stiffness",
        "eq. 3.49",
        ParameterRole::kMaterial,
        CalibrationBox{1e2, 1e6, true}},
       {"K_I_ur",
        "-",
        {0.0, true},
        {kUnbounded, true},
        "stiffness number of unloading and reloading (Duncan & Chang 1970)",
        "README"},
       {"n_HY", "-", {0.0, false}, {2.0, false}, "stiffness exponent", "eq. 3.49"},
       {"R_f",
        "-",
        {0.0, true},
        {1.0, false},
        "failure ratio tau_f / tau_ult",
        "eq. 3.48",
        ParameterRole::kMaterial,
        CalibrationBox{0.5, 1.0, false}},
       {"delta_deg",
        "deg",
        {0.0, true},
        {90.0, true},
        "interface friction angle",
        "eq. 3.50",
        ParameterRole::kMaterial,
        CalibrationBox{15.0, 50.0, false}},
       {"k_n_kPa_per_mm",
        "kPa/mm",
        {0.0, true},
        {kUnbounded, true},
        "normal stiffness (uncoupled, typically high)",
        "eq. 3.53"},
       {"p_a_kPa",
        "kPa",
        {0.0, true},
        {kUnbounded, true},
        "atmospheric pressure of eq. 3.49 (101.325)",
        "eq. 3.49"},
       {"gamma_w_kN_per_m3",
        "kN/m3",
        {0.0, true},
        {kUnbounded, true},
        "unit weight of water of eq. 3.49 (9.81)",
        "eq. 3.49"}}};
  return t;
}

struct HyperbolicParameters {
  double K_I, K_ur, n, R_f, tan_delta, k_n, p_a, gamma_w, d_s_m;
};

// State: [T_n, tau_x, tau_y, stress_level_max]: T_n = -sigma_n; the largest stress level
// ||tau|| / tau_f reached, which decides loading against unloading.
enum : int { kTn = kTractionN, kTauX = kTractionX, kTauY = kTractionY, kLevelMax = 3, kSize = 4 };

class Hyperbolic final : public TractionModel<Hyperbolic> {
 public:
  explicit Hyperbolic(HyperbolicParameters p) : p_(p) {}
  std::string_view name() const override { return "hyperbolic"; }
  int state_size() const override { return kSize; }
  std::vector<std::string> state_names() const override {
    return {"T_n", "tau_x", "tau_y", "stress_level_max"};
  }

  StateVector initial_state(const InitialState& in) const override {
    return unsheared_in_compression(in.sigma_n, kSize,
                                    "its stiffness (eq. 3.49) needs compression");
  }
  std::string domain_violation(const StateVector& s) const override {
    return compression_violation(s, "the hyperbolic stiffness needs compression");
  }
  StateVector error_scale(const StateVector& s) const override {
    return traction_error_scale(s, 1.0);
  }
  std::vector<NamedValue> diagnostics(const StateVector& s) const override {
    return {{"stress_level", level(s)}, {"K_s_kPa_per_mm", 1e-3 * loading_stiffness(s)}};
  }
  friend class TractionModel<Hyperbolic>;

 private:
  HyperbolicParameters p_;

  template <class S>
  S tau_f(const StateVectorT<S>& s) const {
    return -s(kTn) * p_.tan_delta;
  }
  double level(const StateVector& s) const { return std::hypot(s(kTauX), s(kTauY)) / tau_f(s); }
  // Eq. 3.49 times (1 - R_f SL)^2 (eq. 3.52), 0 once the stress level reaches 1; kPa per metre.
  template <class S>
  S loading_stiffness(const StateVectorT<S>& s) const {
    using std::pow;
    const S tau2 = s(kTauX) * s(kTauX) + s(kTauY) * s(kTauY);
    const S sl = safe_sqrt(tau2) / tau_f(s);
    if (value_of(sl) >= 1.0) return S(0.0);
    const S one_minus = 1.0 - p_.R_f * sl;
    const S sigma_ratio = -s(kTn) / p_.p_a;
    return p_.K_I * p_.gamma_w * pow(sigma_ratio, p_.n) * one_minus * one_minus;
  }

  // Loading: the shear increment points along tau (or tau = 0) at the largest stress level reached;
  // otherwise unloading or reloading, elastic with K_ur. Piecewise linear in d: degree one.
  template <class S>
  void rate_of(const StateVectorT<S>& s, const InterfaceStrainT<S>& d, StateVectorT<S>& ds) const {
    using std::pow;
    ds = StateVectorT<S>::Zero(kSize);
    const S along = s(kTauX) * d.gamma_x + s(kTauY) * d.gamma_y;
    const S tau2 = s(kTauX) * s(kTauX) + s(kTauY) * s(kTauY);
    const S tau = safe_sqrt(tau2);
    const S sl = tau / tau_f(s);
    const bool loading =
        value_of(along) >= 0.0 && value_of(sl) >= value_of(s(kLevelMax)) * (1.0 - 1e-12);
    const S sigma_ratio = -s(kTn) / p_.p_a;
    const S K = loading ? loading_stiffness(s) : S(p_.K_ur * p_.gamma_w * pow(sigma_ratio, p_.n));
    const S dsigma_n = -p_.k_n * 1e3 * p_.d_s_m * d.eps_n;  // kPa/mm x mm of opening
    ds(kTn) = -dsigma_n;
    ds(kTauX) = K * p_.d_s_m * d.gamma_x;
    ds(kTauY) = K * p_.d_s_m * d.gamma_y;
    if (loading && value_of(tau) > 0.0) {  // the level's own rate, from tau's and sigma_n's
      const S dtau = (s(kTauX) * ds(kTauX) + s(kTauY) * ds(kTauY)) / tau;
      ds(kLevelMax) = (dtau - sl * dsigma_n * p_.tan_delta) / tau_f(s);
    } else if (loading) {
      ds(kLevelMax) =
          K * p_.d_s_m * safe_sqrt(S(d.gamma_x * d.gamma_x + d.gamma_y * d.gamma_y)) / tau_f(s);
    }
  }
};

}  // namespace

ModelSpec hyperbolic_spec() {
  ModelDeclaration d;
  d.listing_order = 21;  // after mc
  d.layout.components = traction_components();
  d.layout.components.push_back({"stress_level_max", "-", ComponentKind::kHardening});
  d.layout.void_ratio = -1;
  d.initial = {{"sigma_n_kPa", "kPa", "initial normal stress (compression positive)"}};
  d.diagnostics = {{"stress_level", "-", "||tau|| / (sigma_n tan delta): 1 at failure"},
                   {"K_s_kPa_per_mm", "kPa/mm", "loading tangent stiffness (eq. 3.52)"}};
  d.example_parameters = "table_4_4_hyperbolic.toml";
  d.displacement_based = true;
  d.plan_rank = 2;
  d.example_start = {{"sigma_n_kPa", 100.0}};
  return {"hyperbolic",
          "Clough & Duncan (1971) hyperbolic non-linear elastic interface, elastic unloading, no "
          "dilatancy",
          "seed 3.46-3.53, Table 3.2 (3.49 and 3.52 re-read)",
          false,
          {&hyperbolic_table()},
          [](const ModelInputs& in) {
            const auto& v = require_table(in, "hyperbolic");
            require_keys(hyperbolic_table(), v, in.source + " [hyperbolic]");
            return std::make_unique<Hyperbolic>(HyperbolicParameters{
                v.at("K_I"), v.at("K_I_ur"), v.at("n_HY"), v.at("R_f"),
                std::tan(v.at("delta_deg") * M_PI / 180.0), v.at("k_n_kPa_per_mm"), v.at("p_a_kPa"),
                v.at("gamma_w_kN_per_m3"), 1e-3 * in.shear_zone_mm});
          },
          d};
}

}  // namespace iwb::models
