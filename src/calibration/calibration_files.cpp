// Writing a calibration: the parameter file in the data/params format and calibration.json.
#include <fmt/core.h>

#include <cmath>

#include "calibration/calibrate.hpp"
#include "io/output_path.hpp"
#include "io/run_directory.hpp"

namespace iwb::calibration {

namespace {

std::string sigma_text(const ParameterEstimate& p) {
  return std::isfinite(p.sigma) ? fmt::format("+- {:.3g}", p.sigma) : "+- undefined";
}

std::string parameter_file(const CalibrationResult& r, const std::vector<SoilTest>& tests,
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
      "# Joint fit s^2 = {:.3g} (residuals in units of {} sigma0 for stresses, {} for e, or of the "
      "seed scatter of tests run with several seeds where larger: calibration.json).\n",
      r.s2, kStressRatioScale, kVoidRatioScale);
  s += "# Per parameter: value +- one sigma (Gauss-Newton), and how it was set. See "
       "calibration.json.\n";
  s += fmt::format("# Command: {}\n[hypoplastic]\n", command_line);
  for (const auto& p : r.parameters)
    s += fmt::format("{} = {:.9g}  # {} ({})\n", p.key, p.value, sigma_text(p), p.how);
  return s;
}

nlohmann::json finite_or_null(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json();
}

nlohmann::json calibration_json(const CalibrationResult& r, const std::vector<SoilTest>& tests,
                                const std::string& command_line) {
  nlohmann::json j;
  j["kind"] = "calibration";
  j["model"] = r.model;
  j["command_line"] = command_line;
  j["finished"] = io::utc_timestamp();
  j["wall_seconds"] = r.seconds;
  j["evaluations"] = r.evaluations;
  j["converged"] = r.converged;
  j["s2_scatter_units"] = r.s2;
  j["residual_scales"] = {{"stress_over_sigma0", kStressRatioScale},
                          {"void_ratio", kVoidRatioScale}};
  for (const auto& p : r.parameters)
    j["parameters"].push_back({{"key", p.key},
                               {"value", p.value},
                               {"sigma", finite_or_null(p.sigma)},
                               {"sigma_statistical", finite_or_null(p.sigma_statistical)},
                               {"sigma_systematic", finite_or_null(p.sigma_systematic)},
                               {"sigma_at_declared_scatter", finite_or_null(p.sigma_at_scatter)},
                               {"identified", p.identified},
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
    if (sc.replicates > 1)  // measured over the seeds; otherwise the declared residual_scales
      tj["residual_scales"] = {{"tau_kPa", sc.tau_kPa},
                               {"sigma_n_kPa", sc.sigma_n_kPa},
                               {"e", sc.e},
                               {"seeds", sc.replicates}};
    for (const auto& c : t.rmse) tj["rmse"][c.column] = c.rmse;
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
    j["held_out"].push_back(tj);
  }
  j["notes"] = r.notes;
  return j;
}

}  // namespace

void write_calibration(const CalibrationResult& r, const std::filesystem::path& toml_file,
                       const std::vector<SoilTest>& tests, const std::string& command_line) {
  // the parameter file and its calibration.json together or not at all
  io::StagedDirectory staged(std::filesystem::absolute(toml_file).parent_path());
  io::write_atomically(staged.path() / toml_file.filename(),
                       parameter_file(r, tests, command_line));
  io::write_atomically(staged.path() / "calibration.json",
                       calibration_json(r, tests, command_line).dump(2) + "\n");
  staged.commit_into();
}

}  // namespace iwb::calibration
