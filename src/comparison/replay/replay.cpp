#include "comparison/replay/replay.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "common/errors.hpp"

namespace iwb::comparison {

namespace {

driver::Path dem_path(const DemRun& dem, double d_s_mm) {
  driver::Path path;
  // CNL follows the measured normal stress; CNS and CV are the scene's own boundary.
  const auto bc = driver::with_stiffness_per_mm(dem.boundary, dem.K_kPa_per_mm, d_s_mm);
  for (std::size_t i = 1; i < dem.u_x_mm.size(); ++i) {
    const double dgamma = (dem.u_x_mm[i] - dem.u_x_mm[i - 1]) / d_s_mm;
    const int n = std::max(1, int(std::ceil(std::abs(dgamma) / kReplayStrainIncrement)));
    const auto row = bc.row((dem.sigma_n_kPa[i] - dem.sigma_n_kPa[i - 1]) / n);
    path.push_back({fmt::format("DEM row {}", i), dgamma, 0.0, row, n});
  }
  return path;
}

// The void ratio of the DEM's wall zone (height h above the wall) when the model's band of
// thickness d_s, now at void ratio e, lies at its bottom: the band's grains, d_s / (1 + e0) of
// solid, fill d_s (1 + e) / (1 + e0); a band still inside the zone pushed as much of the grains
// above it (at e0) out of the zone's top, a band that reaches beyond the zone fills it at e.
double zone_void_ratio(double e0, double e, double d_s, double h) {
  const double band = d_s * (1.0 + e) / (1.0 + e0);
  if (band >= h) return e;
  return h * (1.0 + e0) / (h - (band - d_s)) - 1.0;
}

}  // namespace

Start start_of(const DemRun& dem, const Variant& v) {
  const auto& spec = models::find_model(v.model);
  models::ModelInputs in = v.inputs;
  in.shear_zone_mm = v.d_s_mm;  // a model with stiffness per displacement scales by it (hyperbolic)
  Start out;
  // a fit of material parameters may try a set the model refuses (Mohr-Coulomb's psi above phi):
  // InputError, as a start outside the domain
  out.model = spec.make(in);
  // from the DEM's first state: its sigma_n, the void ratio of its wall band
  const auto init = models::offer(
      spec, v.inputs, {{"sigma_n_kPa", dem.sigma_n_kPa.front()}, {"e0", dem.e_band.front()}});
  out.state = out.model->initial_state(init);
  return out;
}

std::string inadmissible_start(const DemRun& dem, const Variant& v) {
  try {
    start_of(dem, v);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

Replay replay(const DemRun& dem, const Variant& v, const driver::RunSettings& settings) {
  Replay out{v, "", {}, {}, {}, {}, {}, dem.e_band.front()};
  Start start;
  try {
    start = start_of(dem, v);
  } catch (const InputError& e) {
    // the DEM's start lies outside this variant's domain (a clay model's critical state cone
    // shrinks with kappa_r, eq. 6.22): a replay that reaches no row, which the fit and the scan
    // weigh as a miss, not the end of the comparison
    out.status = fmt::format("failed: inadmissible start: {}", e.what());
    return out;
  }
  auto& model = start.model;
  const auto& s0 = start.state;
  driver::RunSettings rs = settings;
  rs.output_every = 1;
  const auto result = driver::run_element_test(*model, s0, dem_path(dem, v.d_s_mm), rs);
  out.status = result.status;
  // the state at the end of each segment is the model's answer at that DEM row
  std::vector<const driver::HistoryRow*> at_row(dem.u_x_mm.size(), nullptr);
  at_row[0] = &result.rows.front();
  for (const auto& r : result.rows)
    if (r.segment >= 0) at_row[std::size_t(r.segment) + 1] = &r;  // last row of the segment wins
  for (std::size_t i = 0; i < at_row.size() && at_row[i] != nullptr; ++i) {
    const auto s = model->stress(at_row[i]->state);
    out.u_x_mm.push_back(dem.u_x_mm[i]);
    out.tau_kPa.push_back(s.tau_x);
    out.sigma_n_kPa.push_back(s.sigma_n);
    out.u_n_mm.push_back(at_row[i]->eps_n * v.d_s_mm);
    // the band's void ratio: the model's own (a hypoplastic e follows de = (1 + e) d eps_v, so
    // 1 + e = (1 + e0) exp(eps_n)), else, for a model without one, from its strain
    double e = model->void_ratio(at_row[i]->state);
    if (!std::isfinite(e)) e = (1.0 + out.e0) * (1.0 + at_row[i]->eps_n) - 1.0;
    out.e_band.push_back(zone_void_ratio(out.e0, e, v.d_s_mm, dem.wall_zone_mm));
  }
  return out;
}

}  // namespace iwb::comparison
