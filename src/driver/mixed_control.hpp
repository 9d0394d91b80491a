#pragma once
// Mixed control of one increment: the shear increment is prescribed, the normal strain increment
// x is found so that the normal row a d(sigma_n) + b x = c holds at the end of the increment.
//
// Newton (default): on the integrated increment, with the exact derivative of the discrete
// integration obtained by running it on dual numbers; converges quadratically.
// Closed form (seed appendix C, ERRATA item 18): for explicit Euler, each substep's row is a
// quadratic in x after squaring; solved per substep, the root checked by substitution. It needs
// a rate of the form L:D + N||D||, whose L and N rows it reads off four rate evaluations, so it
// knows no model internals either.
#include <array>
#include <vector>

#include "driver/control.hpp"
#include "integration/stress_point_integrator.hpp"
#include "models/model.hpp"

namespace iwb::driver {

enum class MixedControlMethod { kNewton, kClosedForm };

struct MixedControlSettings {
  MixedControlMethod method = MixedControlMethod::kNewton;
  double tolerance = 1e-8;  // relative residual of the normal row (CONVENTIONS.md default)
  int max_iterations = 30;
};

struct IncrementRequest {
  double gamma_x = 0.0;
  double gamma_y = 0.0;
  NormalControlRow row;
  double eps_n_guess = 0.0;
  std::array<double, models::kExternalSlots> external{};  // dT, ds, dt over the increment

  bool has_external() const { return external != std::array<double, models::kExternalSlots>{}; }
  template <class S>
  models::InterfaceStrainT<S> strain(const S& eps_n) const {
    models::InterfaceStrainT<S> d{eps_n, S(gamma_x), S(gamma_y)};
    for (int i = 0; i < models::kExternalSlots; ++i)
      d.external[std::size_t(i)] = S(external[std::size_t(i)]);
    return d;
  }
};

struct IncrementSolution {
  models::StateVector state;  // state at the end of the increment (not yet committed)
  double eps_n = 0.0;         // normal strain increment found
  int iterations = 0;
  std::vector<double> residuals;  // relative residual before each Newton update
  integration::IntegrationCounters counters;
};

IncrementSolution solve_increment(const models::Model& model, const models::StateVector& committed,
                                  const IncrementRequest& request,
                                  const integration::IntegratorSettings& integrator,
                                  const MixedControlSettings& settings, double& first_step);

// x satisfying the row for one explicit Euler step from `state` (appendix C); also the Newton
// predictor. Throws ConvergenceError if no root satisfies the unsquared equation.
double closed_form_normal_strain(const models::Model& model, const models::StateVector& state,
                                 double gamma_x, double gamma_y, const NormalControlRow& row,
                                 integration::IntegrationCounters& counters);

}  // namespace iwb::driver
