#pragma once
// What Masin's clay models declare alike (src/models/README.md 8.2): the rate-form layout and
// start of the hypoplastic family over [hypoplastic_clay] (K0 = 1 - sin phi_c of that table), the
// mean stress and Hvorslev's p_e* among the diagnostics, kappa_r from an angle ratio (eq. 6.21)
// and no R_n (eq. 5.35 is Gutjahr's, for sand), Table 6.1 as the example.
#include <string>
#include <vector>

#include "models/declaration.hpp"

namespace iwb::models {

// `table` holds phi_c_deg (the default K0): Masin's [hypoplastic_clay], or Barodesy's own.
ModelDeclaration clay_declaration(const std::vector<std::string>& stress_components,
                                  bool interface_model, int listing_order, RoughnessScheme scheme,
                                  std::vector<DiagnosticSpec> own_diagnostics,
                                  const std::string& table = "hypoplastic_clay");

}  // namespace iwb::models
