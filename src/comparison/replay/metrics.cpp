#include "comparison/replay/metrics.hpp"

#include <algorithm>
#include <cmath>

namespace iwb::comparison {

namespace {

double rmse(const std::vector<double>& a, const std::vector<double>& b, std::size_t n) {
  double s = 0.0;
  for (std::size_t i = 0; i < n; ++i) s += (a[i] - b[i]) * (a[i] - b[i]);
  return std::sqrt(s / double(n));
}

struct Friction {
  double peak, u_at_peak, residual;
};

// The peak along u_x, and the mean over the last fifth of `travel`: u_x itself on a monotonic
// path; on a cyclic one, which returns through u_x, the wall's travel v t, as its summary.json's
// end of path (issue 59).
Friction friction(const std::vector<double>& u, const std::vector<double>& travel,
                  const std::vector<double>& tau, const std::vector<double>& sigma, std::size_t n) {
  Friction f{0.0, 0.0, 0.0};
  for (std::size_t i = 0; i < n; ++i)
    if (std::abs(tau[i]) / sigma[i] > f.peak)
      f.peak = std::abs(tau[i]) / sigma[i], f.u_at_peak = u[i];
  const double from = (1.0 - kResidualWindowShare) * travel[n - 1];
  int count = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (travel[i] >= from) f.residual += std::abs(tau[i]) / sigma[i], ++count;
  f.residual /= std::max(count, 1);
  return f;
}

}  // namespace

const char* end_friction_key(bool cyclic) {
  return cyclic ? "end_of_path_friction" : "residual_friction";
}

Metrics compare(const DemRun& dem, const Replay& r) {
  const std::size_t n = r.u_x_mm.size();
  Metrics m{};
  m.rows_compared = n;
  m.cyclic = dem.cyclic();
  if (n < 2) return m;
  m.rmse_tau_kPa = rmse(dem.tau_kPa, r.tau_kPa, n);
  // a replay's rows are the DEM's, in time: one travel for both
  const std::vector<double> travel = m.cyclic ? cyclic_travel(dem) : dem.u_x_mm;
  const Friction fd = friction(dem.u_x_mm, travel, dem.tau_kPa, dem.sigma_n_kPa, n);
  const Friction fm = friction(r.u_x_mm, m.cyclic ? travel : r.u_x_mm, r.tau_kPa, r.sigma_n_kPa, n);
  m.peak_friction_dem = fd.peak, m.peak_friction_model = fm.peak;
  m.residual_friction_dem = fd.residual, m.residual_friction_model = fm.residual;
  m.u_x_at_peak_dem_mm = fd.u_at_peak, m.u_x_at_peak_model_mm = fm.u_at_peak;
  if (dem.boundary != driver::BoundaryKind::kCV) m.rmse_u_n_mm = rmse(dem.u_n_mm, r.u_n_mm, n);
  if (dem.boundary != driver::BoundaryKind::kCNL)
    m.rmse_sigma_n_kPa = rmse(dem.sigma_n_kPa, r.sigma_n_kPa, n);
  return m;
}

nlohmann::json to_json(const Metrics& m) {
  auto opt = [](const std::optional<double>& v) {
    return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
  };
  return {{"rows_compared", m.rows_compared},
          {"rmse_tau_kPa", m.rmse_tau_kPa},
          {"peak_friction",
           {{"dem", m.peak_friction_dem},
            {"model", m.peak_friction_model},
            {"error", m.peak_friction_model - m.peak_friction_dem}}},
          {end_friction_key(m.cyclic),
           {{"dem", m.residual_friction_dem},
            {"model", m.residual_friction_model},
            {"error", m.residual_friction_model - m.residual_friction_dem}}},
          {"u_x_at_peak_mm",
           {{"dem", m.u_x_at_peak_dem_mm},
            {"model", m.u_x_at_peak_model_mm},
            {"error", m.u_x_at_peak_model_mm - m.u_x_at_peak_dem_mm}}},
          {"rmse_u_n_mm", opt(m.rmse_u_n_mm)},
          {"rmse_sigma_n_kPa", opt(m.rmse_sigma_n_kPa)}};
}

}  // namespace iwb::comparison
