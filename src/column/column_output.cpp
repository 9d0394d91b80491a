#include "column/column_output.hpp"

#include <fmt/core.h>

#include <chrono>

#include "io/run_directory.hpp"

namespace iwb::column {

namespace {

const char* to_string(TopBoundary t) {
  switch (t) {
    case TopBoundary::kCNL:
      return "CNL";
    case TopBoundary::kCNS:
      return "CNS";
    case TopBoundary::kCV:
      return "CV";
  }
  return "";
}

std::string timeseries_csv(const ColumnResult& r) {
  std::string out = "u_x_mm,tau_kPa,sigma_n_kPa,u_n_mm,slip_mm,e_wall_zone\n";
  for (const auto& row : r.rows)
    out += fmt::format("{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g}\n", row.u_mm, row.tau_kPa,
                       row.sigma_n_kPa, row.u_n_mm, row.slip_mm, row.e_wall_zone);
  return out;
}

std::string profiles_csv(const ColumnResult& r) {
  std::string out =
      "u_x_mm_window,z_over_d50,vx_over_vwall,spin_d50_over_vwall,shear_rate_d50_over_vwall,e,"
      "tau_zx_kPa,tau_xz_kPa,sigma_zz_kPa,m_kPa_mm\n";
  for (const auto& p : r.profiles)
    for (std::size_t k = 0; k < p.z_over_d50.size(); ++k)
      out += fmt::format(
          "{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g}\n",
          p.u_mm, p.z_over_d50[k], p.vx_over_vwall[k], p.spin[k], p.shear_rate[k], p.e[k],
          p.tau_kPa[k], p.T21_kPa[k], p.sigma_zz_kPa[k], p.m_kPa_mm[k]);
  return out;
}

nlohmann::json bands_json(const ColumnResult& r) {
  nlohmann::json bands = nlohmann::json::array();
  for (const auto& p : r.profiles) {
    const auto b = band_widths(p);
    bands.push_back(
        {{"u_x_mm", p.u_mm}, {"band_fwhm_d50", b.fwhm_d50}, {"band_velocity_d50", b.velocity_d50}});
  }
  return bands;
}

std::string band_csv(const nlohmann::json& bands) {
  std::string out = "u_x_mm,band_fwhm_d50,band_velocity_d50\n";
  for (const auto& b : bands)
    out += fmt::format("{:.10g},{:.10g},{:.10g}\n", b["u_x_mm"].get<double>(),
                       b["band_fwhm_d50"].get<double>(), b["band_velocity_d50"].get<double>());
  return out;
}

// The run's quantities under the names a DEM run's summary.json gives them (peak_friction,
// dilation_mm), so that a claims file (`iwb claims`) sets a column against its DEM runs; beside
// them the friction and the band at the end and the share of the last fifth of the travel that
// the wall slid.
nlohmann::json summary_json(const ColumnResult& r, const nlohmann::json& bands) {
  double peak = 0.0;
  for (std::size_t k = 1; k < r.rows.size(); ++k)
    peak = std::max(peak, r.rows[k].tau_kPa / r.rows[k].sigma_n_kPa);
  const auto& end = r.rows.back();
  const auto& fifth = r.rows[r.rows.size() - 1 - (r.rows.size() - 1) / 5];
  const double travel = end.u_mm - fifth.u_mm;
  return {{"status", r.status},
          {"peak_friction", peak},
          {"end_friction", end.tau_kPa / end.sigma_n_kPa},
          {"dilation_mm", end.u_n_mm},
          {"band_fwhm_d50", bands.empty() ? nlohmann::json() : bands.back()["band_fwhm_d50"]},
          {"wall_slip_share", travel > 0.0 ? (end.slip_mm - fifth.slip_mm) / travel : 0.0}};
}

}  // namespace

nlohmann::json spec_json(const ColumnSpec& s) {
  return {{"height_mm", s.height_mm},
          {"d50_mm", s.d50_mm},
          {"elements", s.elements},
          {"element_d50", s.height_mm / s.elements / s.d50_mm},
          {"e0", s.e0},
          {"sigma_n0_kPa", s.sigma_n0_kPa},
          {"top", to_string(s.top)},
          {"stiffness_kPa_per_mm", s.stiffness_kPa_per_mm},
          {"wall_rotation", s.wall_rotation == WallRotation::kFixed ? "fixed" : "free"},
          {"wall_friction", std::isfinite(s.wall_friction) ? nlohmann::json(s.wall_friction)
                                                           : nlohmann::json("no slip")},
          {"polar", s.polar},
          {"imperfection", s.imperfection},
          {"travel_mm", s.travel_mm},
          {"increments", s.increments},
          {"wall_zone_mm", wall_zone_of(s)},
          {"profile_at_mm", s.profile_at_mm},
          {"substep_strain", s.substep_strain}};
}

ColumnResult run_column_into(const ColumnSpec& spec, const std::filesystem::path& dir, bool force,
                             const nlohmann::json& inputs, const nlohmann::json& dem_runs,
                             const std::function<void(long, long)>& progress) {
  require_spec(spec);  // before anything is written
  io::prepare_run_directory(dir, {"column"}, force);
  nlohmann::json m = {{"kind", "column"}, {"status", "running"},  {"spec", spec_json(spec)},
                      {"inputs", inputs}, {"dem_runs", dem_runs}, {"started", io::utc_timestamp()}};
  io::write_manifest(dir, m);
  const auto t0 = std::chrono::steady_clock::now();
  const auto r = run_column(spec, progress);
  const auto bands = bands_json(r);
  io::write_atomically(dir / "timeseries.csv", timeseries_csv(r));
  io::write_atomically(dir / "profiles.csv", profiles_csv(r));
  io::write_atomically(dir / "band.csv", band_csv(bands));
  io::write_atomically(dir / "summary.json", summary_json(r, bands).dump(1) + "\n");
  m["status"] = r.status == "complete" ? "complete" : "stopped";
  m["reason"] = r.status;
  m["bands"] = bands;
  m["newton_iterations"] = r.newton_iterations;
  m["cutbacks"] = r.cutbacks;
  m["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  m["finished"] = io::utc_timestamp();
  io::write_manifest(dir, m);
  return r;
}

}  // namespace iwb::column
