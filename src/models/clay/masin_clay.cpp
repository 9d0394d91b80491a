#include "models/clay/masin_clay.hpp"

#include <fmt/core.h>

#include "common/errors.hpp"
#include "models/clay/critical_state_keys.hpp"

namespace iwb::models {

// As the other clay tables: bounds far beyond published clays refuse only units mistakes.
constexpr double kMaxR = 10.0;  // Masin (2005): r ~ 0.1-0.7

const ParameterTable& MasinClayParameters::table() {
  static const ParameterTable t{
      "clay_hypoplasticity",
      {
          clay_keys::phi_c_deg("critical state friction angle phi_c", "eqs. 6.35, 6.38"),
          clay_keys::lambda_star("eq. 6.43"),
          clay_keys::kappa_star("eq. 6.36"),
          clay_keys::N("ln(1+e) on the isotropic normal compression line at p = 1 kPa", "eq. 6.43"),
          {"r",
           "-",
           {0.0, true},
           {kMaxR, false},
           "ratio of bulk to shear stiffness at the isotropic state",
           "eq. 6.34",
           ParameterRole::kMaterial,
           CalibrationBox{0.05, 1.0, false}},
      }};
  return t;
}

MasinClayParameters MasinClayParameters::from(const ParameterValues& v, const std::string& source) {
  validate(table(), v, source);
  clay_keys::require_slopes_ordered(v, source);
  return {v.at("phi_c_deg") * M_PI / 180.0, v.at("lambda_star"), v.at("kappa_star"), v.at("N"),
          v.at("r")};
}

MasinClayConstants make_masin_clay_constants(const MasinClayParameters& p, const Roughness& r) {
  MasinClayConstants c{p, 0.0, 0.0, 0.0};
  c.p.phi_c = p.phi_c * r.kappa_r;  // 6.22, 6.26: the critical state
  if (r.scheme == RoughnessScheme::kStutzMasin)
    c.p.r = p.r * r.kappa_r;  // 6.24: the shear stiffness
  const double s = std::sin(c.p.phi_c);
  c.a = std::sqrt(3.0) * (3.0 - s) / (2.0 * std::sqrt(2.0) * s);  // 6.35, ERRATA 14
  c.k = std::sqrt(3.0) * c.a / (3.0 + c.a * c.a);                 // 6.38, ERRATA 14
  c.sin2_phi = s * s;
  return c;
}

std::string MasinClayLaw::domain_violation(const StressInvariants& s, double, const Constants&) {
  if (!(s.F_m < 1.0))
    return fmt::format(
        "stress outside Matsuoka-Nakai's cone (F_m = {:.6g}): tension in a direction", s.F_m);
  return {};
}

namespace {

// How far outside the state boundary surface a start may lie and still be taken for "on it": 1 %
// of OCR, as hcc and hce (their kAsbsTolerance). An e0 written to three decimals off the surface
// is off by at most 5e-4, OCR 1 - 5e-4 / (lambda* (1 + e)) = 0.996 for Table 6.5's Soil 1; the
// table's own start (e0 0.5 at 300 kPa) lies at OCR 0.72, f_d / f_d^SBS = 1.37.
constexpr double kStateBoundaryTolerance = 0.01;

}  // namespace

// Outside is looser than the surface: OCR = p_e / p_e^SBS < 1, with ln p_e = (N - ln(1+e)) /
// lambda* (6.43) at e and at e_SBS, so OCR = exp[(ln(1+e_SBS) - ln(1+e)) / lambda*]. By f_d =
// (2p / p_e)^alpha (6.42), f_d / f_d^SBS = OCR^-alpha: for alpha > 0 outside is f_d / f_d^SBS > 1,
// as Masin (2005) and the seed (6.49, 6.51's f_u) read it. A set with alpha < 0 (kappa* / lambda*
// above about 0.42: Table 6.5's CNL column) reverses the ratio, not the surface, so the test is
// on OCR.
std::string MasinClayLaw::outside_state_boundary(double e, double e_sbs, double lambda,
                                                 double alpha) {
  if (alpha == 0.0 || !std::isfinite(e_sbs) || !(e_sbs > -1.0))
    return {};  // f_d does not depend on e: no surface in e to lie outside of
  const double ocr = std::exp((std::log(1.0 + e_sbs) - std::log(1.0 + e)) / lambda);
  if (ocr >= 1.0 - kStateBoundaryTolerance) return {};
  const double ratio = std::pow(ocr, -alpha);
  const std::string measure =
      alpha > 0.0
          ? fmt::format("f_d / f_d^SBS = {:.4g} > 1 (seed eqs. 6.42, 6.49; OCR = {:.4g})", ratio,
                        ocr)
          : fmt::format(
                "OCR = p_e / p_e^SBS = {:.4g} < 1 (seed eqs. 6.43, 6.49; f_d / f_d^SBS = {:.4g} at "
                "alpha = {:.3g} < 0, where the looser state has the smaller f_d)",
                ocr, ratio, alpha);
  return fmt::format(
      "outside the state boundary surface: {}; the largest e0 at this stress is {:.4f} (on the "
      "surface; or give OCR >= 1)",
      measure, e_sbs);
}

std::vector<NamedValue> MasinClayLaw::diagnostics(const StressInvariants& s, double e,
                                                  const Constants& c) {
  return {{"mean_stress_kPa", s.mean_stress},
          {"p_e_kPa", std::exp((c.p.N - std::log(1.0 + e)) / c.p.lambda_star)},
          {"F_m", s.F_m}};
}

}  // namespace iwb::models
