#include "dem/analysis/summary.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "walls/descriptors.hpp"

namespace iwb::dem {

namespace {

using statistics::kResidualWindowShare;  // the end friction's window: the last fifth
constexpr double kFirstLayerD50 = 1.0;   // the first grain layer above the wall surface
constexpr double kDistributedR2 = 0.95;  // a linear velocity profile this good: no band
constexpr double kDefaultBandD50 = 10.0;
// Bin heights are read to 1e-6 d50 (rounded as round(z 1e6) / 1e6, which lands on the decimal
// value itself): the profile's bins sit on a grid of bin centres, and the middle third's bounds
// (height / 3, 2 height / 3) and the first layer's fall on such centres, so a height of 13.9999999
// in memory and 14 in the 10-digit profiles.csv would take a bin in or out and move the far-field
// median (by 0.02 of v_wall, the band by 0.5 d50, in a truth run at R_n 0.1).
constexpr double kHeightStepsPerD50 = 1e6;
constexpr double kLocalisedFarField = 0.25;  // far field below this: the wall takes >= 75 %

struct Fit {
  double slope, intercept, r2;
};

Fit linear_fit(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = double(x.size());
  const double mx = std::accumulate(x.begin(), x.end(), 0.0) / n;
  const double my = std::accumulate(y.begin(), y.end(), 0.0) / n;
  double sxy = 0, sxx = 0, syy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxy += (x[i] - mx) * (y[i] - my);
    sxx += (x[i] - mx) * (x[i] - mx);
    syy += (y[i] - my) * (y[i] - my);
  }
  const double slope = sxx > 0 ? sxy / sxx : 0.0;
  return {slope, my - slope * mx, (sxx > 0 && syy > 0) ? sxy * sxy / (sxx * syy) : 0.0};
}

// Width w of r(z) = erfc((z - zc)/w)/2 by least squares on a refined grid; the 0.9 -> 0.1 width
// of that profile is 2 * 0.9062 w.
double erfc_width(const std::vector<double>& z, const std::vector<double>& r, double height) {
  double best = INFINITY, best_w = NAN;
  double zc_lo = 0.0, zc_hi = height, w_lo = 0.05, w_hi = height;
  for (int level = 0; level < 4; ++level) {
    double bz = 0, bw = 0;
    for (int i = 0; i <= 40; ++i)
      for (int j = 0; j <= 40; ++j) {
        const double zc = zc_lo + (zc_hi - zc_lo) * i / 40.0,
                     w = w_lo * std::pow(w_hi / w_lo, j / 40.0);
        double sse = 0;
        for (std::size_t k = 0; k < z.size(); ++k) {
          const double d = 0.5 * std::erfc((z[k] - zc) / w) - r[k];
          sse += d * d;
        }
        if (sse < best) best = sse, bz = zc, bw = w, best_w = w;
      }
    const double dz = (zc_hi - zc_lo) / 20.0;
    zc_lo = std::max(0.0, bz - dz), zc_hi = bz + dz;
    w_lo = bw / 1.5, w_hi = bw * 1.5;
  }
  return 2.0 * 0.9062 * best_w;
}

// The velocity and porosity profile of the last window (bin heights on the d50 grid: see above).
struct Profile {
  std::vector<double> z, v, porosity;
};

Profile last_window(const io::CsvTable& profiles) {
  Profile p;
  const auto window = profiles.values("u_x_mm_window");
  const double last = *std::max_element(window.begin(), window.end());
  for (const auto& row : profiles.rows)
    if (row[profiles.column("u_x_mm_window")] == last &&
        row[profiles.column("z_over_d50")] >= 0.0) {
      p.z.push_back(std::round(row[profiles.column("z_over_d50")] * kHeightStepsPerD50) /
                    kHeightStepsPerD50);
      p.v.push_back(row[profiles.column("vx_over_vwall")]);
      p.porosity.push_back(row[profiles.column("porosity")]);
    }
  return p;
}

// The mean speed of the first grain layer, relative to the wall's.
double first_layer_speed(const Profile& p) {
  double first = 0.0;
  int n_first = 0;
  for (std::size_t i = 0; i < p.z.size(); ++i)
    if (p.z[i] <= kFirstLayerD50) first += p.v[i], ++n_first;
  return n_first ? first / n_first : p.v.front();
}

// Where shear localised and how wide its bands are, from the speeds r relative to the first
// layer's and the far field's `far`; returns the top of the zone whose porosity is e_band's.
double localised_bands(const Profile& p, const std::vector<double>& r, double far, Summary& s) {
  const auto& z = p.z;
  const double height = z.back();
  double band_top = std::min(kDefaultBandD50, 0.5 * height);
  s.shear_mode = far < kLocalisedFarField         ? "localised at the wall"
                 : far > 1.0 - kLocalisedFarField ? "localised at the plate"
                                                  : "split between wall and plate";
  // the wall band: from the wall until r is within 10 % of its drop from the far field (only
  // where the wall carries a real share of the drop)
  for (std::size_t i = 0; i < z.size() && far < 1.0 - kLocalisedFarField; ++i)
    if (r[i] - far <= 0.1 * (1.0 - far)) {
      s.wall_band_d50 = z[i];
      band_top = z[i];
      break;
    }
  // the plate band: from the top down until r is within 10 % of the far field (a rough plate
  // holds its grains at rest; DEM.md: shear may localise there instead of at the wall)
  for (std::size_t i = z.size(); i-- > 0;)
    if (r[i] >= 0.9 * far) {
      if (far > kLocalisedFarField) s.plate_band_d50 = height - z[i];
      break;
    }
  // Relative to the first layer (DEM.md: on smooth walls the 0.9 -> 0.1 band is undefined
  // against the wall's speed because the wall slips).
  double z90 = NAN, z10 = NAN;
  for (std::size_t i = 0; i < z.size(); ++i) {
    if (std::isnan(z90) && r[i] < 0.9) z90 = z[i];
    if (std::isnan(z10) && r[i] < 0.1) z10 = z[i];
  }
  if (far < kLocalisedFarField && !std::isnan(z90) && !std::isnan(z10))
    s.band_thickness_d50 = z10 - z90;
  std::vector<double> zl, ql;  // the wall band normalised to [0, 1], lower half of the specimen
  for (std::size_t i = 0; i < z.size(); ++i)
    if (z[i] <= 0.5 * height) zl.push_back(z[i]), ql.push_back((r[i] - far) / (1.0 - far));
  if (zl.size() >= 4 && far < 1.0 - kLocalisedFarField)
    s.band_thickness_erf_d50 = erfc_width(zl, ql, 0.5 * height);
  return band_top;
}

void shear_band(const io::CsvTable& profiles, Summary& s) {
  const Profile p = profiles.rows.empty() ? Profile{} : last_window(profiles);
  if (p.z.size() < 4) {
    s.shear_mode = "no profile";
    return;
  }
  const double first = first_layer_speed(p);
  s.wall_slip = 1.0 - first;
  std::vector<double> r;
  for (double x : p.v) r.push_back(first > 1e-9 ? x / first : 0.0);
  const double height = p.z.back();
  std::vector<double> middle;
  for (std::size_t i = 0; i < p.z.size(); ++i)
    if (p.z[i] >= height / 3.0 && p.z[i] <= 2.0 * height / 3.0) middle.push_back(r[i]);
  std::nth_element(middle.begin(), middle.begin() + long(middle.size() / 2), middle.end());
  const double far = middle.empty() ? 0.0 : middle[middle.size() / 2];
  s.far_field_speed = far;
  s.wall_share = 1.0 - far;
  const bool distributed = linear_fit(p.z, r).r2 > kDistributedR2;
  if (distributed) s.shear_mode = "distributed shear";
  const double band_top =
      distributed ? std::min(kDefaultBandD50, 0.5 * height) : localised_bands(p, r, far, s);
  double n = 0;
  int count = 0;
  for (std::size_t i = 0; i < p.z.size(); ++i)
    if (p.z[i] <= band_top) n += p.porosity[i], ++count;
  if (count > 0) {
    n /= count;
    s.e_band = n / (1.0 - n);
  }
}

}  // namespace

Summary summarize(const Scene& scene, const io::CsvTable& ts, const io::CsvTable& profiles) {
  Summary s;
  const auto ux = ts.values("u_x_mm"), un = ts.values("u_n_mm");
  const auto sigma = ts.values("sigma_n_kPa"), tau = ts.values("tau_kPa");
  if (ux.empty()) return s;
  // |tau|/sigma_n along the travelled distance, so that reversals (cyclic shear) count alike
  std::vector<double> friction(ux.size()), travel(ux.size(), 0.0);
  for (std::size_t i = 0; i < ux.size(); ++i) {
    friction[i] = std::abs(tau[i]) / sigma[i];
    if (i > 0) travel[i] = travel[i - 1] + std::abs(ux[i] - ux[i - 1]);
  }
  const auto peak = std::max_element(friction.begin(), friction.end());
  s.peak_friction = *peak;
  s.u_x_at_peak_mm = ux[std::size_t(peak - friction.begin())];
  const double u_end = travel.back(), u_from = (1.0 - kResidualWindowShare) * u_end;
  std::vector<double> xs, fs, ns;
  for (std::size_t i = 0; i < ux.size(); ++i)
    if (travel[i] >= u_from)
      xs.push_back(travel[i]), fs.push_back(friction[i]), ns.push_back(un[i]);
  if (scene.shear.cyclic()) {
    // the wall moves at v throughout (no ramp with cycles): its travel is v t
    cycles::Path path{cycles::travel_at_speed(ts.values("t_s"), scene.shear.velocity_m_s * 1e3),
                      ux,
                      un,
                      sigma,
                      tau,
                      ts.column("e_band") >= 0 ? ts.values("e_band") : std::vector<double>{}};
    s.cyclic = cycles::cyclic_quantities(
        path, {scene.shear.amplitude_m * 1e3, scene.shear.cycles, scene.shear.post_cyclic_m * 1e3});
  }
  s.end_friction = std::accumulate(fs.begin(), fs.end(), 0.0) / double(fs.size());
  const double d50_mm = scene.particles.d50_m * 1e3;
  const std::size_t peak_row = std::size_t(peak - friction.begin());
  if (!scene.shear.cyclic()) {
    s.residual_test = statistics::residual_steady_state(travel, friction, peak_row, d50_mm);
    s.rate_at_peak = statistics::local_rate(travel, un, travel[peak_row], kRateHalfSpanD50 * d50_mm,
                                            kRateBlockD50 * d50_mm);
  }
  s.dilation_mm = un.back();
  s.dilatancy_angle_deg = std::atan(linear_fit(xs, ns).slope) * 180.0 / M_PI;
  const double target = scene.boundary.sigma_n_Pa / 1e3;
  s.sigma_n_mean_kPa = std::accumulate(sigma.begin(), sigma.end(), 0.0) / double(sigma.size());
  for (double x : sigma)
    s.sigma_n_max_deviation = std::max(s.sigma_n_max_deviation, std::abs(x / target - 1.0));
  shear_band(profiles, s);
  // a flat wall has none; a scene without a box (a test's synthetic run) describes no wall
  if (scene.wall.kind != walls::ProfileKind::kFlat && scene.length_m > 0.0 && scene.width_m > 0.0 &&
      scene.particles.d50_m > 0.0)
    s.wall_mean_abs_slope =
        walls::describe_roughness(scene.wall, scene.length_m, scene.width_m, scene.particles.d50_m)
            .mean_abs_slope;
  return s;
}

nlohmann::json to_json(const Summary& s) {
  auto opt = [](const std::optional<double>& v) {
    return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
  };
  nlohmann::json out = {
      {"peak_friction", s.peak_friction},
      {"u_x_at_peak_mm", s.u_x_at_peak_mm},
      {"dilation_mm", s.dilation_mm},
      {"dilatancy_angle_deg", s.dilatancy_angle_deg},
      {"sigma_n_mean_kPa", s.sigma_n_mean_kPa},
      {"sigma_n_max_relative_deviation", s.sigma_n_max_deviation},
      {"shear_mode", s.shear_mode},
      {"far_field_speed", s.far_field_speed},
      {"wall_share_of_velocity_drop", s.wall_share},
      {"wall_band_d50", opt(s.wall_band_d50)},
      {"plate_band_d50", opt(s.plate_band_d50)},
      {"band_thickness_d50", opt(s.band_thickness_d50)},
      {"band_thickness_erfc_fit_d50", opt(s.band_thickness_erf_d50)},
      {"wall_slip", s.wall_slip},
      {"e_band", opt(s.e_band)},
      {"wall_mean_abs_slope", s.wall_mean_abs_slope},
      {"cyclic", s.cyclic ? cycles::to_json(*s.cyclic) : nlohmann::json(nullptr)},
      {"definitions",
       {{"friction", "tau/sigma_n, both on the tested wall"},
        {"residual",
         "mean |tau|/sigma_n over the last fifth of the travel (a monotonic run); 'steady' only "
         "where the decay fitted from the peak has at most 2.5 % of it to go at the window's "
         "centre and the window's half-grain block means do not drift "
         "(statistics/steady_state.hpp)"},
        {"end_of_path_friction",
         "a cyclic run's mean |tau|/sigma_n over the last fifth of its travel: not a residual"},
        {"dilatancy_rate_at_peak",
         "d u_n / d u_x over half a d50 either side of the peak friction: the mean of the "
         "least-squares slopes of blocks of d50 / 8, with its 95 % t half-width over the blocks"},
        {"far_field_speed",
         "median vx over the middle third of the specimen, relative to the first grain layer"},
        {"wall_band", "from the wall until vx is within 10 % of its drop to the far field"},
        {"plate_band", "from the top of the specimen down until vx reaches 90 % of the far field"},
        {"band",
         "where vx falls from 0.9 to 0.1 of the first grain layer's speed; only when the far field "
         "is at rest (< 0.25); 'distributed shear' when the profile is linear (R^2 > 0.95)"},
        {"e_band", "porosity of the band (or the lowest 10 d50) as void ratio"},
        {"wall_mean_abs_slope",
         "the tested wall's mean |dz/dx| along the shear, from the scene (iwb dem roughness)"}}}};
  if (s.cyclic) {
    out["end_of_path_friction"] = s.end_friction;
    out["last_cycle_mean_friction"] = nullptr;
    if (!s.cyclic->cycles.empty())
      out["last_cycle_mean_friction"] = s.cyclic->cycles.back().mean_friction;
    return out;
  }
  out["residual_friction"] = s.end_friction;
  out["residual_is"] = s.steady() ? "steady" : "not steady";
  out["residual_test"] = nullptr;
  if (s.residual_test)
    out["residual_test"] = {
        {"to_go_at_window_centre", s.residual_test->remaining},
        {"window_mean", s.residual_test->window_mean},
        {"window_drift", s.residual_test->window_drift},
        {"window_drift_ci95", s.residual_test->window_drift_ci},
        {"allowed", statistics::kSteadyShare * std::abs(s.residual_test->window_mean)},
        {"extrapolated_steady", opt(s.residual_test->extrapolated)}};
  out["dilatancy_rate_at_peak"] = nullptr;
  if (s.rate_at_peak)
    out["dilatancy_rate_at_peak"] = {{"rate", s.rate_at_peak->rate},
                                     {"ci95", s.rate_at_peak->half_width},
                                     {"blocks", s.rate_at_peak->blocks},
                                     {"from_u_x_mm", s.rate_at_peak->from},
                                     {"to_u_x_mm", s.rate_at_peak->to}};
  return out;
}

}  // namespace iwb::dem
