#include "bench/calibration_bench.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>

#include "calibration/calibrate.hpp"
#include "calibration/synthetic.hpp"
#include "io/parameter_file.hpp"

namespace iwb::bench {

soil_test::SoilTest synthetic_soil_test(soil_test::SoilTestKind kind, driver::BoundaryKind bc,
                                        double e0, const std::string& name,
                                        const models::ModelInputs& truth, double sigma_max_kPa) {
  calibration::SyntheticSpec s;
  s.kind = kind;
  s.boundary = bc;
  s.e0 = e0;
  if (kind == soil_test::SoilTestKind::kOedometer) {
    s.sigma0_kPa = 10.0, s.sigma_max_kPa = sigma_max_kPa, s.sigma_end_kPa = 100.0, s.rows = 30;
  } else {
    s.gamma_max = 2.0, s.rows = 40;
  }
  auto t = calibration::synthesise(s, truth);
  t.name = name;
  return t;
}

std::vector<soil_test::SoilTest> hostun_soil_tests(const models::ModelInputs& truth) {
  using driver::BoundaryKind;
  using soil_test::SoilTestKind;
  return {
      synthetic_soil_test(SoilTestKind::kOedometer, BoundaryKind::kCNL, 0.85, "oedometer", truth),
      synthetic_soil_test(SoilTestKind::kSimpleShear, BoundaryKind::kCNL, 0.65, "dense CNL", truth),
      synthetic_soil_test(SoilTestKind::kSimpleShear, BoundaryKind::kCNL, 0.90, "loose CNL", truth),
      synthetic_soil_test(SoilTestKind::kSimpleShear, BoundaryKind::kCV, 0.70, "dense CV", truth),
      synthetic_soil_test(SoilTestKind::kSimpleShear, BoundaryKind::kCV, 0.88, "loose CV", truth)};
}

nlohmann::json run_calibration_bench(const CalibrationBenchOptions& o) {
  const std::string path = "data/params/table_5_2_hostun.toml";
  const models::ModelInputs truth{io::load_parameter_file(path), path, {}};
  const auto tests = hostun_soil_tests(truth);
  const auto& table = truth.tables.at("hypoplastic");
  double best_cpu = INFINITY, best_wall = INFINITY, worst_error = 0.0;
  long evaluations = 0;
  for (int k = 0; k < o.repeats; ++k) {
    const std::clock_t cpu0 = std::clock();
    const auto wall0 = std::chrono::steady_clock::now();
    const auto r = calibration::calibrate(tests);
    const double cpu = double(std::clock() - cpu0) / CLOCKS_PER_SEC;
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
    best_cpu = std::min(best_cpu, cpu), best_wall = std::min(best_wall, wall);
    evaluations = long(r.evaluations);
    for (const auto& p : r.parameters)
      worst_error = std::max(worst_error, std::abs(p.value / table.at(p.key) - 1.0));
  }
  fmt::print(
      "calibration of vw3d on 5 synthetic Table 5.2 Hostun soil tests (best of {}): CPU {:.1f} s, "
      "wall {:.1f} s, {} evaluations; largest relative error of a parameter {:.2g}\n",
      o.repeats, best_cpu, best_wall, evaluations, worst_error);
  return {{"cpu_seconds", best_cpu},
          {"wall_seconds", best_wall},
          {"evaluations", evaluations},
          {"largest_relative_error", worst_error}};
}

}  // namespace iwb::bench
