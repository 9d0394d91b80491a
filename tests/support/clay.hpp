#pragma once
// What the tests of Masin's clay models share: Table 6.1 with a roughness, and the isotropic
// compression slope of a law taken straight from its rate.
#include <cmath>

#include "algebra/ops.hpp"
#include "models/clay/parameters.hpp"
#include "support/fixtures.hpp"

namespace iwb::test {

// Table 6.1: lambda* 0.1, kappa* 0.01, nu 0.2, phi_c 25 deg, N 1.0.
inline models::ModelInputs table_6_1(models::RoughnessScheme scheme, double kappa_r = 1.0) {
  auto in = shipped("table_6_1_evaluation.toml");
  in.roughness = {scheme, kappa_r};
  return in;
}

inline models::ClayParameters clay_parameters(const models::ModelInputs& in) {
  return models::ClayParameters::from(in.tables.at("hypoplastic_clay"), in.source);
}

// e on Table 6.1's isotropic normal compression line at p: ln(1+e) = N - lambda* ln p (p in kPa).
inline double e_on_table_6_1_ncl(double p) {
  return std::exp(1.0 - 0.1 * std::log(p)) - 1.0;
}

// d ln(1+e) / d ln p of an isotropic stretching D = rate * 1 from an isotropic state on the NCL,
// with the model's void-ratio rate (1 + e) tr D (ERRATA 6).
template <class Law>
double isotropic_slope(const typename Law::Constants& c, double p, double rate) {
  using Ops = algebra::Tensor3Ops;
  using Tensor = Ops::Tensor<double>;
  const double e = e_on_table_6_1_ncl(p);
  const Tensor T = -p * Tensor::Identity();
  const Tensor D = rate * Tensor::Identity();
  const Tensor T_rate = Law::template rate<Ops, double>(T, e, D, c);
  return D.trace() / ((-T_rate.trace() / 3.0) / p);
}

}  // namespace iwb::test
