#include "models/registry.hpp"

#include <cmath>
#include <fmt/core.h>

#include "common/errors.hpp"

namespace iwb::models {

ModelSpec vw3d_spec();
ModelSpec ah_spec();
ModelSpec ahe_spec();
ModelSpec hvwe_spec();
ModelSpec hvwe_exact_spec();
ModelSpec hp1d_spec();
ModelSpec vw3d_igs_spec();
ModelSpec ahe_igs_spec();
ModelSpec hvwe_igs_spec();
ModelSpec hvwe_exact_igs_spec();

const std::vector<ModelSpec>& model_registry() {
  static const std::vector<ModelSpec> specs{vw3d_spec(), ah_spec(),         ahe_spec(),
                                            hvwe_spec(), hvwe_exact_spec(), hp1d_spec(),
                                            vw3d_igs_spec(), ahe_igs_spec(), hvwe_igs_spec(),
                                            hvwe_exact_igs_spec()};
  return specs;
}

const ModelSpec& find_model(const std::string& name) {
  std::string known;
  for (const auto& s : model_registry()) {
    if (s.name == name) return s;
    known += (known.empty() ? "" : ", ") + s.name;
  }
  throw InputError(fmt::format("unknown model '{}'; known models: {}", name, known));
}

double critical_friction_angle(const ModelInputs& inputs) {
  for (const auto& [name, values] : inputs.tables)
    if (const auto it = values.find("phi_c_deg"); it != values.end()) return it->second * M_PI / 180.0;
  return NAN;
}

double oedometric_K0(const ModelInputs& inputs) { return 1.0 - std::sin(critical_friction_angle(inputs)); }

const ParameterValues& require_table(const ModelInputs& inputs, const std::string& name) {
  const auto it = inputs.tables.find(name);
  if (it == inputs.tables.end())
    throw InputError(fmt::format("{}: no table [{}] of parameters", inputs.source, name));
  return it->second;
}

}  // namespace iwb::models
