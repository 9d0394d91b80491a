#include "calibration/calibration_run.hpp"

#include <fmt/core.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <string_view>

#include "calibration/seed_scatter.hpp"
#include "io/output_path.hpp"
#include "io/parameter_file.hpp"
#include "io/run_directory.hpp"

namespace iwb::calibration {

namespace {

namespace fs = std::filesystem;

// How a test's status begins when the model refused its parameters or initial state (simulate).
constexpr std::string_view kRefused = "refused: ";

// The tables of a parameter file but the fitted one: what is held while `fitted` is fitted.
std::map<std::string, models::ParameterValues> held_tables(const std::string& file,
                                                           const std::string& fitted) {
  auto tables = io::load_parameter_file(file);
  tables.erase(fitted);
  return tables;
}

CalibrationOptions options_of(const CalibrationRequest& q) {
  CalibrationOptions opt;
  opt.model = q.model;
  opt.table = q.table;
  if (!q.held_params.empty()) opt.held = held_tables(q.held_params, q.table);
  opt.weights = parse_weights(q.weights);
  opt.fixed = parse_fixed(q.fixed);
  return opt;
}

// A test whose cell localised before it was an element is left out with a note (`left_out`);
// every other defect refuses the calibration.
std::vector<soil_test::SoilTest> read_soil_tests(const std::vector<std::string>& dirs,
                                                 std::vector<std::string>& left_out) {
  std::vector<soil_test::SoilTest> out;
  for (const auto& dir : dirs) try {
      out.push_back(soil_test::read_soil_test(dir));
    } catch (const soil_test::NotAnElement& e) {
      left_out.push_back(fmt::format("{}; left out", e.what()));
    }
  return out;
}

bool refused(const TestFit& t) {
  return t.status.rfind(kRefused, 0) == 0;
}

// The --fix that leaves the model no set it admits the tests with: every test refused at the
// fitted set, and some admitted once that value is freed to the middle of its box (the fit then
// found nothing to move, which is not the tests' fault). Empty when no --fix is to blame.
std::string blocking_fix(const CalibrationResult& r,
                         const std::vector<soil_test::SoilTest>& tests) {
  if (r.tests.empty() || !std::all_of(r.tests.begin(), r.tests.end(), refused)) return "";
  for (const auto& p : r.parameters) {
    if (!p.fixed) continue;
    auto freed = r.inputs();
    freed.tables[r.table][p.key] = 0.5 * (p.lower + p.upper);
    const auto admitted = std::count_if(
        tests.begin(), tests.end(),
        [&](const soil_test::SoilTest& t) { return !refused(test_fit(t, r.model, freed)); });
    if (admitted == 0) continue;
    const auto& first = r.tests.front();
    return fmt::format(
        "--fix {}={:g} leaves no admissible parameter set: the model refuses every soil test at "
        "the fitted set ({}: {}), and admits {} of {} with {} at the middle of its box ({:g}); "
        "fix {} where the other parameters can meet it, or leave it to the fit; no parameter "
        "file written",
        p.key, p.value, first.name, first.status.substr(kRefused.size()), admitted, tests.size(),
        p.key, 0.5 * (p.lower + p.upper), p.key);
  }
  return "";
}

// Nothing is written and the input is refused (exit 2), rather than a file of starting values
// flagged NOT IDENTIFIED (issue 37).
void refuse_if_nothing_identified(const CalibrationResult& r,
                                  const std::vector<soil_test::SoilTest>& tests,
                                  const std::vector<std::string>& runs) {
  if (std::any_of(r.parameters.begin(), r.parameters.end(),
                  [](const auto& p) { return p.identified && !p.fixed; }))
    return;
  if (const auto fix = blocking_fix(r, tests); !fix.empty()) throw NothingIdentified(r, fix);
  const std::string give =
      r.held.empty() ? "give oedometer and simple-shear tests, dense and loose, that reach the "
                       "critical state"
                     : "give tests that move them (the intergranular strain: cyclic shear at two "
                       "amplitudes, CV and CNL)";
  throw NothingIdentified(
      r, fmt::format(
             "{}: the {} soil test(s) given identify none of the {} parameters of [{}] of {} "
             "(each one's sigma exceeds a quarter of its box; the fit is printed above); {}; no "
             "parameter file written",
             fmt::join(runs, ", "), runs.size(), r.parameters.size(), r.table, r.model, give));
}

}  // namespace

models::ParameterValues parse_fixed(const std::vector<std::string>& items) {
  models::ParameterValues out;
  for (const auto& item : items) {
    const auto eq = item.find('=');
    std::size_t used = 0;
    double v = NAN;
    try {
      if (eq != std::string::npos) v = std::stod(item.substr(eq + 1), &used);
    } catch (const std::exception&) {
    }
    if (eq == std::string::npos || used == 0 || used != item.size() - eq - 1 || !std::isfinite(v))
      throw InputError(fmt::format("--fix {}: expected KEY=VALUE with a finite number", item));
    if (!out.emplace(item.substr(0, eq), v).second)
      throw InputError(fmt::format("--fix {}: '{}' fixed twice", item, item.substr(0, eq)));
  }
  return out;
}

CalibrationRun run_calibration(const CalibrationRequest& q,
                               const std::function<void(const std::string&)>& progress) {
  io::require_file_destination(q.out, "-o");  // before minutes of fitting, not after
  // a test twice would weigh double, or be predicted by the fit it took part in
  const std::vector<fs::path> fit(q.runs.begin(), q.runs.end()),
      held(q.held_out.begin(), q.held_out.end());
  io::refuse_repeated_directories("calibrate",
                                  {{fit, "fit", "runs"}, {held, "hold out", "--held-out"}});
  CalibrationOptions opt = options_of(q);
  std::optional<std::pair<ObjectiveGroup, ObjectiveGroup>> pair;
  if (!q.pareto.empty()) pair = parse_pareto_groups(q.pareto);
  if (!pair) opt.progress = progress;  // a front reports per point
  CalibrationRun run;
  std::vector<std::string> left_out;
  run.tests = read_soil_tests(q.runs, left_out);
  // now: a bad one is refused before the fit
  const auto held_out = read_soil_tests(q.held_out, left_out);
  if (run.tests.empty())
    throw InputError(fmt::format("no soil test left to fit: {}", fmt::join(left_out, "; ")));
  measure_seed_scatter(run.tests);
  if (pair) run.front = trace_front(run.tests, opt, pair->first, pair->second, q.points, progress);
  run.result = run.front ? run.front->given().result : calibrate(run.tests, opt);
  refuse_if_nothing_identified(run.result, run.tests, q.runs);
  for (const auto& t : held_out)
    run.result.held_out.push_back(test_fit(t, q.model, run.result.inputs()));
  const auto note_localised = [&run](const std::vector<soil_test::SoilTest>& tests) {
    for (const auto& t : tests)
      if (t.element_until > 0.0)
        run.result.notes.push_back(fmt::format(
            "{}: the periodic cell's shear localised after gamma {:.3g}; its first {} of {} rows "
            "(an element's) are read",
            t.name, t.element_until, t.rows(), t.rows_in_file));
  };
  note_localised(run.tests);
  note_localised(held_out);
  run.result.notes.insert(run.result.notes.end(), left_out.begin(), left_out.end());
  return run;
}

void write_calibration(const CalibrationRun& run, const std::filesystem::path& toml_file,
                       const std::string& command_line) {
  write_calibration(run.result, toml_file, run.tests, command_line,
                    run.front ? &*run.front : nullptr);
}

}  // namespace iwb::calibration
