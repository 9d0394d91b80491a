// Writing a calibration: the parameter file in the data/params format and calibration.json.
#include <fmt/core.h>

#include <cmath>

#include "calibration/calibrate.hpp"
#include "calibration/pareto.hpp"
#include "io/output_path.hpp"
#include "io/run_directory.hpp"

namespace iwb::calibration {

namespace {

std::string sigma_text(const ParameterEstimate& p) {
  return std::isfinite(p.sigma) ? fmt::format("+- {:.3g}", p.sigma) : "+- undefined";
}

}  // namespace

std::string parameter_file_text(const CalibrationResult& r,
                                const std::vector<soil_test::SoilTest>& tests,
                                const std::string& command_line) {
  std::string s = fmt::format("# Calibrated by `iwb calibrate` ({}) for {} from {} soil test(s):\n",
                              io::utc_timestamp(), r.model, tests.size());
  for (const auto& t : r.tests) {
    s += fmt::format("#   {} ({}{}{}), RMSE", t.name, t.test, t.boundary.empty() ? "" : " ",
                     t.boundary);
    for (const auto& c : t.rmse) s += fmt::format(" {} {:.3g}", c.column, c.rmse);
    s += "\n";
  }
  s += fmt::format(
      "# Joint fit s^2 = {:.3g} (residuals in units of {} sigma0 for stresses, {} for e, {} for a "
      "peak dilatancy rate, or of the seed scatter of tests run with several seeds where larger: "
      "calibration.json).\n# Objective groups (weight: RMS in scatter units):",
      r.s2, kStressRatioScale, kVoidRatioScale, kDilatancyRateScale);
  for (const auto& g : r.objectives)
    s += fmt::format(" {} ({:.4g}: {:.3g})", to_string(g.group), g.weight, g.rms);
  s += "\n";
  s += "# Per parameter: value +- one sigma (Gauss-Newton), and how it was set. See "
       "calibration.json.\n";
  s += fmt::format("# Command: {}\n[{}]\n", command_line, r.table);
  for (const auto& p : r.parameters)
    s += fmt::format("{} = {:.9g}  # {} ({})\n", p.key, p.value, sigma_text(p), p.how);
  for (const auto& [table, values] : r.held) {
    s += fmt::format("\n# held as given (--params), not fitted\n[{}]\n", table);
    for (const auto& [key, value] : values) s += fmt::format("{} = {:.9g}\n", key, value);
  }
  return s;
}

namespace {

nlohmann::json finite_or_null(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json();
}

}  // namespace

nlohmann::json calibration_json(const CalibrationResult& r,
                                const std::vector<soil_test::SoilTest>& tests,
                                const std::string& command_line) {
  nlohmann::json j;
  j["kind"] = "calibration";
  j["model"] = r.model;
  j["table"] = r.table;
  if (!r.held.empty()) j["held"] = r.held;
  j["command_line"] = command_line;
  j["finished"] = io::utc_timestamp();
  j["wall_seconds"] = r.seconds;
  j["evaluations"] = r.evaluations;
  j["converged"] = r.converged;
  j["s2_scatter_units"] = r.s2;
  j["residual_scales"] = {{"stress_over_sigma0", kStressRatioScale},
                          {"void_ratio", kVoidRatioScale},
                          {"peak_dilatancy_rate", kDilatancyRateScale}};
  for (const auto& g : r.objectives)
    j["objectives"][to_string(g.group)] = {{"weight", g.weight},
                                           {"residuals", g.residuals},
                                           {"rms_scatter_units", g.rms},
                                           {"unreached_residuals", g.unreached},
                                           {"what", describe(g.group)}};
  for (const auto& p : r.parameters)
    j["parameters"].push_back(
        {{"key", p.key},
         {"value", p.value},
         {"sigma", finite_or_null(p.sigma)},
         {"sigma_statistical", finite_or_null(p.sigma_statistical)},
         {"sigma_systematic", finite_or_null(p.sigma_systematic)},
         {"sigma_at_declared_scatter", finite_or_null(p.sigma_at_scatter)},
         {"identified", p.identified},
         {"fixed", p.fixed},
         {"at_bound", p.at_bound.empty() ? nlohmann::json() : nlohmann::json(p.at_bound)},
         {"how", p.how},
         {"box", {p.lower, p.upper}}});
  for (std::size_t i = 0; i < r.tests.size(); ++i) {
    const auto& t = r.tests[i];
    nlohmann::json tj = {{"dir", t.name},      {"test", t.test},
                         {"status", t.status}, {"rows_reached", t.rows_reached},
                         {"rows", t.rows},     {"source", tests[i].source},
                         {"e0", tests[i].e0},  {"sigma0_kPa", tests[i].sigma0_kPa}};
    if (!t.boundary.empty()) tj["boundary"] = t.boundary;
    if (!tests[i].specimen.empty()) tj["specimen"] = tests[i].specimen;
    if (tests[i].seed > 0) tj["seed"] = tests[i].seed;
    const auto& sc = tests[i].scales;
    if (sc.replicates > 1) {  // measured over the seeds; otherwise the declared residual_scales
      tj["residual_scales"] = {{"tau_kPa", sc.tau_kPa},
                               {"sigma_n_kPa", sc.sigma_n_kPa},
                               {"e", sc.e},
                               {"seeds", sc.replicates}};
      if (sc.dilatancy_rate > 0.0) tj["residual_scales"]["peak_dilatancy_rate"] = sc.dilatancy_rate;
    }
    for (const auto& c : t.rmse) tj["rmse"][c.column] = c.rmse;
    if (std::isfinite(t.peak_rate_model))
      tj["peak_dilatancy_rate"] = {{"model", t.peak_rate_model},
                                   {"measured", t.peak_rate_measured}};
    j["tests"].push_back(tj);
  }
  j["held_out"] = nlohmann::json::array();
  for (const auto& t : r.held_out) {
    nlohmann::json tj = {{"dir", t.name},
                         {"test", t.test},
                         {"status", t.status},
                         {"rows_reached", t.rows_reached},
                         {"rows", t.rows}};
    if (!t.boundary.empty()) tj["boundary"] = t.boundary;
    for (const auto& c : t.rmse)
      tj["rmse"][c.column] = c.rmse,
      tj["end"][c.column] = {{"model", finite_or_null(c.end_model)},
                             {"measured", finite_or_null(c.end_measured)}};
    if (std::isfinite(t.peak_rate_model))
      tj["peak_dilatancy_rate"] = {{"model", t.peak_rate_model},
                                   {"measured", t.peak_rate_measured}};
    j["held_out"].push_back(tj);
  }
  j["notes"] = r.notes;
  return j;
}

void write_calibration(const CalibrationResult& r, const std::filesystem::path& toml_file,
                       const std::vector<soil_test::SoilTest>& tests,
                       const std::string& command_line, const ParetoFront* front) {
  // the parameter file and its calibration.json together or not at all
  io::StagedDirectory staged(std::filesystem::absolute(toml_file).parent_path());
  io::write_atomically(staged.path() / toml_file.filename(),
                       parameter_file_text(r, tests, command_line));
  io::write_atomically(staged.path() / "calibration.json",
                       calibration_json(r, tests, command_line).dump(2) + "\n");
  if (front) write_front_files(*front, staged.path(), tests, command_line);
  staged.commit_into();
}

}  // namespace iwb::calibration
