// mortara: Mortara's (2003) elasto-plastic interface model (Ghionna & Mortara 2002; seed 3.3.3,
// Table 3.3; EP1 of chapter 4), monotonic part (the outer surface; the inner surface of cyclic
// loading is not built). Displacement based, in Pa and m as the seed's parameters: the element's
// strains are displacements over d_s (ModelInputs::shear_zone_mm). The reconstruction of the
// garbled 3.56-3.61, 3.66 and of the unprinted w_p, d_max: README.md,
// docs/derivations/mortara_2003.md. Compression positive inside; v = -u_n is the closure.
//
//   f = ||tau|| - alpha(h) sigma_n^beta                                  (3.58)
//   alpha(h) = alpha_c [(omega h + 1)^psi - 2] exp(-L h^M) + alpha_c      (3.61; alpha(0) = 0,
//   alpha(1) = alpha_p) L = ln{alpha_c [(omega + 1)^psi - 2] / (alpha_p - alpha_c)} (3.66,
//   corrected) M = psi omega (omega + 1)^(psi - 1) / (L [(omega + 1)^psi - 2])       (3.67:
//   alpha'(1) = 0) dh = d u^p / w_p,  w_p = xi sigma_n + zeta,  d_max = nu_d + mu sigma_n (assumed
//   linear) flow: eta = b + a d (d = dv^p / du^p, negative dilates), b = rho eta_c while h < 1,
//   eta_c after,
//         a = (eta_p - b) / d_max,  eta_{p,c} = alpha_{p,c} sigma_n^(beta - 1)      (3.57)
//   K_s = C_k K_n;  H = alpha'(h) sigma_n^beta / w_p;  n = [1, -N], N = beta alpha sigma_n^(beta -
//   1) Lambda = (K_s du_t - N K_n dv) / (H + K_s - N K_n d)   (loading: Lambda > 0)
#include <fmt/core.h>

#include <cmath>
#include <memory>

#include "common/errors.hpp"
#include "models/registry.hpp"
#include "models/traction/traction_model.hpp"

namespace iwb::models {

namespace {

const ParameterTable& mortara_table() {
  static const ParameterTable t{
      "mortara",
      {{"K_n_Pa_per_m",
        "Pa/m",
        {0.0, true},
        {kUnbounded, true},
        "elastic normal stiffness",
        "eq. 3.59, Table 3.3"},
       {"C_k",
        "-",
        {0.0, true},
        {kUnbounded, true},
        "shear over normal stiffness, K_s = C_k K_n",
        "eq. 3.60"},
       {"alpha_p",
        "Pa^(1-beta)",
        {0.0, true},
        {kUnbounded, true},
        "peak envelope tau_p = alpha_p sigma_n^beta",
        "eq. 3.62",
        ParameterRole::kMaterial,
        CalibrationBox{0.3, 10.0, true}},
       {"alpha_c",
        "Pa^(1-beta)",
        {0.0, true},
        {kUnbounded, true},
        "critical envelope tau_c = alpha_c sigma_n^beta",
        "eq. 3.63",
        ParameterRole::kMaterial,
        CalibrationBox{0.3, 10.0, true}},
       {"beta",
        "-",
        {0.0, true},
        {2.0, false},
        "curvature of the envelopes (below 1: concave; the sensitivity samples reach above)",
        "eq. 3.58"},
       {"omega", "-", {0.0, true}, {kUnbounded, true}, "hardening law shape", "eq. 3.61"},
       {"psi",
        "-",
        {0.0, true},
        {kUnbounded, true},
        "hardening law exponent ((omega + 1)^psi > 2)",
        "eq. 3.61"},
       {"xi_m_per_Pa",
        "m/Pa",
        {0.0, false},
        {kUnbounded, true},
        "w_p = xi sigma_n + zeta: slope",
        "Table 3.3 (linear: README.md)"},
       {"zeta_m",
        "m",
        {0.0, true},
        {kUnbounded, true},
        "w_p = xi sigma_n + zeta: plastic slip to the peak at sigma_n 0",
        "Table 3.3",
        ParameterRole::kMaterial,
        CalibrationBox{1e-5, 1e-2, true}},
       {"mu_per_Pa",
        "1/Pa",
        {-kUnbounded, true},
        {kUnbounded, true},
        "d_max = nu_d + mu sigma_n: slope",
        "Table 3.3 (linear)"},
       {"nu_d",
        "-",
        {-kUnbounded, true},
        {kUnbounded, true},
        "d_max = nu_d + mu sigma_n: dilatancy at the peak at sigma_n 0 (< 0 dilates)",
        "Table 3.3",
        ParameterRole::kMaterial,
        CalibrationBox{-2.0, 0.5, false}},
       {"rho",
        "-",
        {0.0, true},
        {1.0, false},
        "stress ratio of zero dilatancy while hardening, over eta_c",
        "eq. 3.57, Table 3.3"}}};
  return t;
}

struct MortaraParameters {
  double K_n, C_k, alpha_p, alpha_c, beta, omega, psi, xi, zeta, mu, nu_d, rho;
  double L, M;  // eqs. 3.66, 3.67
};

MortaraParameters read(const ModelInputs& in) {
  const auto& v = require_table(in, "mortara");
  const std::string source = in.source + " [mortara]";
  validate(mortara_table(), v, source);
  MortaraParameters p{v.at("K_n_Pa_per_m"),
                      v.at("C_k"),
                      v.at("alpha_p"),
                      v.at("alpha_c"),
                      v.at("beta"),
                      v.at("omega"),
                      v.at("psi"),
                      v.at("xi_m_per_Pa"),
                      v.at("zeta_m"),
                      v.at("mu_per_Pa"),
                      v.at("nu_d"),
                      v.at("rho"),
                      0.0,
                      0.0};
  const double g1 = std::pow(p.omega + 1.0, p.psi) - 2.0;
  if (!(g1 > 0.0) || !(p.alpha_p > p.alpha_c))
    throw InputError(fmt::format(
        "{}: the hardening law needs (omega + 1)^psi > 2 and alpha_p > alpha_c (eq. 3.66: "
        "(omega + 1)^psi = {:.4g}, alpha_p = {:g}, alpha_c = {:g})",
        source, g1 + 2.0, p.alpha_p, p.alpha_c));
  p.L = std::log(p.alpha_c * g1 / (p.alpha_p - p.alpha_c));
  if (!(p.L > 0.0))
    throw InputError(fmt::format("{}: L = {:.4g} (eq. 3.66) must be > 0", source, p.L));
  p.M = p.psi * p.omega * std::pow(p.omega + 1.0, p.psi - 1.0) / (p.L * g1);
  return p;
}

// State: [T_n, tau_x, tau_y, h]: the traction (T_n = -sigma_n, kPa) and the normalised plastic
// slip.
enum : int { kH = 3, kSize = 4 };
constexpr double kPa = 1000.0;  // Pa per kPa

class Mortara final : public TractionModel<Mortara> {
 public:
  Mortara(MortaraParameters p, double d_s_mm) : p_(p), d_s_m_(d_s_mm / 1000.0) {}
  std::string_view name() const override { return "mortara"; }
  int state_size() const override { return kSize; }
  std::vector<std::string> state_names() const override { return {"T_n", "tau_x", "tau_y", "h"}; }
  StateVector initial_state(const InitialState& in) const override {
    return unsheared_in_compression(in.sigma_n, kSize, "compression");
  }
  std::string domain_violation(const StateVector& s) const override {
    return compression_violation(s, "contact lost");
  }
  StateVector error_scale(const StateVector& s) const override {
    return traction_error_scale(s, 1e-3);
  }
  std::vector<NamedValue> diagnostics(const StateVector& s) const override {
    const double sigma = -s(kTractionN) * kPa, tau = std::hypot(s(kTractionX), s(kTractionY)) * kPa;
    return {{"alpha", alpha(s(kH))},
            {"eta_p", p_.alpha_p * std::pow(sigma, p_.beta - 1.0)},
            {"eta_c", p_.alpha_c * std::pow(sigma, p_.beta - 1.0)},
            {"f_yield", (tau - alpha(s(kH)) * std::pow(sigma, p_.beta)) / kPa}};
  }
  friend class TractionModel<Mortara>;

 private:
  MortaraParameters p_;
  double d_s_m_;

  template <class S>
  S alpha(const S& h) const {
    using std::exp;
    using std::pow;
    const S hh = value_of(h) > 0.0 ? h : S(0.0);
    return p_.alpha_c * (pow(p_.omega * hh + 1.0, p_.psi) - 2.0) * exp(-p_.L * pow(hh, p_.M)) +
           p_.alpha_c;
  }
  template <class S>
  S alpha_slope(const S& h) const {  // alpha'(h)
    using std::exp;
    using std::pow;
    const S hh = value_of(h) > 0.0 ? h : S(0.0);
    const S g = pow(p_.omega * hh + 1.0, p_.psi) - 2.0;
    const S dg = p_.psi * p_.omega * pow(p_.omega * hh + 1.0, p_.psi - 1.0);
    const S hm1 = value_of(hh) > 0.0 ? S(pow(hh, p_.M - 1.0)) : S(0.0);
    return p_.alpha_c * exp(-p_.L * pow(hh, p_.M)) * (dg - g * p_.L * p_.M * hm1);
  }

  template <class S>
  void rate_of(const StateVectorT<S>& s, const InterfaceStrainT<S>& d, StateVectorT<S>& ds) const {
    using std::pow;
    ds = StateVectorT<S>::Zero(kSize);
    const S sigma = -s(kTractionN) * kPa, h = s(kH);
    const double K_n = p_.K_n, K_s = p_.C_k * p_.K_n;
    // displacement rates (m): the tangential one along tau (or along the slip from an unsheared
    // state)
    const S du_x = d.gamma_x * d_s_m_, du_y = d.gamma_y * d_s_m_,
            dv = -d.eps_n * d_s_m_;  // v: closure
    const S tau = safe_sqrt(S(s(kTractionX) * s(kTractionX) + s(kTractionY) * s(kTractionY)));
    const S slip = safe_sqrt(S(du_x * du_x + du_y * du_y));
    S nx = S(1.0), ny = S(0.0);
    if (value_of(tau) > 0.0)
      nx = s(kTractionX) / tau, ny = s(kTractionY) / tau;
    else if (value_of(slip) > 0.0)
      nx = du_x / slip, ny = du_y / slip;
    const S du_t = nx * du_x + ny * du_y;
    const S a_h = alpha(h);
    const S eta_p = p_.alpha_p * pow(sigma, p_.beta - 1.0),
            eta_c = p_.alpha_c * pow(sigma, p_.beta - 1.0);
    const S eta = tau * kPa / sigma;
    const S w_p = p_.xi * sigma + p_.zeta, d_max = p_.nu_d + p_.mu * sigma;
    const S b = value_of(h) < 1.0 ? S(p_.rho * eta_c) : eta_c;  // hardening, then softening branch
    const S dil = (eta - b) * d_max / (eta_p - b);  // d = (eta - b) / a, a = (eta_p - b) / d_max
    const S N = p_.beta * a_h * pow(sigma, p_.beta - 1.0);
    const S H = alpha_slope(h) * pow(sigma, p_.beta) / w_p;
    // on the surface (to the integrator's drift) and loading it
    const bool on_surface =
        value_of(tau) * kPa >= value_of(a_h * pow(sigma, p_.beta)) * (1.0 - kOnSurface);
    S lambda = (K_s * du_t - N * K_n * dv) / (H + K_s - N * K_n * dil);
    if (!on_surface || !(value_of(lambda) > 0.0)) lambda = S(0.0);
    ds(kTractionX) = (K_s * (du_x - lambda * nx)) / kPa;
    ds(kTractionY) = (K_s * (du_y - lambda * ny)) / kPa;
    ds(kTractionN) = -(K_n * (dv - lambda * dil)) / kPa;
    ds(kH) = lambda / w_p;
  }

  // The stress ratio this close below the surface counts as on it (the integrator's drift is 1e-6).
  static constexpr double kOnSurface = 1e-5;
};

}  // namespace

ModelSpec mortara_spec() {
  ModelDeclaration d;
  d.listing_order = 23;  // after mc, hyperbolic, lashkari
  d.layout.components = traction_components();
  d.layout.components.push_back({"h", "-", ComponentKind::kHardening});
  d.layout.void_ratio = -1;
  d.initial = {{"sigma_n_kPa", "kPa", "initial normal stress (compression positive)"}};
  d.diagnostics = {{"alpha", "Pa^(1-beta)", "the yield surface's alpha(h) (eq. 3.61)"},
                   {"eta_p", "-", "peak stress ratio alpha_p sigma_n^(beta - 1)"},
                   {"eta_c", "-", "critical stress ratio alpha_c sigma_n^(beta - 1)"},
                   {"f_yield", "kPa", "||tau|| - alpha sigma_n^beta: 0 while loading",
                    DiagnosticRole::kYieldFunction}};
  d.example_parameters = "table_4_5_mortara.toml";
  d.displacement_based = true;
  d.monotonic_only = true;  // the inner (kinematic) surface is not built: README.md
  d.plan_rank = 7;
  d.example_start = {{"sigma_n_kPa", 100.0}};
  return {
      "mortara",
      "Mortara (2003) two-surface elasto-plastic interface model, monotonic (outer) surface: peak "
      "and critical envelopes, "
      "double flow rule",
      "seed 3.54-3.67, Table 3.3 (3.57, 3.61, 3.66 read, w_p and d_max linear: README.md)",
      false,
      {&mortara_table()},
      [](const ModelInputs& in) { return std::make_unique<Mortara>(read(in), in.shear_zone_mm); },
      d};
}

}  // namespace iwb::models
