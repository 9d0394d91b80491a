#pragma once
// Wall roughness for the interface models (seed 5.5.2, CONVENTIONS.md "Roughness").
//
// Both schemes reduce the friction angle that enters the coefficient a: sin(phi_r) = kappa_r
// sin(phi_c) (eq. 5.37 as printed). Gutjahr's scheme also scales the pyknotropy exponent alpha by
// kappa_r^2 (eqs. 5.38, 5.39); Arnold & Herle's multiplies the whole rate by f_c = 1/kappa_r
// (eqs. 5.40, 5.41). That difference is data (RoughnessEffect), not code paths.
#include <optional>
#include <string>
#include <vector>

namespace iwb::models {

// kStutzMasin: the clay scheme of seed 6.2.4 (eqs. 6.23-6.28), for hce.
enum class RoughnessScheme { kGutjahr, kArnoldHerle, kStutzMasin };

// Arnold & Herle's factor on the whole rate (ERRATA 9): eq. 5.40 prints f_c = 1/kappa_r, which
// makes a smoother wall stiffer; the text of 5.7.3-5.7.4 calls it softer, which fits f_c = kappa_r.
// Both are offered until the DEM decides.
enum class ArnoldHerleFactor { kReciprocal, kProportional };

struct Roughness {
  RoughnessScheme scheme = RoughnessScheme::kGutjahr;
  double kappa_r = 1.0;  // (0, 1]; 1 = fully rough
  ArnoldHerleFactor f_c =
      ArnoldHerleFactor::kReciprocal;  // read only by Arnold & Herle's sand scheme
  // The wall's normalized roughness where the caller knows the wall (a DEM run, an element test's
  // [roughness] R_n), for a model that reads it beside kappa_r (issue 56: a form in which
  // roughness adds dilatancy); empty where no wall is described (the stability map, a pile).
  std::optional<double> R_n = {};
  // The wall's mean |dz/dx| along the shear direction (`iwb dem roughness`), for a model whose
  // asperities ride (issue 56); empty where no wall is described.
  std::optional<double> mean_abs_slope = {};
};

// "1/kappa_r" (as printed, the default) or "kappa_r"; InputError naming `where` otherwise.
ArnoldHerleFactor parse_arnold_herle_factor(const std::string& text, const std::string& where);
const char* to_string(ArnoldHerleFactor f);

// How kappa_r enters the hypoplastic rate.
struct RoughnessEffect {
  double sin_phi_factor;  // sin(phi_r) = factor * sin(phi_c), used for a_r
  double alpha_factor;    // alpha_r = factor * alpha in f_d and f_s
  double rate_factor;     // f_c multiplying the whole rate
};
RoughnessEffect effect_of(const Roughness& r);

// Smallest kappa_r the formulas accept; below it the base-10 reading of eq. 5.35 would go
// negative (R_n < ~1e-4). Values are clamped to it with a warning.
inline constexpr double kKappaRFloor = 0.05;

struct KappaR {
  double value;
  std::vector<std::string> warnings;
};

// Gutjahr's eq. 5.35, kappa_r = min(1, 0.25 log_b(R_n) + 1.05). The seed does not print the
// base; 10 is our reading (CONVENTIONS.md), e is offered so the DEM fits can decide.
KappaR kappa_r_from_normalized_roughness(double R_n, double log_base = 10.0);
// Eq. 5.36 (granular): kappa_r = tan(delta) / tan(phi_c), capped at 1; angles in radians.
KappaR kappa_r_from_friction_angles(double delta, double phi_c);
// Eq. 6.21 (clay): kappa_r = delta / phi_c, capped at 1; angles in radians.
KappaR kappa_r_from_angle_ratio(double delta, double phi_c);

const char* to_string(RoughnessScheme s);

}  // namespace iwb::models
