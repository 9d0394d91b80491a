#pragma once
// `iwb bench integrators`: accuracy against cost of the stress-point integration (issue 3, item
// 4). For each model and CNL, CNS, CV, a monotonic simple shear is run with explicit Euler at
// n = 1, 2, 4, ..., 256 substeps per increment and with the adaptive pairs rk32 and rk54 at
// rtol = 1e-2 ... 1e-8, and compared with a converged reference (rk54 at rtol 1e-10).
//
// Error (the norm): for tau and sigma_n, the largest deviation from the reference over every
// increment of the path divided by the largest magnitude of the reference over the path (a max
// norm relative to the path's scale, so tau = 0 at the start does not divide by zero); the error
// of a run is the larger of the two. Cost: rate evaluations (Newton's dual-number evaluations
// included) and wall time. Prints figures; asserts nothing.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "driver/control.hpp"
#include "integration/stress_point_integrator.hpp"
#include "models/registry.hpp"

namespace iwb::bench {

struct TradeoffSetting {
  std::string scheme;  // "euler", "rk32", "rk54"
  double parameter;    // substeps (euler) or rtol
  integration::IntegratorSettings settings;
};

// Euler with 1, 2, 4, ..., max_substeps; rk32 and rk54 at 1e-2, 1e-3, ..., min_rtol.
std::vector<TradeoffSetting> tradeoff_settings(int max_substeps = 256, double min_rtol = 1e-8);

struct TradeoffPath {
  double sigma_n_kPa = 100.0;
  double e0 =
      0.75;  // medium dense for Table 5.3 Toyoura at 100 kPa: (e_d, e_c, e_i) = (0.57, 0.92, 1.03)
  double gamma = 0.1;
  int increments = 20;        // 5e-3 per increment: coarse enough that the adaptive tolerances bind
  double cns_K_kPa = 1000.0;  // per unit normal strain
};

struct TradeoffPoint {
  std::string model, boundary, scheme;
  double parameter = 0.0;
  double error_tau = 0.0, error_sigma_n = 0.0, error = 0.0;  // see the header comment
  long rate_evaluations = 0;
  double seconds = 0.0;
  std::string status;
  bool on_front = false;  // not dominated in (rate evaluations, error) within model and boundary
};

// The settings against the reference for one model and boundary condition.
std::vector<TradeoffPoint> run_tradeoff(const models::ModelSpec& spec,
                                        const models::ModelInputs& inputs, driver::BoundaryKind bc,
                                        const TradeoffPath& path,
                                        const std::vector<TradeoffSetting>& settings);

struct IntegratorBenchOptions {
  std::filesystem::path out = "runs/bench-integrators";
  std::vector<std::string> models{"vw3d", "hvwe", "ahe", "ah", "hp1d", "hvwe-exact", "hvwe-igs"};
};

// Prints the table and the cheapest settings for 1e-3 and 1e-6; writes integrators.csv,
// integrators.md and pareto_<model>.svg/.png into options.out.
nlohmann::json run_integrator_bench(const IntegratorBenchOptions& options);

}  // namespace iwb::bench
