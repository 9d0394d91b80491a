#include "element/element_run.hpp"

#include <fmt/core.h>

#include <chrono>

#include "common/errors.hpp"
#include "element/history_csv.hpp"
#include "io/directory_lock.hpp"
#include "io/run_directory.hpp"

namespace iwb::element {

namespace {

nlohmann::json counters_json(const driver::ElementTestResult& r) {
  return {{"increments", r.increments},
          {"newton_iterations", r.newton_iterations},
          {"rate_evaluations", r.counters.rate_evaluations},
          {"accepted_substeps", r.counters.accepted_substeps},
          {"rejected_substeps", r.counters.rejected_substeps},
          {"domain_cutbacks", r.counters.domain_cutbacks}};
}

}  // namespace

ElementRunOutcome run_element_to_directory(const ElementTestSpec& spec,
                                           const ElementRunOptions& opt) {
  const auto model = models::find_model(spec.model).make(spec.inputs);
  const auto initial =
      [&] {  // not admissible: an InputError naming the file and its table (issue 37)
        try {
          return model->initial_state(spec.initial);
        } catch (const InputError& e) {
          throw InputError(fmt::format("{}: table [initial]: {}", spec.source, e.what()));
        }
      }();
  try {  // bad input is refused before the run directory is touched
    driver::check_path(*model, spec.path);
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}: key 'path.direction' = \"y\": {}", spec.source, e.what()));
  }

  ElementRunOutcome outcome;
  auto& m = outcome.manifest;
  m["kind"] = "element-test";
  m["workbench"] = {{"name", "iwb"}, {"version", IWB_VERSION}};
  m["command_line"] = opt.command_line;
  m["conventions"] = {
      {"signs",
       "compression positive; u_n > 0 is dilation; tau has the sign of the shear displacement"},
      {"units", "kPa, mm, degrees; strains dimensionless"}};
  m["inputs"] = {{"test", {{"source", spec.source}, {"sha256", io::sha256_hex(opt.input_text)}}}};
  if (spec.parameter_source != "inline")
    m["inputs"]["parameters"] = {{"source", spec.parameter_source},
                                 {"sha256", io::sha256_hex(io::read_file(spec.parameter_source))}};
  m["test"] = spec.resolved;
  m["warnings"] = spec.warnings;
  for (const auto& w : model->initial_warnings(spec.initial))  // a start taken though doubted
    m["warnings"].push_back(fmt::format("{}: table [initial]: {}", spec.source, w));
  m["state_variables"] = model->state_names();
  m["files"] =
      nlohmann::json::array();  // each file as it is written, so the list never names a missing one
  m["started"] = io::utc_timestamp();
  m["status"] = "running";
  const io::OutputKind kind{"element-test"};
  io::require_new_run_directory(opt.out, kind, opt.force);  // before the lock touches it
  const auto lock = io::DirectoryLock::take(opt.out, opt.command_line);  // until the run is written
  io::prepare_run_directory(opt.out, kind, opt.force);
  io::write_manifest(opt.out, m);

  driver::RunSettings settings = spec.settings;
  settings.interrupt = opt.interrupt;
  const auto t0 = std::chrono::steady_clock::now();
  try {
    outcome.result = driver::run_element_test(*model, initial, spec.path, settings);
  } catch (const std::exception& e) {  // the manifest must not keep saying "running"
    m["finished"] = io::utc_timestamp();
    m["status"] = fmt::format("failed: {}", e.what());
    io::write_manifest(opt.out, m);
    throw;
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  io::write_atomically(opt.out / "history.csv",
                       history_csv(*model, spec.zone, outcome.result.rows, spec.direction));
  m["files"].push_back("history.csv");
  if (!outcome.result.cycles.empty()) {
    io::write_atomically(opt.out / "cycles.csv", cycles_csv(spec.zone, outcome.result.cycles));
    m["files"].push_back("cycles.csv");
  }
  m["finished"] = io::utc_timestamp();
  m["wall_seconds"] = seconds;
  m["counters"] = counters_json(outcome.result);
  m["status"] = outcome.result.status;
  io::write_manifest(opt.out, m);
  return outcome;
}

}  // namespace iwb::element
