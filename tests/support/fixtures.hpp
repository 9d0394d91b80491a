#pragma once
// Shared test fixtures: the seed's parameter sets and short ways to run element tests.
#include <cmath>
#include <memory>
#include <string>

#include "driver/element_test.hpp"
#include "models/registry.hpp"

namespace iwb::test {

inline models::ModelInputs table_5_1(double kappa_r = 1.0,
                                     models::RoughnessScheme scheme = models::RoughnessScheme::kGutjahr) {
  models::ModelInputs in;
  in.tables["hypoplastic"] = {{"phi_c_deg", 28.0}, {"hs_kPa", 2.0e6}, {"n", 0.29},
                              {"ed0", 0.61},       {"ec0", 0.96},     {"ei0", 1.09},
                              {"alpha", 0.13},     {"beta", 2.0}};
  in.source = "seed Table 5.1";
  in.roughness = {scheme, kappa_r};
  return in;
}

inline models::ModelInputs table_5_2_hostun() {
  models::ModelInputs in;
  in.tables["hypoplastic"] = {{"phi_c_deg", 31.0}, {"hs_kPa", 1.0e6}, {"n", 0.29},
                              {"ed0", 0.61},       {"ec0", 0.96},     {"ei0", 1.09},
                              {"alpha", 0.13},     {"beta", 2.0}};
  in.source = "seed Table 5.2 Hostun";
  return in;
}

// data/params/table_5_2_toyoura.toml (Table 5.2 differs from 5.3 in alpha: 0.25, not 0.18).
inline models::ModelInputs table_5_2_toyoura() {
  models::ModelInputs in;
  in.tables["hypoplastic"] = {{"phi_c_deg", 30.0}, {"hs_kPa", 2.6e6}, {"n", 0.27},
                              {"ed0", 0.61},       {"ec0", 0.98},     {"ei0", 1.1},
                              {"alpha", 0.25},     {"beta", 1.0}};
  in.source = "seed Table 5.2 Toyoura";
  return in;
}

// Table 5.3's intergranular-strain columns for Toyoura sand (Arnold 2008).
inline models::ParameterValues table_5_3_toyoura_igs() {
  return {{"R", 1e-4}, {"m_R", 5.0}, {"m_T", 2.0}, {"beta_r", 0.12}, {"chi", 1.0}};
}

// Seed Table 5.3, Toyoura sand, both column groups (seed 5.7.5).
inline models::ModelInputs table_5_3_toyoura() {
  models::ModelInputs in;
  in.tables["hypoplastic"] = {{"phi_c_deg", 30.0}, {"hs_kPa", 2.6e6}, {"n", 0.27},
                              {"ed0", 0.61},       {"ec0", 0.98},     {"ei0", 1.1},
                              {"alpha", 0.18},     {"beta", 1.0}};
  in.tables["intergranular_strain"] = table_5_3_toyoura_igs();
  in.source = "seed Table 5.3 Toyoura";
  return in;
}

// Seed Table 5.3, homo-gravel (Zhang and Zhang 2006), both column groups
// (data/params/table_5_3_homo_gravel.toml): h_s = 20 MPa and m_R = 7 make its reversals the
// stiffest of the seed's sets.
inline models::ModelInputs table_5_3_homo_gravel() {
  models::ModelInputs in;
  in.tables["hypoplastic"] = {{"phi_c_deg", 44.0}, {"hs_kPa", 2.0e7}, {"n", 0.18},
                              {"ed0", 0.26},       {"ec0", 0.45},     {"ei0", 0.5},
                              {"alpha", 0.1},      {"beta", 2.0}};
  in.tables["intergranular_strain"] = {
      {"R", 1e-4}, {"m_R", 7.0}, {"m_T", 2.0}, {"beta_r", 0.12}, {"chi", 0.75}};
  in.source = "seed Table 5.3 homo-gravel";
  return in;
}

inline bool has_intergranular_strain(const std::string& model) {
  return model.size() > 4 && model.compare(model.size() - 4, 4, "-igs") == 0;
}

inline const double kPhiC51 = 28.0 * M_PI / 180.0;
inline const double kK0Oedometric51 = 1.0 - std::sin(kPhiC51);

// `in`, with Table 5.3's Toyoura intergranular-strain columns added for the -igs models when it
// has none (the seed gives them only with Table 5.3).
inline std::unique_ptr<models::Model> make(const std::string& name,
                                           const models::ModelInputs& in = table_5_1()) {
  models::ModelInputs with = in;
  if (has_intergranular_strain(name) && !with.tables.count("intergranular_strain"))
    with.tables["intergranular_strain"] = table_5_3_toyoura_igs();
  return models::find_model(name).make(with);
}

struct Run {
  std::unique_ptr<models::Model> model;
  driver::ElementTestResult result;

  models::InterfaceStress stress(std::size_t row) const { return model->stress(result.rows.at(row).state); }
  models::InterfaceStress last() const { return stress(result.rows.size() - 1); }
  double ratio(std::size_t row) const { const auto s = stress(row); return s.tau_x / s.sigma_n; }
  double last_ratio() const { return ratio(result.rows.size() - 1); }
  double peak_ratio() const {
    double p = 0.0;
    for (std::size_t i = 0; i < result.rows.size(); ++i) p = std::max(p, ratio(i));
    return p;
  }
  double last_e() const { return model->void_ratio(result.rows.back().state); }
  double diagnostic(const std::string& name, std::size_t row) const {
    for (const auto& d : model->diagnostics(result.rows.at(row).state))
      if (d.name == name) return d.value;
    return NAN;
  }
};

struct ShearSpec {
  std::string model = "hvwe";
  driver::BoundaryCondition bc{driver::BoundaryKind::kCNL, 0.0};
  double sigma_n = 100.0;
  double e0 = 0.80;
  double K0 = kK0Oedometric51;
  double gamma = 0.3;
  int increments = 1500;
  int output_every = 1;
  driver::ShearDirection direction = driver::ShearDirection::kX;
  models::ModelInputs inputs = table_5_1();
  driver::RunSettings settings{};
};

inline Run shear(const ShearSpec& s) {
  Run r{make(s.model, s.inputs), {}};
  const auto s0 = r.model->initial_state({s.sigma_n, s.K0, s.e0});
  auto settings = s.settings;
  settings.output_every = s.output_every;
  r.result = driver::run_element_test(
      *r.model, s0, driver::monotonic_path(s.bc, s.gamma, s.direction, s.increments), settings);
  return r;
}

}  // namespace iwb::test
