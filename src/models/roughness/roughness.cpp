#include "models/roughness/roughness.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "common/errors.hpp"

namespace iwb::models {

RoughnessEffect effect_of(const Roughness& r) {
  const double k = r.kappa_r;
  if (r.scheme == RoughnessScheme::kGutjahr) return {k, k * k, 1.0};  // eqs. 5.37-5.39
  return {
      k, 1.0,
      r.f_c == ArnoldHerleFactor::kReciprocal ? 1.0 / k : k};  // eqs. 5.37, 5.40, 5.41; ERRATA 9
}

ArnoldHerleFactor parse_arnold_herle_factor(const std::string& text, const std::string& where) {
  if (text == "1/kappa_r") return ArnoldHerleFactor::kReciprocal;
  if (text == "kappa_r") return ArnoldHerleFactor::kProportional;
  throw InputError(fmt::format(
      "{}: f_c = '{}': Arnold & Herle's rate factor is \"1/kappa_r\" (eq. 5.40 as printed) or "
      "\"kappa_r\" (the reading of 5.7.3, ERRATA 9)",
      where, text));
}

const char* to_string(ArnoldHerleFactor f) {
  return f == ArnoldHerleFactor::kReciprocal ? "1/kappa_r" : "kappa_r";
}

namespace {
KappaR clamped(double raw, const std::string& origin) {
  KappaR out{std::min(1.0, raw), {}};
  if (out.value < kKappaRFloor) {
    out.warnings.push_back(fmt::format("kappa_r = {:.4g} from {} is below the floor {}; clamped",
                                       raw, origin, kKappaRFloor));
    out.value = kKappaRFloor;
  }
  return out;
}
}  // namespace

KappaR kappa_r_from_normalized_roughness(double R_n, double log_base) {
  if (!(R_n > 0.0) || !std::isfinite(R_n))
    throw InputError(fmt::format("R_n = {:g}: normalized roughness must be > 0", R_n));
  if (!(log_base > 1.0))
    throw InputError(fmt::format("log base {:g} for eq. 5.35 must be > 1", log_base));
  const double raw = 0.25 * std::log(R_n) / std::log(log_base) + 1.05;
  return clamped(raw, fmt::format("R_n = {:g} (eq. 5.35, log base {:g})", R_n, log_base));
}

namespace {
void require_interface_angle(double delta) {
  if (!(delta > 0.0) || !(delta < M_PI / 2))
    throw InputError(
        fmt::format("interface friction angle {:g} deg must be in (0, 90)", delta * 180.0 / M_PI));
}
}  // namespace

KappaR kappa_r_from_friction_angles(double delta, double phi_c) {
  require_interface_angle(delta);
  return clamped(std::tan(delta) / std::tan(phi_c),
                 fmt::format("delta = {:g} deg (eq. 5.36)", delta * 180.0 / M_PI));
}

KappaR kappa_r_from_angle_ratio(double delta, double phi_c) {
  require_interface_angle(delta);
  return clamped(delta / phi_c, fmt::format("delta = {:g} deg (eq. 6.21)", delta * 180.0 / M_PI));
}

const char* to_string(RoughnessScheme s) {
  switch (s) {
    case RoughnessScheme::kGutjahr:
      return "gutjahr";
    case RoughnessScheme::kArnoldHerle:
      return "arnold-herle";
    case RoughnessScheme::kStutzMasin:
      return "stutz-masin";
  }
  return "?";
}

}  // namespace iwb::models
