#pragma once
// The Dual derivative of a model's closed-form increment (Model::update) against central
// differences in the normal strain, component by component of the state: what every return
// mapping's consistent tangent must pass (mc, mcc).
#include <catch2/catch.hpp>
#include <vector>

#include "models/model.hpp"

namespace iwb::test {

inline void check_increment_derivative(const models::Model& m, const models::StateVector& s,
                                       const std::vector<models::InterfaceStrain>& increments,
                                       double h, double rel, double margin) {
  for (const auto& d0 : increments) {
    models::StateVectorT<Dual> sd = s.cast<Dual>(), out;
    m.update(sd, {make_variable(d0.eps_n), Dual(d0.gamma_x), Dual(d0.gamma_y)}, out);
    models::StateVector up, down;
    m.update(s, {d0.eps_n + h, d0.gamma_x, d0.gamma_y}, up);
    m.update(s, {d0.eps_n - h, d0.gamma_x, d0.gamma_y}, down);
    for (int i = 0; i < s.size(); ++i)
      CHECK(derivative_of(out(i)) ==
            Approx((up(i) - down(i)) / (2 * h)).epsilon(rel).margin(margin));
  }
}

}  // namespace iwb::test
