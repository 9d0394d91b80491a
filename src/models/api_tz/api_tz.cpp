// api-tz: the t-z curve of pile practice (API RP 2GEO 2011 / ISO 19901-4, after API RP 2A) as an
// interface law: tau = t_max f(u) with t_max = sigma_n tan(delta) at the current normal stress. The
// backbone f (t / t_max against u / z_peak) is data: API sand (linear to 1 at z_peak, 0.1 in) or
// API clay (the published z/D points over z_peak = 0.01 D), then a drop to t_res / t_max at
// 2 z_peak. Written as elasto-plasticity in the mobilisation m = tau / t_max, so that unloading is
// elastic at the backbone's initial slope (the workbench's rule: API gives none) and the monotonic
// curve is the backbone exactly. No dilatancy: sigma_n moves only by the normal control (k_n).
// README.md gives the equations, the sources and the facts the tests assert.
#include <fmt/core.h>

#include <array>
#include <cmath>
#include <memory>
#include <utility>
#include <vector>

#include "common/errors.hpp"
#include "models/registry.hpp"
#include "models/traction/traction_model.hpp"

namespace iwb::models {

namespace {

constexpr double kDegree = M_PI / 180.0;

const ParameterTable& api_tz_table() {
  static const ParameterTable t{
      "api_tz",
      {{"delta_deg",
        "deg",
        {0.0, true},
        {90.0, true},
        "pile-soil interface friction angle: t_max = sigma_n tan(delta)",
        "API RP 2A f = K p'_0 tan(delta), sigma_n = K p'_0",
        ParameterRole::kMaterial,
        CalibrationBox{15.0, 40.0, false}},
       {"z_peak_mm",
        "mm",
        {0.0, true},
        {kUnbounded, true},
        "slip at which t_max is mobilised: API sand 0.1 in = 2.54 mm, API clay 0.01 D",
        "API RP 2GEO t-z curves"},
       {"shape",
        "-",
        {0.0, false},
        {1.0, false},
        "backbone: 0 = API sand (linear to z_peak), 1 = API clay (the z/D points)",
        "README",
        ParameterRole::kOption},
       {"t_res_ratio",
        "-",
        {0.0, true},
        {1.0, false},
        "t_res / t_max from 2 z_peak on: 1 for API sand (no drop), 0.70-0.90 for API clay",
        "API RP 2GEO t-z curves"},
       {"k_n_kPa_per_mm",
        "kPa/mm",
        {0.0, true},
        {kUnbounded, true},
        "normal stiffness, uncoupled (no dilatancy)",
        "README"}}};
  return t;
}

// A backbone point: slip over z_peak, t / t_max.
struct BackbonePoint {
  double u, f;
};
// API sand: t rises linearly to t_max at z_peak = 0.1 in (openpile's api_sand: 0.0254 m).
constexpr std::array<BackbonePoint, 1> kSandRise{{{1.0, 1.0}}};
// API clay: z/D = 0.0016, 0.0031, 0.0057, 0.0080, 0.0100 over z_peak = 0.01 D (API RP 2GEO's
// table as openpile's api_clay writes it; README.md).
constexpr std::array<BackbonePoint, 5> kClayRise{
    {{0.16, 0.30}, {0.31, 0.50}, {0.57, 0.75}, {0.80, 0.90}, {1.00, 1.00}}};
// Both reach t_res at z/D = 0.02, i.e. 2 z_peak, and stay there.
constexpr double kResidualSlip = 2.0;

// The backbone as a hardening curve: with the elastic slope k0 = f_1 / u_1 (the first segment),
// the plastic slip along the backbone is kappa = u - f / k0, and the strength g(kappa) passes
// through (kappa_i, f_i). Increasing in kappa because every later segment is flatter than k0, so
// monotonic loading retraces f(u) exactly and unloading is elastic at k0 (all in units of z_peak).
struct StrengthCurve {
  double k0 = 1.0;
  std::vector<double> kappa, g;

  template <class Rise>
  StrengthCurve(const Rise& rise, double t_res_ratio) {
    k0 = rise.front().f / rise.front().u;
    for (const auto& p : rise) add(p.u, p.f);
    add(kResidualSlip, t_res_ratio);
  }
  void add(double u, double f) {
    kappa.push_back(u - f / k0);
    g.push_back(f);
  }
  // The segment from kappa_j; the last point's constant beyond.
  int segment(double k) const {
    int j = 0;
    while (j + 1 < int(kappa.size()) && k >= kappa[j + 1]) ++j;
    return j;
  }
  double slope(int j) const {
    if (j + 1 >= int(kappa.size())) return 0.0;
    return (g[j + 1] - g[j]) / (kappa[j + 1] - kappa[j]);
  }
  template <class S>
  S strength(const S& k) const {
    const int j = segment(value_of(k));
    return g[j] + slope(j) * (k - kappa[j]);
  }
  // The plastic slip dk >= 0 that brings the trial mobilisation mt back onto the curve,
  // mt - k0 dk = g(k + dk): linear on each segment, and mt - k0 dk - g decreases strictly
  // (k0 + slope > 0 for a slope flatter than k0), so the first segment whose end is not passed
  // holds the one root.
  template <class S>
  S plastic_slip(const S& mt, const S& k) const {
    for (int j = segment(value_of(k));; ++j) {
      const S dk = (mt - g[j] - slope(j) * (k - kappa[j])) / (k0 + slope(j));
      if (j + 1 >= int(kappa.size()) || value_of(k + dk) <= kappa[j + 1]) return dk;
    }
  }
};

struct ApiTzParameters {
  double tan_delta, z_peak_mm, k_n, d_s_mm;
  StrengthCurve curve;
};

ApiTzParameters read(const ModelInputs& in) {
  const auto& v = require_table(in, "api_tz");
  require_keys(api_tz_table(), v, in.source + " [api_tz]");
  const double shape = v.at("shape");
  if (shape != 0.0 && shape != 1.0)
    throw InputError(fmt::format("{}: [api_tz] shape = {} is neither 0 (API sand) nor 1 (API clay)",
                                 in.source, shape));
  const double r = v.at("t_res_ratio");
  return {std::tan(v.at("delta_deg") * kDegree), v.at("z_peak_mm"), v.at("k_n_kPa_per_mm"),
          in.shear_zone_mm,
          shape == 0.0 ? StrengthCurve(kSandRise, r) : StrengthCurve(kClayRise, r)};
}

// State: [T_n, tau_x, tau_y, u_p_mm]: T_n = -sigma_n, the shear stresses, and the accumulated
// plastic slip kappa z_peak, which sets the strength g(kappa).
enum : int { kTn = kTractionN, kTauX = kTractionX, kTauY = kTractionY, kSlip = 3, kSize = 4 };

constexpr std::string_view kNeedsCompression = "t_max = sigma_n tan(delta) needs compression";

class ApiTz final : public TractionModel<ApiTz> {
 public:
  explicit ApiTz(ApiTzParameters p) : p_(std::move(p)) {}
  std::string_view name() const override { return "api-tz"; }
  int state_size() const override { return kSize; }
  std::vector<std::string> state_names() const override {
    return {"T_n", "tau_x", "tau_y", "u_p_mm"};
  }

  StateVector initial_state(const InitialState& in) const override {
    return unsheared_in_compression(in.sigma_n, kSize, kNeedsCompression);
  }
  std::string domain_violation(const StateVector& s) const override {
    return compression_violation(s, kNeedsCompression);
  }
  StateVector error_scale(const StateVector& s) const override {
    return traction_error_scale(s, p_.z_peak_mm);
  }
  std::vector<NamedValue> diagnostics(const StateVector& s) const override {
    return {{"mobilisation", std::hypot(s(kTauX), s(kTauY)) / (-s(kTn) * p_.tan_delta)},
            {"strength_level", p_.curve.strength(s(kSlip) / p_.z_peak_mm)}};
  }
  friend class TractionModel<ApiTz>;

 private:
  ApiTzParameters p_;

  // The increment in closed form. The normal stress first (uncoupled), then the mobilisation
  // m = tau / t_max, which a change of sigma_n alone leaves as it is (tau scales with t_max: the
  // t-z curve is drawn at the current t_max): trial m + k0 du / z_peak, returned radially onto
  // ||m|| = g(kappa) if beyond it, exact for any increment on the piecewise-linear curve.
  template <class S>
  void update_of(const StateVectorT<S>& s, const InterfaceStrainT<S>& d,
                 StateVectorT<S>& out) const {
    out = s;
    const S sigma_n = -s(kTn), sigma_n_new = sigma_n - p_.k_n * p_.d_s_mm * d.eps_n;
    const double k0 = p_.curve.k0, to_z = p_.d_s_mm / p_.z_peak_mm;  // strain -> u / z_peak
    const S mx = s(kTauX) / (sigma_n * p_.tan_delta) + k0 * to_z * d.gamma_x;
    const S my = s(kTauY) / (sigma_n * p_.tan_delta) + k0 * to_z * d.gamma_y;
    const S mt = safe_sqrt(S(mx * mx + my * my));
    const S kappa = s(kSlip) / p_.z_peak_mm;
    S shrink = S(1.0);
    if (value_of(mt) > value_of(p_.curve.strength(kappa))) {
      const S dk = p_.curve.plastic_slip(mt, kappa);
      shrink = (mt - k0 * dk) / mt;
      out(kSlip) += dk * p_.z_peak_mm;
    }
    const S t_max = sigma_n_new * p_.tan_delta;
    out(kTn) = -sigma_n_new, out(kTauX) = mx * shrink * t_max, out(kTauY) = my * shrink * t_max;
  }

  // The return's limit for a small increment: elastic inside, on the curve the plastic slip
  // that keeps ||m|| = g(kappa) when the trial loads it. Degree one in d, like every rate.
  template <class S>
  void rate_of(const StateVectorT<S>& s, const InterfaceStrainT<S>& d, StateVectorT<S>& ds) const {
    ds = StateVectorT<S>::Zero(kSize);
    const S sigma_n = -s(kTn), t_max = sigma_n * p_.tan_delta;
    const S dsigma_n = -p_.k_n * p_.d_s_mm * d.eps_n;
    const double k0 = p_.curve.k0, to_z = p_.d_s_mm / p_.z_peak_mm;
    const S mx = s(kTauX) / t_max, my = s(kTauY) / t_max;
    S dmx = k0 * to_z * d.gamma_x, dmy = k0 * to_z * d.gamma_y;
    const S m = safe_sqrt(S(mx * mx + my * my));
    const double kappa = value_of(s(kSlip)) / p_.z_peak_mm;
    const bool on_curve = value_of(m) > 0.0 && value_of(m) >= p_.curve.strength(kappa) - 1e-12;
    if (on_curve) {
      const S nx = mx / m, ny = my / m, along = nx * dmx + ny * dmy;
      if (value_of(along) > 0.0) {
        const S dk = along / (k0 + p_.curve.slope(p_.curve.segment(kappa)));
        dmx -= k0 * dk * nx, dmy -= k0 * dk * ny;
        ds(kSlip) = dk * p_.z_peak_mm;
      }
    }
    ds(kTn) = -dsigma_n;
    ds(kTauX) = t_max * dmx + mx * p_.tan_delta * dsigma_n;
    ds(kTauY) = t_max * dmy + my * p_.tan_delta * dsigma_n;
  }
};

}  // namespace

ModelSpec api_tz_spec() {
  ModelDeclaration d;
  d.listing_order = 24;  // after the other reference interface laws (mc 20 ... mortara 23)
  d.layout.components = traction_components();
  d.layout.components.push_back({"u_p_mm", "mm", ComponentKind::kHardening});
  d.layout.void_ratio = -1;
  d.initial = {{"sigma_n_kPa", "kPa", "initial normal stress (compression positive)"}};
  d.diagnostics = {
      {"mobilisation", "-", "||tau|| / (sigma_n tan delta): t / t_max"},
      {"strength_level", "-", "the largest t / t_max reachable now, g(kappa): 1 at the peak"}};
  d.update = StressPointUpdate::kIncrement;
  d.displacement_based = true;
  d.example_parameters = "api_tz_sand.toml";
  d.example_start = {{"sigma_n_kPa", 100.0}};
  return {"api-tz",
          "API RP 2GEO t-z curve (sand or clay shape) at t_max = sigma_n tan(delta), elastic "
          "unloading at the initial slope, no dilatancy",
          "API RP 2GEO / ISO 19901-4 t-z curves; unloading rule of README.md",
          false,
          {&api_tz_table()},
          [](const ModelInputs& in) { return std::make_unique<ApiTz>(read(in)); },
          d};
}

}  // namespace iwb::models
