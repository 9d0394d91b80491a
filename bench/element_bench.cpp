#include "bench/element_bench.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <map>
#include <set>

#include "common/subprocess.hpp"
#include "driver/element_test.hpp"
#include "io/parameter_file.hpp"
#include "io/parameter_sets.hpp"
#include "models/registry.hpp"

namespace iwb::bench {

namespace {

using Clock = std::chrono::steady_clock;

// The set every model that it can drive runs on: seed Table 5.1, as the sand family declares it.
constexpr const char* kBaseSet = "table_5_1_evaluation.toml";

// Nanoseconds per rate evaluation on `s`, measured over at least `min_seconds`.
template <class S>
double ns_per_rate(const models::Model& m, const models::StateVector& s, double min_seconds) {
  const models::StateVectorT<S> state = s.cast<S>();
  models::InterfaceStrainT<S> d{S(-2e-5), S(1e-4), S(0.0)};
  if constexpr (!std::is_same_v<S, double>) d.eps_n = make_variable(-2e-5);
  models::StateVectorT<S> r;
  long n = 0;
  double sink = 0.0;
  const auto t0 = Clock::now();
  double elapsed = 0.0;
  while (elapsed < min_seconds) {
    for (int i = 0; i < 1000; ++i, ++n) {
      m.rate(state, d, r);
      sink += value_of(r(0));
    }
    elapsed = std::chrono::duration<double>(Clock::now() - t0).count();
  }
  if (sink == 42.0) fmt::print("");  // keeps the loop from being optimised away
  return 1e9 * elapsed / double(n);
}

// Parameter tables of a shipped set, for the models Table 5.1 cannot drive (the -igs models need
// [intergranular_strain]); no tables when the file is not there, so those models are skipped.
models::ModelInputs parameter_set(const std::filesystem::path& file) {
  models::ModelInputs in;
  in.source = file.string();
  if (std::filesystem::exists(file))
    in.tables = io::load_parameter_file(file.string());
  else
    in.source += " (not found)";
  return in;
}

// The tables `spec` reads that `in` does not hold, as "[a], [b]"; empty when it holds them all.
std::string missing_tables(const models::ModelInputs& in, const models::ModelSpec& spec) {
  std::string missing;
  for (const auto* t : spec.tables)
    if (!in.tables.count(t->name)) missing += (missing.empty() ? "[" : ", [") + t->name + "]";
  return missing;
}

// One row of the table: the 2000-increment test (best of opt.repeats) and the rate cost.
// Whether `spec` reads none of the tables of `in`: a model of another family (clay against sand).
bool other_family(const models::ModelInputs& in, const models::ModelSpec& spec) {
  for (const auto* t : spec.tables)
    if (in.tables.count(t->name)) return false;
  return true;
}

// The start of the sand rows: Table 5.1's e0 = 0.80 at 100 kPa.
const std::map<std::string, double> kSandStart{{"sigma_n_kPa", 100.0}, {"e0", 0.80}};

nlohmann::json bench_model(const models::ModelSpec& spec, const models::ModelInputs& in,
                           const std::string& label, const ElementBenchOptions& opt,
                           const std::map<std::string, double>& start = kSandStart) {
  const auto model = spec.make(in);
  auto initial = models::offer(spec, in, {});
  for (const auto& [key, value] : start) models::set_initial_input(initial, key, value);
  const auto s0 = model->initial_state(initial);
  driver::RunSettings rs;
  rs.integrator.rtol = 1e-6;
  rs.output_every = 2000;
  const auto path = driver::monotonic_path({driver::BoundaryKind::kCNL, 0.0}, 0.2,
                                           driver::ShearDirection::kX, 2000);
  double best = INFINITY;
  driver::ElementTestResult result;
  for (int i = 0; i < opt.repeats; ++i) {
    const auto t0 = Clock::now();
    result = driver::run_element_test(*model, s0, path, rs);
    best = std::min(best, std::chrono::duration<double>(Clock::now() - t0).count());
  }
  const auto& sheared = result.rows.back().state;
  const double ns_double = ns_per_rate<double>(*model, sheared, 0.2);
  const double ns_dual = ns_per_rate<Dual>(*model, sheared, 0.2);
  fmt::print("{:<16} {:>9.2f} {:>11} {:>9} {:>12.0f} {:>12.0f} {:>13.3g}{}\n", label, 1e3 * best,
             result.counters.rate_evaluations, result.newton_iterations, ns_double, ns_dual,
             1e9 / ns_double, result.complete() ? "" : "  (" + result.status + ")");
  return {{"model", spec.name},
          {"parameters", in.source},
          {"test_ms", 1e3 * best},
          {"rate_evaluations", result.counters.rate_evaluations},
          {"newton_iterations", result.newton_iterations},
          {"ns_per_rate_double", ns_double},
          {"ns_per_rate_dual", ns_dual},
          {"status", result.status}};
}

// Start-up of iwb as a whole process (issue 37): `iwb --help`, from fork to exit, best and median
// of kStartupRuns; a callgrind of it put 82 % of its instructions in the dynamic loader, relocating
// the shared libraries every command loads (VTK's among them), which this counts.
constexpr int kStartupRuns = 20;

std::size_t shared_libraries_loaded() {
  std::ifstream maps("/proc/self/maps");
  std::set<std::string> libraries;
  for (std::string line; std::getline(maps, line);)
    if (const auto at = line.find('/');
        at != std::string::npos && line.find(".so", at) != std::string::npos)
      libraries.insert(line.substr(at));
  return libraries.size();
}

nlohmann::json startup_figure() {
  std::vector<double> ms;
  for (int i = 0; i < kStartupRuns; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    run_process({"/proc/self/exe", "--help"}, ".", [](const std::string&) { return true; });
    ms.push_back(1e3 *
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  std::sort(ms.begin(), ms.end());
  const std::size_t libraries = shared_libraries_loaded();
  fmt::print(
      "\nstart-up: `iwb --help` as a whole process, best {:.1f} ms, median {:.1f} ms of {} runs; "
      "{} shared libraries loaded (goal: under 5 ms)\n",
      ms.front(), ms[ms.size() / 2], kStartupRuns, libraries);
  return {{"startup_best_ms", ms.front()},
          {"startup_median_ms", ms[ms.size() / 2]},
          {"shared_libraries", libraries}};
}

}  // namespace

nlohmann::json run_element_bench(const ElementBenchOptions& opt) {
  const auto base = io::shipped_inputs(kBaseSet);
  const auto extra = parameter_set(opt.igs_params);
  nlohmann::json out = nlohmann::json::array();
  fmt::print(
      "iwb bench element: Table 5.1 sand, e0 = 0.80, sigma_n = 100 kPa, CNL simple shear,\n"
      "2000 increments of d gamma = 1e-4, adaptive rk32, rtol 1e-6, Newton to 1e-8; "
      "best of {} runs, one core\n\n",
      opt.repeats);
  fmt::print("{:<16} {:>9} {:>11} {:>9} {:>12} {:>12} {:>13}\n", "model", "test ms", "rate evals",
             "Newton", "ns/eval dbl", "ns/eval dual", "evals/s (dbl)");
  std::vector<std::string> notes;
  bool used_extra = false, used_declared = false;
  for (const auto& spec : models::model_registry()) {
    if (!opt.models.empty() &&
        std::find(opt.models.begin(), opt.models.end(), spec.name) == opt.models.end())
      continue;
    const auto& declared = spec.declaration.example_parameters;
    if (missing_tables(base, spec).empty()) {
      out.push_back(bench_model(spec, base, spec.name, opt));
    } else if (missing_tables(extra, spec).empty()) {
      out.push_back(bench_model(spec, extra, spec.name + " *", opt));
      used_extra = true;
    } else if (other_family(base, spec) && !declared.empty() &&
               !spec.declaration.example_start.empty()) {
      // a model of another family (clay): its own declared example set and start
      out.push_back(bench_model(spec, io::shipped_inputs(declared), spec.name + " +", opt,
                                spec.declaration.example_start));
      used_declared = true;
    } else {
      notes.push_back(fmt::format("skipped {}: needs {}, in neither {} nor {}", spec.name,
                                  missing_tables(base, spec), base.source, extra.source));
    }
  }
  if (used_extra)
    fmt::print("\n* parameters of {} at the same start: Table 5.1 has no [intergranular_strain]\n",
               extra.source);
  if (used_declared)
    fmt::print(
        "+ the model's own declared example set and start (iwb models; e.g. Table 6.1 for hcc, "
        "hce)\n");
  if (!notes.empty()) fmt::print("\n");
  for (const auto& n : notes) fmt::print("{} (pass --igs-params FILE)\n", n);
  fmt::print("\ntarget: the whole test under 10 ms on one core (issue 2)\n");
  out.push_back(startup_figure());
  return out;
}

}  // namespace iwb::bench
