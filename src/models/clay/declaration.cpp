#include "models/clay/declaration.hpp"

#include "models/hypoplastic/family.hpp"

namespace iwb::models {

ModelDeclaration clay_declaration(const std::vector<std::string>& stress_components, bool interface_model,
                                  int listing_order, RoughnessScheme scheme, std::vector<DiagnosticSpec> own_diagnostics) {
  auto d = rate_form_declaration(stress_components, InPlaneStart::kFreeK0, listing_order, "hypoplastic_clay");
  d.initial[1].doc = "initial void ratio, on or below the normal compression line";
  d.diagnostics = {{"mean_stress_kPa", "kPa", "mean stress -tr T / 3", DiagnosticRole::kMeanStress},
                   {"p_e_kPa", "kPa", "Hvorslev's equivalent pressure p_e* (eq. 6.7)", DiagnosticRole::kEquivalentPressure}};
  for (auto& own : own_diagnostics) d.diagnostics.push_back(std::move(own));
  if (interface_model) {
    d.roughness = {{scheme}, scheme, false, KappaFromAngle::kAngleRatio};
    d.fit = interface_fit_parameters();
  }
  d.example_parameters = "table_6_1_evaluation.toml";
  d.example_start = {{"sigma_n_kPa", 100.0}, {"e0", 0.70}};  // OCR 1.12 at K0 = 1 - sin 25 deg (Table 6.1)
  return d;
}

}  // namespace iwb::models
