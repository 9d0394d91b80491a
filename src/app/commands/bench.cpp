// `iwb bench element | integrators | dem`: benchmarks that print figures (bench/).
#include <memory>

#include "app/command_list.hpp"
#include "app/commands/commands.hpp"
#include "app/option_checks.hpp"
#include "bench/assess_bench.hpp"
#include "bench/calibration_bench.hpp"
#include "bench/dem_bench.hpp"
#include "bench/element_bench.hpp"
#include "bench/integrator_bench.hpp"
#include "models/registry.hpp"

namespace iwb::app {

void add_bench_element_command(CLI::App& bench, CommandList& commands) {
  auto o = std::make_shared<bench::ElementBenchOptions>();
  auto* element = bench.add_subcommand(
      "element",
      "Rate evaluations per second and the time of a 2000-increment CNL simple shear "
      "at rtol 1e-6, for each model.");
  element->add_option("--repeats", o->repeats, "runs per model; the best is reported")
      ->check(whole_in(1, 1000))
      ->capture_default_str();
  element
      ->add_option("--igs-params", o->igs_params,
                   "parameter set of the -igs models (Table 5.1 has no [intergranular_strain]); "
                   "they are skipped when it is not there")
      ->capture_default_str();
  element
      ->add_option(
          "--models", o->models,
          "only these models, comma-separated (names of `iwb models`); default every model")
      ->delimiter(',');
  commands.add(element, [o](const CommandContext&) {
    for (const auto& m : o->models) models::find_model(m);  // an unknown name refused, exit 2
    bench::run_element_bench(*o);
    return 0;
  });
}

void add_bench_assess_command(CLI::App& bench, CommandList& commands) {
  auto o = std::make_shared<bench::AssessBenchOptions>();
  auto* assess = bench.add_subcommand("assess",
                                      "Throughput of the model assessment: element tests per "
                                      "second on one core and the speed-up on every "
                                      "core, for each interface model of the league (a Latin "
                                      "hypercube of CNL simple shears about its "
                                      "example set).");
  assess->add_option("--tests", o->tests, "element tests per model and thread count")
      ->check(whole_in(10, 100000))
      ->capture_default_str();
  commands.add(assess, [o](const CommandContext&) {
    bench::run_assess_bench(*o);
    return 0;
  });
}

void add_bench_integrators_command(CLI::App& bench, CommandList& commands) {
  auto o = std::make_shared<bench::IntegratorBenchOptions>();
  auto out = std::make_shared<std::string>(o->out.string());
  auto* integrators = bench.add_subcommand(
      "integrators",
      "Integration error against cost (rate evaluations, wall time) of explicit Euler with "
      "1..256 substeps and adaptive rk32/rk54 at rtol 1e-2..1e-8, against rk54 at 1e-10, for "
      "vw3d, hvwe, ahe, ah, hp1d, hvwe-exact, hvwe-igs under CNL, CNS and CV; writes "
      "integrators.csv, integrators.md and pareto_<model>.svg/.png (a few seconds). Error: max "
      "over the path of |x - x_ref| / max |x_ref| for tau and sigma_n, the larger of the two.");
  integrators->add_option("--out,-o", *out, "output directory")
      ->check(output_directory())
      ->capture_default_str();
  commands.add(integrators, [o, out](const CommandContext&) {
    auto opt = *o;
    opt.out = *out;
    bench::run_integrator_bench(opt);
    return 0;
  });
}

void add_bench_dem_command(CLI::App& bench, CommandList& commands) {
  auto o = std::make_shared<bench::DemBenchOptions>();
  auto* dem = bench.add_subcommand(
      "dem",
      "Particle-steps per second of a DEM engine on a scene with 1 and 2 ranks, and the "
      "workbench's own overhead as a share of the run (a few minutes on the default scene).");
  dem->add_option("--engine", o->engine,
                  "DEM engine: liggghts (ranks = MPI ranks) or yade (ranks = OpenMP threads)")
      ->check(CLI::IsMember({"liggghts", "yade"}))
      ->capture_default_str();
  dem->add_option("--scene", o->scene, "scene file")->check(input_file())->capture_default_str();
  dem->add_option("--ranks", o->ranks, "rank counts to measure")
      ->check(whole_in(1, kMaxProcesses))
      ->capture_default_str();
  commands.add(dem, [o](const CommandContext&) {
    bench::run_dem_bench(*o);
    return 0;
  });
}

void add_bench_calibration_command(CLI::App& bench, CommandList& commands) {
  auto o = std::make_shared<bench::CalibrationBenchOptions>();
  auto* calibration = bench.add_subcommand(
      "calibration",
      "CPU and wall seconds of a full calibration: vw3d on five noise-free synthetic Table 5.2 "
      "Hostun soil tests (an oedometer, dense and loose CNL and CV simple shears), the unit "
      "test's workload; evaluations and the largest relative error of a recovered parameter "
      "(about 11 s of CPU on the 2-core machine).");
  calibration->add_option("--repeats", o->repeats, "calibrations; the fastest is reported")
      ->check(whole_in(1, 100))
      ->capture_default_str();
  commands.add(calibration, [o](const CommandContext&) {
    bench::run_calibration_bench(*o);
    return 0;
  });
}

}  // namespace iwb::app
