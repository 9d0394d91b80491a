// mc: the Mohr-Coulomb interface model of seed 3.3.1 (Van Langen 1991; Table 3.1) on the
// interface's strains (u / d_s, as every interface model here): linear elasticity D^e = diag(E_oed,
// G, G) (eqs. 3.36-3.37), the yield function f = ||tau|| - sigma_n tan(phi_i) - c and the plastic
// potential g = ||tau|| - sigma_n tan(psi) (eqs. 3.38, 3.40, compression positive: ERRATA-to-be,
// README.md), and a tension cut-off sigma_n >= -sigma_t. The increment is a closed-form return
// (StressPointUpdate::kIncrement): linear in the plastic multiplier, so the yield condition holds
// to round-off after every increment, and on Dual numbers it carries the consistent tangent.
#include <fmt/core.h>

#include <cmath>
#include <memory>

#include "common/errors.hpp"
#include "models/registry.hpp"
#include "models/traction/traction_model.hpp"

namespace iwb::models {

namespace {

constexpr double kDegree = M_PI / 180.0;

const ParameterTable& mohr_coulomb_table() {
  static const ParameterTable t{
      "mohr_coulomb",
      {{"E_kPa",
        "kPa",
        {0.0, true},
        {kUnbounded, true},
        "Young's modulus of the interface zone",
        "Table 3.1, eq. 3.37",
        ParameterRole::kMaterial,
        CalibrationBox{1e3, 1e6, true}},
       {"nu", "-", {0.0, false}, {0.5, true}, "Poisson's ratio", "Table 3.1, eq. 3.37"},
       {"phi_i_deg",
        "deg",
        {0.0, true},
        {90.0, true},
        "interface friction angle",
        "eq. 3.38",
        ParameterRole::kMaterial,
        CalibrationBox{15.0, 50.0, false}},
       {"psi_deg",
        "deg",
        {0.0, false},
        {90.0, true},
        "dilatancy angle, at most phi_i (non-associated flow)",
        "eq. 3.40",
        ParameterRole::kMaterial,
        CalibrationBox{0.0, 25.0, false}},
       {"c_kPa",
        "kPa",
        {0.0, false},
        {kUnbounded, true},
        "adhesion (cohesion) of the interface",
        "eq. 3.38"},
       {"tension_cutoff_kPa",
        "kPa",
        {0.0, false},
        {kUnbounded, true},
        "largest tension sigma_n may carry (0: none); at most c / tan(phi_i), the apex",
        "issue 17"}}};
  return t;
}

struct McParameters {
  double G, E_oed, tan_phi, tan_psi, c, sigma_t;
};

McParameters read(const ModelInputs& in) {
  const auto& v = require_table(in, "mohr_coulomb");
  require_keys(mohr_coulomb_table(), v, in.source + " [mohr_coulomb]");
  const double E = v.at("E_kPa"), nu = v.at("nu");
  McParameters p{E / (2.0 * (1.0 + nu)),
                 0.0,
                 std::tan(v.at("phi_i_deg") * kDegree),
                 std::tan(v.at("psi_deg") * kDegree),
                 v.at("c_kPa"),
                 v.at("tension_cutoff_kPa")};
  p.E_oed = 2.0 * p.G * (1.0 - nu) / (1.0 - 2.0 * nu);  // eq. 3.37: the constrained modulus
  if (v.at("psi_deg") > v.at("phi_i_deg"))
    throw InputError(fmt::format(
        "{}: [mohr_coulomb] psi_deg = {} above phi_i_deg = {}: the flow rule would dilate more "
        "than the associated one (eq. 3.40 asks psi <= phi_i)",
        in.source, v.at("psi_deg"), v.at("phi_i_deg")));
  if (p.sigma_t * p.tan_phi > p.c + 1e-12 * (1.0 + p.c))
    throw InputError(fmt::format(
        "{}: [mohr_coulomb] tension_cutoff_kPa = {} beyond the yield surface's apex c / tan(phi_i) "
        "= {:.6g} kPa",
        in.source, p.sigma_t, p.c / p.tan_phi));
  return p;
}

// State: [T_n, tau_x, tau_y, eps_p_n, gamma_p]: T_n = -sigma_n (tension positive, every model's
// component 0), the shear stresses, the accumulated plastic opening and plastic shear strain.
enum : int {
  kTn = kTractionN,
  kTauX = kTractionX,
  kTauY = kTractionY,
  kEpsPN = 3,
  kGammaP = 4,
  kSize = 5
};

class MohrCoulomb final : public TractionModel<MohrCoulomb> {
 public:
  explicit MohrCoulomb(McParameters p) : p_(p) {}
  std::string_view name() const override { return "mc"; }
  int state_size() const override { return kSize; }
  std::vector<std::string> state_names() const override {
    return {"T_n", "tau_x", "tau_y", "eps_p_n", "gamma_p"};
  }

  StateVector initial_state(const InitialState& in) const override {
    if (!(in.sigma_n > -p_.sigma_t))
      throw InputError(fmt::format(
          "sigma_n_kPa = {} is not admissible for mc: beyond the tension cut-off {} kPa",
          in.sigma_n, -p_.sigma_t));
    return unsheared(in.sigma_n, kSize);
  }

  std::string domain_violation(const StateVector& s) const override {
    if (!s.allFinite()) return "non-finite state";
    if (-s(kTn) < -p_.sigma_t * (1.0 + 1e-12) - 1e-12)
      return fmt::format("sigma_n = {:.6g} kPa beyond the tension cut-off", -s(kTn));
    return {};
  }
  StateVector error_scale(const StateVector& s) const override {
    return traction_error_scale(s, 1e-3);
  }
  std::vector<NamedValue> diagnostics(const StateVector& s) const override {
    const double sigma_n = -s(kTn), tau = std::hypot(s(kTauX), s(kTauY));
    return {{"f_yield", tau - sigma_n * p_.tan_phi - p_.c},
            {"mobilised_friction", sigma_n > 0.0 ? tau / sigma_n : 0.0}};
  }
  friend class TractionModel<MohrCoulomb>;

 private:
  McParameters p_;

  // The closed-form return (two surfaces, each linear in its multiplier). Trial: sigma_n^tr =
  // sigma_n - E_oed d eps_n (opening unloads), tau^tr = tau + G d gamma. On the Coulomb surface
  // alone, lambda_1 moves ||tau|| back by G lambda_1 along tau's own direction and opens the
  // interface by lambda_1 tan(psi), which loads sigma_n by E_oed lambda_1 tan(psi) (the elastic
  // strain is the total less the plastic): f_1 = f_1^tr - lambda_1 (G + E_oed tan(phi_i) tan(psi))
  // = 0. On the cut-off f_2 = -sigma_n - sigma_t alone (associated: opening lambda_2), sigma_n =
  // -sigma_t. Where neither alone lands admissible, the corner: sigma_n = -sigma_t and ||tau|| = c
  // - sigma_t tan(phi_i), lambda_1 from the shear and lambda_2 from the normal equation.
  template <class S>
  void update_of(const StateVectorT<S>& s, const InterfaceStrainT<S>& d,
                 StateVectorT<S>& out) const {
    out = s;
    const S sn_tr = -s(kTn) - p_.E_oed * d.eps_n;
    const S tx_tr = s(kTauX) + p_.G * d.gamma_x, ty_tr = s(kTauY) + p_.G * d.gamma_y;
    const S t2 = tx_tr * tx_tr + ty_tr * ty_tr;
    const S t_tr = safe_sqrt(t2);
    const S f1 = t_tr - sn_tr * p_.tan_phi - p_.c, f2 = -sn_tr - p_.sigma_t;
    S sigma_n = sn_tr, tau = t_tr, lambda1 = S(0.0), lambda2 = S(0.0);
    bool done = value_of(f1) <= 0.0 && value_of(f2) <= 0.0;  // elastic
    if (!done && value_of(f1) > 0.0) {                       // the Coulomb surface alone
      lambda1 = f1 / (p_.G + p_.E_oed * p_.tan_phi * p_.tan_psi);
      tau = t_tr - p_.G * lambda1;
      sigma_n = sn_tr + p_.E_oed * lambda1 * p_.tan_psi;
      done = value_of(tau) >= 0.0 && value_of(sigma_n) >= -p_.sigma_t;
    }
    const double cap =
        p_.c - p_.sigma_t * p_.tan_phi;    // ||tau|| on the Coulomb surface at the cut-off
    if (!done && value_of(t_tr) <= cap) {  // the cut-off alone
      lambda1 = S(0.0), tau = t_tr, sigma_n = S(-p_.sigma_t), lambda2 = f2 / p_.E_oed;
      done = true;
    }
    if (!done) {  // the corner
      lambda1 = (t_tr - cap) / p_.G, tau = S(cap), sigma_n = S(-p_.sigma_t);
      lambda2 = (-p_.sigma_t - sn_tr) / p_.E_oed - lambda1 * p_.tan_psi;
    }
    // tau's direction is kept; with no trial shear every case above leaves tau = t_tr = 0, and the
    // factor 1 keeps the elastic derivative G (0 would make the tangent at rest shear-free: a
    // pile's Newton under load control then never starts)
    const S shrink = value_of(t_tr) > 0.0 ? S(tau / t_tr) : S(1.0);
    out(kTn) = -sigma_n, out(kTauX) = tx_tr * shrink, out(kTauY) = ty_tr * shrink;
    out(kEpsPN) += lambda1 * p_.tan_psi + lambda2;
    out(kGammaP) += lambda1;
  }

  // The rate form is the return's limit for a small increment: elastic inside, D^ep on the surface
  // when the trial direction loads it. Homogeneous of degree one in d, like every rate.
  template <class S>
  void rate_of(const StateVectorT<S>& s, const InterfaceStrainT<S>& d, StateVectorT<S>& ds) const {
    ds = StateVectorT<S>::Zero(kSize);
    const S tau2 = s(kTauX) * s(kTauX) + s(kTauY) * s(kTauY);
    const S sigma_n = -s(kTn), tau = safe_sqrt(tau2);
    S dsigma = -p_.E_oed * d.eps_n, dtx = p_.G * d.gamma_x, dty = p_.G * d.gamma_y;
    const bool on_surface =
        value_of(tau) > 0.0 && std::abs(value_of(tau - sigma_n * p_.tan_phi - p_.c)) <=
                                   1e-9 * (1.0 + std::abs(value_of(sigma_n)));
    if (on_surface) {
      const S nx = s(kTauX) / tau, ny = s(kTauY) / tau;
      const S df = nx * dtx + ny * dty - p_.tan_phi * dsigma;  // the trial rate's loading of f
      if (value_of(df) > 0.0) {
        const S lambda = df / (p_.G + p_.E_oed * p_.tan_phi * p_.tan_psi);
        dtx -= p_.G * lambda * nx, dty -= p_.G * lambda * ny,
            dsigma += p_.E_oed * lambda * p_.tan_psi;
        ds(kEpsPN) = lambda * p_.tan_psi, ds(kGammaP) = lambda;
      }
    }
    ds(kTn) = -dsigma, ds(kTauX) = dtx, ds(kTauY) = dty;
  }
};

}  // namespace

ModelSpec mc_spec() {
  ModelDeclaration d;
  d.listing_order =
      20;  // after the hypoplastic sand (0-5) and clay (10-13) models, before the -igs forms
  d.layout.components = traction_components();
  d.layout.components.push_back({"eps_p_n", "-", ComponentKind::kHardening});
  d.layout.components.push_back({"gamma_p", "-", ComponentKind::kHardening});
  d.layout.void_ratio = -1;
  d.initial = {{"sigma_n_kPa", "kPa", "initial normal stress (compression positive)"}};
  d.diagnostics = {{"f_yield", "kPa",
                    "yield function ||tau|| - sigma_n tan(phi_i) - c (eq. 3.38): 0 on the surface",
                    DiagnosticRole::kYieldFunction},
                   {"mobilised_friction", "-", "||tau|| / sigma_n"}};
  d.update = StressPointUpdate::kIncrement;
  d.example_parameters = "table_4_3_mohr_coulomb.toml";
  d.plan_rank = 1;
  d.example_start = {{"sigma_n_kPa", 100.0}};
  return {"mc",
          "Mohr-Coulomb interface (Van Langen 1991): linear elastic, perfectly plastic, "
          "non-associated (psi), tension cut-off",
          "seed 3.35-3.45, Table 3.1 (3.38-3.44 re-derived, compression positive)",
          false,
          {&mohr_coulomb_table()},
          [](const ModelInputs& in) { return std::make_unique<MohrCoulomb>(read(in)); },
          d};
}

}  // namespace iwb::models
