#pragma once
// A synthetic cyclic simple-shear soil test of vw3d-igs (two cycles, 12 rows, e0 = 0.75), made from
// a known parameter set (Table 5.3 Toyoura unless given): the targets the intergranular strain's
// calibration must find that set again from.
#include <fmt/core.h>

#include "calibration/synthetic.hpp"
#include "support/fixtures.hpp"

namespace iwb::test {

inline soil_test::SoilTest cyclic_soil_test(
    driver::BoundaryKind bc, double amplitude,
    const models::ModelInputs& truth = table_5_3_toyoura()) {
  calibration::SyntheticSpec s;
  s.model = "vw3d-igs";
  s.kind = soil_test::SoilTestKind::kCyclicShear;
  s.boundary = bc;
  s.e0 = 0.75;
  s.gamma_amplitude = amplitude;
  s.cycles = 2;
  s.rows = 12;
  auto t = calibration::synthesise(s, truth);
  t.name = fmt::format("{} A {:g}", driver::to_string(bc), amplitude);
  return t;
}

}  // namespace iwb::test
