#include "models/clay/declaration.hpp"

#include "models/hypoplastic/family.hpp"

namespace iwb::models {

ModelDeclaration clay_declaration(const std::vector<std::string>& stress_components,
                                  bool interface_model, int listing_order, RoughnessScheme scheme,
                                  std::vector<DiagnosticSpec> own_diagnostics,
                                  const std::string& table) {
  auto d = rate_form_declaration(stress_components, InPlaneStart::kFreeK0, listing_order, table);
  // The density as e0 or as an overconsolidation ratio: a clay is usually known by its OCR
  d.initial[1].doc = "initial void ratio, on or below the normal compression line (or give OCR)";
  d.initial[1].need = InitialInputSpec::Need::kOneOf;
  d.initial[1].group = "density";
  InitialInputSpec ocr{
      "OCR", "-",
      "overconsolidation ratio at the start: p_e* over its value on the ASBS at the "
      "initial stress (1: normally consolidated), which sets e0"};
  ocr.need = InitialInputSpec::Need::kOneOf;
  ocr.group = "density";
  ocr.range = closed(1.0, 1000.0);
  d.initial.insert(d.initial.begin() + 2, ocr);
  d.diagnostics = {{"mean_stress_kPa", "kPa", "mean stress -tr T / 3", DiagnosticRole::kMeanStress},
                   {"p_e_kPa", "kPa", "Hvorslev's equivalent pressure p_e* (eq. 6.7)",
                    DiagnosticRole::kEquivalentPressure}};
  for (auto& own : own_diagnostics) d.diagnostics.push_back(std::move(own));
  if (interface_model) {
    // both clay schemes (6.2.4) for both laws; the default is each model's own
    d.roughness = {{RoughnessScheme::kArnoldHerle, RoughnessScheme::kStutzMasin},
                   scheme,
                   false,
                   KappaFromAngle::kAngleRatio};
    d.fit = interface_fit_parameters();
  }
  d.example_parameters = "table_6_1_evaluation.toml";
  d.example_start = {{"sigma_n_kPa", 100.0},
                     {"e0", 0.70}};  // OCR 1.12 at K0 = 1 - sin 25 deg (Table 6.1)
  return d;
}

}  // namespace iwb::models
