#pragma once
// Shared test fixtures: the seed's parameter sets and short ways to run element tests.
#include <cmath>
#include <memory>
#include <string>

#include "driver/element_test.hpp"
#include "io/parameter_file.hpp"
#include "models/registry.hpp"

namespace iwb::test {

// A set of data/params/ (the tests run from the source tree): the seed's tables live there only.
inline models::ModelInputs shipped(const std::string& file) {
  const std::string path = "data/params/" + file;
  return {io::load_parameter_file(path), path, {}};
}

inline models::ModelInputs table_5_1(
    double kappa_r = 1.0, models::RoughnessScheme scheme = models::RoughnessScheme::kGutjahr) {
  auto in = shipped("table_5_1_evaluation.toml");
  in.roughness = {scheme, kappa_r};
  return in;
}

inline models::ModelInputs table_5_2_hostun() {
  return shipped("table_5_2_hostun.toml");
}

// Table 5.2 differs from 5.3 in alpha: 0.25, not 0.18.
inline models::ModelInputs table_5_2_toyoura() {
  return shipped("table_5_2_toyoura.toml");
}

// Seed Table 5.3, Toyoura sand (Arnold 2008), both column groups (seed 5.7.5).
inline models::ModelInputs table_5_3_toyoura() {
  return shipped("table_5_3_toyoura.toml");
}

// Table 5.3's intergranular-strain columns for Toyoura sand.
inline models::ParameterValues table_5_3_toyoura_igs() {
  return table_5_3_toyoura().tables.at("intergranular_strain");
}

// Seed Table 5.3, homo-gravel (Zhang and Zhang 2006), both column groups: h_s = 20 MPa and
// m_R = 7 make its reversals the stiffest of the seed's sets.
inline models::ModelInputs table_5_3_homo_gravel() {
  return shipped("table_5_3_homo_gravel.toml");
}

// The sand family: Bauer's limiting void ratios among its diagnostics. The tests written on Table
// 5.1 run these; the other families bring their own sets (their declared example).
inline bool is_sand(const models::ModelSpec& spec) {
  for (const auto& d : spec.declaration.diagnostics)
    if (d.role == models::DiagnosticRole::kMinVoidRatio) return true;
  return false;
}

// Whether the model declares an initial intergranular strain (the -igs models).
inline bool has_intergranular_strain(const std::string& model) {
  return models::find_initial_input(models::find_model(model).declaration.initial, "delta") !=
         nullptr;
}

inline const double kPhiC51 = 28.0 * M_PI / 180.0;
inline const double kK0Oedometric51 = 1.0 - std::sin(kPhiC51);

// `in`, with Table 5.3's Toyoura intergranular-strain columns added for the -igs models when it
// has none (the seed gives them only with Table 5.3), and any other table the model reads but `in`
// lacks from its declared example set: a merge of shipped files, not a set of its own.
inline models::ModelInputs with_model_tables(const std::string& name, models::ModelInputs in) {
  if (has_intergranular_strain(name) && !in.tables.count("intergranular_strain"))
    in.tables["intergranular_strain"] = table_5_3_toyoura_igs();
  // a table of a model's own beside the soil's (hvwe-rd's [roughness_dilatancy]): its example's
  const auto& spec = models::find_model(name);
  for (const auto* table : spec.tables)
    if (!in.tables.count(table->name)) {
      const auto example = shipped(spec.declaration.example_parameters);
      if (const auto it = example.tables.find(table->name); it != example.tables.end())
        in.tables[table->name] = it->second;
    }
  return in;
}

inline std::unique_ptr<models::Model> make(const std::string& name,
                                           const models::ModelInputs& in = table_5_1()) {
  return models::find_model(name).make(with_model_tables(name, in));
}

struct Run {
  std::unique_ptr<models::Model> model;
  driver::ElementTestResult result;

  models::InterfaceStress stress(std::size_t row) const {
    return model->stress(result.rows.at(row).state);
  }
  models::InterfaceStress last() const { return stress(result.rows.size() - 1); }
  double ratio(std::size_t row) const {
    const auto s = stress(row);
    return s.tau_x / s.sigma_n;
  }
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

// Monotonic shear of `model` on a shipped set from 100 kPa, integrated at rtol 1e-10 (far below the
// 1e-6 the tests compare an independent implementation's numbers at), required to complete.
inline Run tight_shear(const std::string& model, const std::string& set,
                       driver::BoundaryCondition bc, double gamma, int increments,
                       double e0 = 0.8) {
  ShearSpec s;
  s.model = model;
  s.inputs = shipped(set);
  s.bc = bc;
  s.e0 = e0;
  s.gamma = gamma;
  s.increments = increments;
  s.settings.integrator.rtol = 1e-10;
  auto r = shear(s);
  REQUIRE(r.result.complete());
  return r;
}

}  // namespace iwb::test
