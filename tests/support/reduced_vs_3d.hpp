#pragma once
// Reduced = 3D in simple shear (seed 5.4, ERRATA 3 and 13): the interface form of a model and its
// 3D form run the same path, and their stresses agree to `rel` at every 50th row.
#include <catch2/catch.hpp>
#include <string>

#include "support/fixtures.hpp"

namespace iwb::test {

inline void check_reduced_equals_3d(ShearSpec s, const std::string& reduced_model,
                                    const std::string& full_model, double rel = 1e-10) {
  s.model = reduced_model;
  const auto reduced = shear(s);
  s.model = full_model;
  const auto full = shear(s);
  REQUIRE(reduced.result.complete());
  REQUIRE(full.result.complete());
  for (std::size_t i = 0; i < full.result.rows.size(); i += 50) {
    const auto a = reduced.stress(i), b = full.stress(i);
    CHECK(a.sigma_n == Approx(b.sigma_n).epsilon(rel));
    CHECK(*a.sigma_p == Approx(*b.sigma_p).epsilon(rel));
    CHECK(a.tau_x == Approx(b.tau_x).epsilon(rel).margin(rel));
  }
}

// A clay model's shear in simple shear, Table 6.1 from 100 kPa at K0 = 0.6, e0 = 0.70 (OCR ~1.1).
inline ShearSpec table_6_1_shear(driver::BoundaryKind kind) {
  ShearSpec s;
  s.inputs = shipped("table_6_1_evaluation.toml");
  s.bc = {kind, 0.0};
  s.K0 = 0.6;
  s.e0 = 0.70;
  s.gamma = 0.2;
  s.increments = 1000;
  return s;
}

}  // namespace iwb::test
