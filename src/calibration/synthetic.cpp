#include "calibration/synthetic.hpp"

#include <fmt/core.h>

#include <cmath>

#include "common/errors.hpp"
#include "io/parameter_file.hpp"
#include "io/run_directory.hpp"
#include "models/hypoplastic/von_wolffersdorff.hpp"

namespace iwb::calibration {

namespace {

std::vector<double> geometric(double from, double to, int n) {
  std::vector<double> v;
  for (int i = 0; i <= n; ++i) v.push_back(from * std::pow(to / from, double(i) / n));
  return v;
}

// 0 -> +A -> -A -> 0, `cycles` times, `rows` rows a quarter cycle.
std::vector<double> cyclic_control(const SyntheticSpec& s) {
  std::vector<double> g{0.0};
  const int quarters = 4 * s.cycles;
  for (int q = 0; q < quarters; ++q) {
    // quarter q runs from the phase q to q + 1; the displacement is A times a triangle wave
    for (int i = 1; i <= s.rows; ++i) {
      const double phase = q + double(i) / s.rows;  // in quarter cycles
      const double within = std::fmod(phase, 4.0);
      const double wave = within <= 1.0 ? within : within <= 3.0 ? 2.0 - within : within - 4.0;
      g.push_back(s.gamma_amplitude * wave);
    }
  }
  return g;
}

std::vector<double> control_of(const SyntheticSpec& s) {
  if (s.kind == soil_test::SoilTestKind::kCyclicShear) return cyclic_control(s);
  if (s.kind == soil_test::SoilTestKind::kSimpleShear) {
    std::vector<double> g;
    for (int i = 0; i <= s.rows; ++i) g.push_back(s.gamma_max * i / s.rows);
    return g;
  }
  if (!(s.sigma_max_kPa > s.sigma0_kPa))
    throw InputError(fmt::format("oedometer: sigma_max = {:g} kPa must exceed sigma_v0 = {:g} kPa",
                                 s.sigma_max_kPa, s.sigma0_kPa));
  auto v = geometric(s.sigma0_kPa, s.sigma_max_kPa, s.rows);
  if (s.sigma_end_kPa < s.sigma_max_kPa) {
    const auto down = geometric(s.sigma_max_kPa, s.sigma_end_kPa, std::max(2, s.rows / 2));
    v.insert(v.end(), down.begin() + 1, down.end());
  }
  return v;
}

// Bauer's e_c at the initial mean pressure -tr T = sigma0 (1 + 2 K0): a medium-dense start.
double default_e0(const soil_test::SoilTest& t, const std::string& model,
                  const models::ModelInputs& inputs) {
  const auto p = models::HypoplasticParameters::from(models::require_table(inputs, "hypoplastic"),
                                                     inputs.source);
  const double pressure = t.sigma0_kPa * (1.0 + 2.0 * initial_K0(t, model, inputs));
  return models::limiting_void_ratios(pressure, p).e_c;
}

}  // namespace

soil_test::SoilTest synthesise(const SyntheticSpec& spec, const models::ModelInputs& inputs) {
  soil_test::SoilTest t;
  t.kind = spec.kind;
  t.boundary = spec.boundary;
  t.sigma0_kPa = spec.sigma0_kPa;
  t.K0 = models::offer(models::find_model(spec.model), inputs, {}).K0;
  t.control = control_of(spec);
  t.e0 = spec.e0 ? *spec.e0 : default_e0(t, spec.model, inputs);
  t.source = "synthetic:" + spec.model;
  for (const auto& [table, values] : inputs.tables)
    for (const auto& [key, value] : values) t.source_parameters[table][key] = value;
  const Simulated s = simulate(t, spec.model, inputs);
  if (s.status != "complete" || s.rows() != t.rows())
    throw InputError(fmt::format("synthetic {} ({}, e0 = {:g}, sigma0 = {:g} kPa) with {}: {}",
                                 to_string(t.kind), driver::to_string(t.boundary), t.e0,
                                 t.sigma0_kPa, inputs.source, s.status));
  t.e = s.e;
  t.eps_v = s.eps_v;
  t.tau_kPa = s.tau_kPa;
  t.sigma_n_kPa = s.sigma_n_kPa;
  return t;
}

soil_test::SoilTest write_synthetic_test(const SyntheticSpec& spec, const std::string& params,
                                         const std::string& out, bool force,
                                         const std::string& command_line) {
  models::ModelInputs in;
  in.tables = io::load_parameter_file(params);
  in.source = params;
  auto t = synthesise(spec, in);
  t.name = out;
  soil_test::write_soil_test(
      t, out, force,
      {{"command_line", command_line},
       {"workbench", {{"name", "iwb"}}},
       {"inputs",
        {{"parameters", {{"source", params}, {"sha256", io::sha256_hex(io::read_file(params))}}}}},
       {"finished", io::utc_timestamp()}});
  return t;
}

}  // namespace iwb::calibration
