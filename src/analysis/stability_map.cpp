#include "analysis/stability_map.hpp"

#include <fmt/core.h>

#include <chrono>

#include "analysis/stability_output.hpp"
#include "common/errors.hpp"
#include "io/output_directory.hpp"
#include "io/parameter_file.hpp"

namespace iwb::analysis {

namespace {
models::ModelInputs inputs_from(const std::string& params) {
  if (!std::filesystem::is_regular_file(params))
    throw InputError(fmt::format("parameter file '{}' does not exist (see data/params/)", params));
  models::ModelInputs in;
  in.tables = io::load_parameter_file(params);
  in.source = params;
  return in;
}
}  // namespace

StabilityMap run_stability_map(const StabilityMapOptions& opt) {
  const auto& spec = models::find_model(opt.model);  // InputError listing the models
  const auto inputs = inputs_from(opt.params);
  spec.make(inputs);  // refuses a parameter file the model cannot use, before the sweep
  auto sweep = opt.full ? StabilitySweep::full() : StabilitySweep::reduced();
  if (opt.budget_seconds > 0.0) sweep.budget_seconds = opt.budget_seconds;
  StabilityMap map;
  map.dir = opt.out.empty() ? std::filesystem::path("runs") / ("stability-" + opt.model)
                            : std::filesystem::path(opt.out);
  opt.starting(fmt::format("{} with {} ({} form, {} points) -> {}", opt.model, opt.params,
                           opt.full ? "full" : "reduced", sweep.points(spec).size(),
                           map.dir.string()));
  // refused before the sweep's minutes (the map's files enter the directory's ledger together)
  io::require_output_directory(map.dir, kStabilityOutput, false);
  const auto t0 = std::chrono::steady_clock::now();
  map.results = run_stability_sweep(spec, inputs, sweep);
  map.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  write_stability_map(map.results, sweep,
                      {opt.model, opt.params, opt.full ? "full" : "reduced", density_axis_of(spec)},
                      map.dir);
  return map;
}

}  // namespace iwb::analysis
