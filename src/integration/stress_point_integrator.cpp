#include "integration/stress_point_integrator.hpp"

namespace iwb::integration {

std::string IntegratorSettings::describe() const {
  if (scheme == Scheme::kExplicitEuler) return fmt::format("explicit Euler, {} substeps", substeps);
  return fmt::format("adaptive {}, rtol {:g}", pair, rtol);
}

IntegrationCounters& IntegrationCounters::operator+=(const IntegrationCounters& o) {
  rate_evaluations += o.rate_evaluations;
  accepted_substeps += o.accepted_substeps;
  rejected_substeps += o.rejected_substeps;
  domain_cutbacks += o.domain_cutbacks;
  return *this;
}

}  // namespace iwb::integration
