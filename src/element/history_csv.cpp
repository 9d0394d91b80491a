#include "element/history_csv.hpp"

#include <fmt/core.h>

#include <cmath>

namespace iwb::element {

namespace {

// The state components holding external variables (T_K, s_kPa, t_s), by the names the model gives
// them.
std::vector<std::pair<std::string, int>> external_columns(const models::Model& model) {
  const auto names = model.state_names();
  std::vector<std::pair<std::string, int>> columns;
  for (int slot = 0; slot < models::kExternalSlots; ++slot)
    for (std::size_t i = 0; i < names.size(); ++i)
      if (names[i] == models::external_key(models::External(slot)))
        columns.push_back({names[i], int(i)});
  return columns;
}

}  // namespace

std::string history_csv(const models::Model& model, const driver::ShearZone& zone,
                        const std::vector<driver::HistoryRow>& rows,
                        driver::ShearDirection direction) {
  std::string out =
      "increment,segment,u_x_mm,u_y_mm,u_n_mm,gamma_x,gamma_y,eps_n,sigma_n_kPa,sigma_p_kPa,"
      "tau_x_kPa,tau_y_kPa,tau_over_sigma_n,e";
  const auto externals = external_columns(model);
  for (const auto& [name, index] : externals) out += "," + name;
  if (!rows.empty())
    for (const auto& d : model.diagnostics(rows.front().state)) out += "," + d.name;
  out += ",newton_iterations,rate_evaluations,rejected_substeps\n";
  // Every number in its shortest form that reads back to the same double: a caller of the C
  // interface (src/c_api) is held against this file to round-off.
  for (const auto& r : rows) {
    const auto s = model.stress(r.state);
    // sigma_p is empty for models without an in-plane stress (hp1d), never NaN.
    const std::string sigma_p = s.sigma_p ? fmt::format("{}", *s.sigma_p) : "";
    // e is empty for models without a void ratio (mc: NaN from void_ratio), like sigma_p
    const double e = model.void_ratio(r.state);
    const std::string e_field = std::isnan(e) ? "" : fmt::format("{}", e);
    out += fmt::format(
        "{},{},{},{},{},{},{},{},{},{},{},"
        "{},{},{}",
        r.increment, r.segment, zone.u_of(r.gamma_x), zone.u_of(r.gamma_y), zone.u_n_of(r.eps_n),
        r.gamma_x, r.gamma_y, r.eps_n, s.sigma_n, sigma_p, s.tau_x, s.tau_y,
        (direction == driver::ShearDirection::kY ? s.tau_y : s.tau_x) / s.sigma_n, e_field);
    for (const auto& [name, index] : externals) out += fmt::format(",{}", r.state(index));
    for (const auto& d : model.diagnostics(r.state)) out += fmt::format(",{}", d.value);
    out += fmt::format(",{},{},{}\n", r.newton_iterations, r.rate_evaluations, r.rejected_substeps);
  }
  return out;
}

std::string cycles_csv(const driver::ShearZone& zone,
                       const std::vector<driver::CycleSummary>& cycles) {
  std::string out =
      "cycle,tau_max_kPa,tau_min_kPa,sigma_n_at_plus_reversal_kPa,sigma_n_at_minus_reversal_kPa,"
      "sigma_n_end_kPa,u_n_end_mm,du_n_cycle_mm,e_end,complete\n";
  // A reversal not reached (a failed run) is an empty field, never NaN.
  const auto field = [](double v) {
    return std::isfinite(v) ? fmt::format("{:.10g}", v) : std::string();
  };
  for (const auto& c : cycles)
    out += fmt::format(
        "{},{},{},{},{},{},{},{},{},{}\n", c.cycle, field(c.tau_max_kPa), field(c.tau_min_kPa),
        field(c.sigma_n_at_plus_kPa), field(c.sigma_n_at_minus_kPa), field(c.sigma_n_end_kPa),
        field(zone.u_n_of(c.eps_n_end)), field(zone.u_n_of(c.eps_n_end - c.eps_n_start)),
        field(c.e_end), c.complete ? 1 : 0);
  return out;
}

}  // namespace iwb::element
