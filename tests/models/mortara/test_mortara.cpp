// Mortara's (2003) interface model, monotonic part (src/models/mortara, seed 3.3.3): the facts of
// its reconstruction (docs/derivations/mortara_2003.md) and the numbers of an independent
// implementation of the same equations (Python, RK4 in u_x with 1e-4 mm steps, the h = 1 switch
// located by bisection, written outside the repository by a helper from the equations alone).
// Table 4.5, 100 kPa, d_s 1 mm (u_x = gamma in mm).
#include <catch2/catch.hpp>
#include <cmath>

#include "models/registry.hpp"
#include "support/fixtures.hpp"

using namespace iwb;
using driver::BoundaryKind;

namespace {

test::Run shear(driver::BoundaryCondition bc, double gamma, int increments) {
  return test::tight_shear("mortara", "table_4_5_mortara.toml", bc, gamma, increments);
}

}  // namespace

TEST_CASE(
    "mortara: under CNL the peak is alpha_p sigma_n^beta, then tau falls towards alpha_c "
    "sigma_n^beta",
    "[models][mortara]") {
  const auto r = shear({BoundaryKind::kCNL, 0.0}, 1.0, 2000);
  CHECK(r.last().tau_x == Approx(86.860804).epsilon(1e-6));  // u_x = 1 mm
  CHECK(r.result.rows.back().eps_n ==
        Approx(0.13159439).epsilon(1e-5));  // u_n = 0.1316 mm opening at d_s 1 mm
  const auto far = shear({BoundaryKind::kCNL, 0.0}, 3.0, 3000);
  double peak = 0.0;
  for (std::size_t i = 0; i < far.result.rows.size(); ++i) {
    peak = std::max(peak, far.stress(i).tau_x);
    CHECK(std::abs(far.diagnostic("f_yield", i)) < 1e-6 * 100.0);
  }
  CHECK(peak ==
        Approx(2.6 * std::pow(1e5, 0.905) / 1000.0).epsilon(1e-4));  // 87.091014 kPa at h = 1
  CHECK(far.last().tau_x == Approx(72.852129).epsilon(1e-6));
  CHECK(far.result.rows.back().eps_n ==
        Approx(0.33975027).epsilon(1e-5));  // the softening branch's dilatancy
  CHECK(far.last().tau_x > 2.15 * std::pow(1e5, 0.905) / 1000.0);  // approaching tau_c from above
}

TEST_CASE("mortara: CV and CNS against the independent implementation at u_x = 1 mm",
          "[models][mortara]") {
  const auto cv = shear({BoundaryKind::kCV, 0.0}, 1.0, 2000);
  CHECK(cv.last().tau_x == Approx(496.52656).epsilon(1e-6));
  CHECK(cv.last().sigma_n == Approx(752.37259).epsilon(1e-6));
  const auto cns = shear({BoundaryKind::kCNS, 1000.0}, 1.0,
                         2000);  // 1000 kPa per unit strain = 1000 kPa/mm at d_s 1 mm
  CHECK(cns.last().tau_x == Approx(167.86323).epsilon(1e-6));
  CHECK(cns.last().sigma_n == Approx(209.38007).epsilon(1e-6));
  CHECK(cns.result.rows.back().eps_n == Approx(0.10938007).epsilon(1e-5));  // u_n opening, mm
  // past the peak (h = 1 at 1.32 mm): the softening branch of the flow rule
  const auto cns3 = shear({BoundaryKind::kCNS, 1000.0}, 3.0, 3000);
  CHECK(cns3.last().tau_x == Approx(298.70543).epsilon(1e-6));
  CHECK(cns3.last().sigma_n == Approx(434.25334).epsilon(1e-6));
}
