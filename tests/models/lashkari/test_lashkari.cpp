// Lashkari's (2013) interface model (src/models/lashkari, seed 3.3.5): the facts of its
// reconstruction (docs/derivations/lashkari_2013.md), derived from the equations, and the numbers
// of an independent implementation of the same equations (Python, RK4 with d gamma = 1e-4, written
// outside the repository by a helper from the equations alone).
#include <catch2/catch.hpp>
#include <cmath>

#include "models/registry.hpp"
#include "support/fixtures.hpp"

using namespace iwb;
using driver::BoundaryKind;

namespace {

test::Run shear(driver::BoundaryCondition bc, double e0, double gamma, int increments) {
  return test::tight_shear("lashkari", "table_4_7_lashkari.toml", bc, gamma, increments, e0);
}

// The row at gamma = g (the path's increments land on it).
std::size_t row_at(const test::Run& r, double g) {
  for (std::size_t i = 0; i < r.result.rows.size(); ++i)
    if (std::abs(r.result.rows[i].gamma_x - g) < 1e-9) return i;
  FAIL("no row at gamma " << g);
  return 0;
}

}  // namespace

TEST_CASE("lashkari: the initial shear stiffness is K_s0 sqrt(sigma_n / p_ref)",
          "[models][lashkari]") {
  // at eta = 0 nothing is plastic; the plastic share grows with eta, i.e. with gamma: 3.6e-3 of the
  // secant at gamma 1e-4, below 1e-6 at 1e-8
  const auto r = shear({BoundaryKind::kCNL, 0.0}, 0.70, 1e-8, 1);
  CHECK(r.last().tau_x / 1e-8 ==
        Approx(3600.0).epsilon(1e-6));  // Table 4.7's K_s0 at sigma_n = p_ref
}

TEST_CASE(
    "lashkari: dense under CNL peaks at eta = M^b, then softens to M with e on the critical state "
    "line",
    "[models][lashkari]") {
  const auto r = shear({BoundaryKind::kCNL, 0.0}, 0.70, 1.0, 4000);
  // the independent implementation: tau 68.8565993 kPa and e 0.811314348 at gamma 1, peak
  // 0.8145086214
  const auto k = row_at(r, 1.0);
  CHECK(r.stress(k).tau_x == Approx(68.8565993).epsilon(1e-6));
  CHECK(r.result.rows[k].state(3) == Approx(0.811314348).epsilon(1e-6));
  CHECK(r.peak_ratio() == Approx(0.8145086214).epsilon(1e-5));
  // the yield condition while loading, and the peak where the stress ratio meets M^b
  std::size_t peak = 0;
  for (std::size_t i = 1; i < r.result.rows.size(); ++i) {
    CHECK(std::abs(r.diagnostic("f_yield", i)) < 1e-6 * r.stress(i).sigma_n);
    if (r.ratio(i) > r.ratio(peak)) peak = i;
  }
  CHECK(r.ratio(peak) == Approx(r.diagnostic("M_b", peak)).epsilon(1e-3));
  // the critical state: tau/sigma_n -> M, e -> e_c0 - lambda ln(sigma_n0 / p_ref) = 0.85
  const auto far = shear({BoundaryKind::kCNL, 0.0}, 0.70, 20.0, 4000);
  CHECK(far.last_ratio() == Approx(0.64).epsilon(1e-6));
  CHECK(far.result.rows.back().state(3) == Approx(0.85).epsilon(1e-6));
}

TEST_CASE(
    "lashkari: loose under CV loses normal stress, dense under CNS gains it (independent numbers "
    "at gamma 1)",
    "[models][lashkari]") {
  const auto cv = shear({BoundaryKind::kCV, 0.0}, 0.90, 1.0, 2000);
  CHECK(cv.last().tau_x == Approx(24.1707729).epsilon(1e-6));
  CHECK(cv.last().sigma_n == Approx(38.0949005).epsilon(1e-6));
  CHECK(cv.result.rows.back().state(3) == Approx(0.90).epsilon(1e-14));  // CV: e constant
  const auto cns = shear({BoundaryKind::kCNS, 2000.0}, 0.70, 1.0, 2000);
  CHECK(cns.last().tau_x == Approx(129.900884).epsilon(1e-6));
  CHECK(cns.last().sigma_n == Approx(185.778034).epsilon(1e-6));
  CHECK(cns.result.rows.back().state(3) == Approx(0.7744974711).epsilon(1e-6));
}
