#include "bench/assess_bench.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <thread>

#include "assessment/element_sensitivity.hpp"
#include "io/parameter_sets.hpp"
#include "models/registry.hpp"

namespace iwb::bench {

namespace {

std::vector<const models::ModelSpec*> league_models() {
  std::vector<const models::ModelSpec*> out;
  for (const auto& name : models::ranked_interface_models(true))
    out.push_back(&models::find_model(name));
  return out;
}

// Seconds for `tests` element tests of the model on `threads` threads (0: every core), and how many
// failed.
std::pair<double, long> timed(const models::ModelSpec& spec,
                              const assessment::ElementSensitivityOptions& base, int threads) {
  auto o = base;
  o.threads = threads;
  const auto dists = assessment::varied_parameters(spec, o.inputs, 0.05);
  const auto t0 = std::chrono::steady_clock::now();
  const auto r = assessment::element_uncertainty(spec, o, dists);
  return {std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), r.failed};
}

}  // namespace

nlohmann::json run_assess_bench(const AssessBenchOptions& opt) {
  const int cores = int(std::max(1u, std::thread::hardware_concurrency()));
  fmt::print(
      "Assessment throughput: {} monotonic CNL element tests (gamma 0.1, 200 increments) per "
      "model, COV 0.05 "
      "about the example set; one thread, then {} cores.\n\n"
      "| model | tests/s on one core | s (1 thread) | s ({} cores) | speed-up | failed "
      "|\n|---|---|---|---|---|---|\n",
      opt.tests, cores, cores);
  nlohmann::json out = nlohmann::json::array();
  for (const auto* spec : league_models()) {
    assessment::ElementSensitivityOptions o;
    o.inputs = io::shipped_inputs(spec->declaration.example_parameters);
    const auto& start = spec->declaration.example_start;
    o.sigma_n_kPa = start.count("sigma_n_kPa") ? start.at("sigma_n_kPa") : 100.0;
    o.e0 = start.count("e0") ? start.at("e0") : 0.0;
    o.samples = opt.tests;
    const auto [one, failed] = timed(*spec, o, 1);
    const auto [all, failed_all] = timed(*spec, o, 0);
    fmt::print("| {} | {:.0f} | {:.2f} | {:.2f} | {:.2f} | {} |\n", spec->name, opt.tests / one,
               one, all, one / all, failed);
    out.push_back({{"model", spec->name},
                   {"tests_per_s_per_core", opt.tests / one},
                   {"s_one_thread", one},
                   {"s_all_cores", all},
                   {"speed_up", one / all},
                   {"cores", cores},
                   {"failed", failed + failed_all}});
  }
  return out;
}

}  // namespace iwb::bench
