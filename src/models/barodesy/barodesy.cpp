// barodesy-clay: Barodesy for clay (seed 8.2) on the reduced interface vectors [sigma_n, sigma_p,
// tau_x, tau_y] (the kinematics of hvwe), and barodesy-clay3d on 3x3 tensors in simple shear. The
// rate is barodesy_law.hpp's, in the model class of the hypoplastic family (Kolymbas 2012b calls
// barodesy "a new hypoplastic approach"): packed stress and void ratio, no intergranular strain.
#include <fmt/core.h>

#include <cmath>

#include "models/barodesy/barodesy_law.hpp"
#include "models/clay/declaration.hpp"
#include "models/hypoplastic/family.hpp"

namespace iwb::models {

namespace {

// After the clay hypoplastic models (10-13), before modified Cam clay (30).
constexpr int kListingOrder = 25;

// p_e / p up to which isotropic unloading keeps a positive stiffness not above lambda*: the
// unloading entry of eq. 8.12 (the authors' UMAT uses 1000, README.md).
constexpr double kUnloadingOcrLimit = 1000.0;

const ParameterTable& barodesy_table() {
  static const ParameterTable t{
      "barodesy_clay",
      {{"lambda_star",
        "-",
        {0.0, true},
        {2.0, false},
        "slope lambda* of the isotropic normal compression line, ln(1+e) "
        "against ln p",
        "eqs. 8.7-8.9, Table 8.1"},
       {"kappa_star",
        "-",
        {0.0, true},
        {2.0, false},
        "slope kappa* of isotropic unloading, ln(1+e) against ln p",
        "eq. 8.9, 8.12"},
       {"phi_c_deg",
        "deg",
        {0.0, true},
        {90.0, true},
        "critical state friction angle phi_c (triaxial compression)",
        "eqs. 8.10, 8.11",
        ParameterRole::kCriticalFrictionAngle},
       {"N",
        "-",
        {0.0, true},
        {10.0, false},
        "ln(1+e) on the isotropic normal compression line at p = 1 kPa",
        "eq. 8.7"},
       {"G0_over_p",
        "-",
        {0.0, true},
        {1e5, false},
        "shear modulus over mean stress at an isotropic state (Table 8.1's G0/p_ini), for c3",
        "eq. 8.12"}}};
  return t;
}

BarodesyParameters read(const ModelInputs& in) {
  const std::string source = in.source + " [barodesy_clay]";
  const auto& v = require_table(in, "barodesy_clay");
  validate(barodesy_table(), v, source);
  require_below(v, "kappa_star", "lambda_star", source,
                "unloading is stiffer than normal compression");
  return {v.at("lambda_star"), v.at("kappa_star"), v.at("phi_c_deg") * M_PI / 180.0, v.at("N"),
          v.at("G0_over_p")};
}

double hvorslev_pressure(double e, const BarodesyParameters& p) {
  return std::exp((p.N - std::log(1.0 + e)) / p.lambda_star);
}

template <class Kinematics>
std::unique_ptr<Model> build(const std::string& name, const ModelInputs& in) {
  return make_member<BarodesyLaw>(name, Kinematics{},
                                  make_barodesy_constants(read(in), in.roughness), in,
                                  WithIntergranularStrain::kNo);
}

ModelDeclaration barodesy_declaration(const std::vector<std::string>& stress_components,
                                      bool interface_model, int listing_order) {
  auto d = clay_declaration(stress_components, interface_model, listing_order,
                            RoughnessScheme::kArnoldHerle, {}, "barodesy_clay");
  if (interface_model)
    d.roughness.schemes = {RoughnessScheme::kArnoldHerle};  // phi_c kappa_r (eq. 6.22)
  d.initial[2].doc =
      "overconsolidation ratio at the start: Hvorslev's p_e over its value on the state boundary "
      "surface "
      "at the initial stress (1: the isotropic NCL at K0 = 1, the oedometric asymptote at 1 - sin "
      "phi_c), "
      "which sets e0";
  d.diagnostics.push_back(
      {"p_e_over_p", "-", "p_e / p: 1 on the isotropic NCL, 2 at the critical state"});
  d.example_parameters = "table_8_1_london_clay.toml";
  d.example_start = {{"sigma_n_kPa", 100.0}, {"e0", 1.3}};
  return d;
}

}  // namespace

BarodesyConstants make_barodesy_constants(const BarodesyParameters& p, const Roughness& r) {
  const double s = std::sin(p.phi_c * r.kappa_r), sqrt3 = std::sqrt(3.0);
  BarodesyConstants c{p, (1.0 - s) / (1.0 + s), 0, 0, 0, 0, 0, 0, 0};
  const double K0 = 1.0 - s, Kc = c.K_c;
  // 8.11 with the denominator 2 (K_c - K_0) (printed: K_c - 1): K(m = 3/2, oedometric) = K0
  c.c2 = (3.0 * std::sqrt(Kc * (1.0 - Kc) * K0 * (1.0 - K0)) + 3.0 * Kc * (1.0 - K0)) /
         (2.0 * (Kc - K0));
  c.c1 = Kc / (c.c2 * c.c2 * (1.0 - Kc));  // 8.10: K(m = 0, critical) = K_c
  c.c5 = 1.0 / Kc;                         // 8.14
  // 8.12: the shear entry gives the shear modulus G0 at an isotropic state under isochoric
  // triaxial stretching; the unloading entry keeps isotropic unloading's stiffness positive up to
  // p_e / p = kUnloadingOcrLimit. Both negative; the max is the smaller |c3|.
  c.c3_shear = 2.0 * std::sqrt(2.0) * p.G0_over_p * std::sqrt(1.0 + 2.0 * Kc * Kc) / (Kc - 1.0);
  c.c3_unloading = (sqrt3 / p.kappa_star - sqrt3 / p.lambda_star) /
                   (std::pow(2.0, c.c5 * p.lambda_star) +
                    std::pow(2.0 / kUnloadingOcrLimit, c.c5 * p.lambda_star) - 2.0);
  c.c3 = std::max(c.c3_shear, c.c3_unloading);
  // 8.15: f(delta = sqrt3) = 0, beta(sqrt3) with Lambda(sqrt3) = kappa*
  const double beta_unloading =
      -1.0 / (c.c3 * p.kappa_star) + (std::pow(2.0, c.c5 * p.lambda_star) - 1.0) / sqrt3;
  c.c6 = 1.0 / (2.0 * sqrt3 * beta_unloading);
  return c;
}

std::string BarodesyLaw::domain_violation(const StressInvariants& s, double e, const Constants&) {
  if (!(e > 0.0)) return fmt::format("void ratio e = {:.6g} not positive", e);
  (void)s;  // compression is checked by the model class (tr T < 0)
  return {};
}

double BarodesyLaw::void_ratio_at_ratio(double K, double p, double ocr, const Constants& c) {
  if (!(K > 0.0 && K <= 1.0 + 1e-12))
    throw InputError(
        fmt::format("barodesy: no state boundary surface at the principal stress ratio {:.6g}", K));
  if (K >= 1.0 - 1e-12)  // isotropic: the NCL, p_e = p
    return std::exp(c.p.N - c.p.lambda_star * std::log(ocr * p)) - 1.0;
  const double m = c.c2 + std::sqrt(K / ((1.0 - K) * c.c1));  // eq. 8.4 inverted, m >= c2
  const double delta = -m * std::sqrt(6.0 / (9.0 + 2.0 * m * m));
  const double Lambda = -(c.p.lambda_star - c.p.kappa_star) / (2.0 * std::sqrt(3.0)) * delta +
                        (c.p.lambda_star + c.p.kappa_star) / 2.0;
  const double beta =
      -1.0 / (c.c3 * Lambda) + (std::pow(2.0, c.c5 * c.p.lambda_star) - 1.0) / std::sqrt(3.0);
  const double density =
      1.0 - delta * (beta + 1.0 / (c.p.lambda_star * c.c3));  // ((1+e)/(1+e_c))^c5
  if (!(density > 0.0))
    throw InputError(
        fmt::format("barodesy: no state boundary surface at the principal stress ratio {:.6g}", K));
  // (1+e)/(1+e_c) = (2p / p_e)^lambda*: p_e on the surface, then OCR times it
  const double p_e = 2.0 * p / std::pow(density, 1.0 / (c.c5 * c.p.lambda_star)) * ocr;
  return std::exp(c.p.N - c.p.lambda_star * std::log(p_e)) - 1.0;
}

std::vector<NamedValue> BarodesyLaw::diagnostics(const StressInvariants& s, double e,
                                                 const Constants& c) {
  const double p_e = hvorslev_pressure(e, c.p);
  return {
      {"mean_stress_kPa", s.mean_stress}, {"p_e_kPa", p_e}, {"p_e_over_p", p_e / s.mean_stress}};
}

ModelSpec barodesy_clay_spec() {
  using Kinematics = ReducedInterfaceKinematics<algebra::ReducedOps>;
  return {"barodesy-clay",
          "Barodesy for clay (Medicus et al. 2012, improved 2017), interface model on [sigma_n, "
          "sigma_p, tau_x, tau_y]",
          "seed 8.1-8.15 (8.8, 8.9, 8.11, 8.12 corrected: README.md)",
          true,
          {&barodesy_table()},
          [](const ModelInputs& in) { return build<Kinematics>("barodesy-clay", in); },
          barodesy_declaration(Kinematics::component_names(), true, kListingOrder)};
}

ModelSpec barodesy_clay3d_spec() {
  return {
      "barodesy-clay3d",
      "Barodesy for clay (Medicus et al. 2012, improved 2017), full 3x3 tensors in simple shear",
      "seed 8.1-8.15 (8.8, 8.9, 8.11, 8.12 corrected: README.md)",
      false,
      {&barodesy_table()},
      [](const ModelInputs& in) { return build<SimpleShearKinematics>("barodesy-clay3d", in); },
      barodesy_declaration(SimpleShearKinematics::component_names(), false, kListingOrder + 1)};
}

}  // namespace iwb::models
