// The two roughness schemes of seed 6.2.4 on both clay laws (src/models/clay/parameters.hpp,
// poisson_ratio_on_wall). Facts from eqs. 6.23-6.25 alone: with X = (1 + nu)/(1 - 2 nu), eq. 6.25
// is nu_r = (X_r - 1)/(2 X_r + 1) with X_r = kappa_r X, i.e. (1 + nu_r)/(1 - 2 nu_r) = kappa_r X.
// f_s (eq. 6.9) carries (1 - 2 nu)/(1 + nu), so Stutz & Masin's scheme divides the shear stiffness
// of f_s L by kappa_r and leaves the bulk stiffness f_s (1 + nu)/(1 - 2 nu) alone. At an isotropic
// stress the asymptotic direction d is isotropic in both laws (HCC: 3 T* + (eta^2 - M^2) p/3 1 with
// T* = 0; HCE: -T^* + 1 [...]), so the shear component of the rate under a pure shear stretching
// is f_s (L : D)_12 alone: its ratio between the schemes is exactly 1/kappa_r, and Arnold & Herle's
// scheme (phi_c kappa_r in the critical state only) does not move it at all.
#include <catch2/catch.hpp>
#include <cmath>

#include "models/registry.hpp"
#include "support/clay.hpp"

namespace iwb {

namespace {

// d tau_x / d gamma_x at an isotropic start (K0 = 1) of OCR 2, sigma_n 100 kPa.
double shear_tangent(const std::string& model, models::RoughnessScheme scheme, double kappa_r) {
  const auto in = test::table_6_1(scheme, kappa_r);
  const auto m = models::find_model(model).make(in);
  const auto s = m->initial_state({100.0, 1.0, NAN, std::nullopt, {{"OCR", 2.0}}});
  models::StateVector ds(s.size());
  m->rate(s, {0.0, 1e-3, 0.0}, ds);
  return m->stress(ds).tau_x / 1e-3;
}

}  // namespace

TEST_CASE(
    "clay roughness: Stutz & Masin divide the initial shear stiffness by kappa_r, Arnold & Herle "
    "keep it",
    "[models][clay]") {
  using models::RoughnessScheme;
  for (const std::string model : {"hcc", "hce", "hcc3d", "hce3d"}) {
    INFO(model);
    for (double k : {0.75, 0.5}) {
      INFO("kappa_r " << k);
      const double ah = shear_tangent(model, RoughnessScheme::kArnoldHerle, k);
      const double sm = shear_tangent(model, RoughnessScheme::kStutzMasin, k);
      CHECK(ah == Approx(shear_tangent(model, RoughnessScheme::kArnoldHerle, 1.0)).epsilon(1e-12));
      CHECK(sm / ah == Approx(1.0 / k).epsilon(1e-12));
    }
    CHECK(shear_tangent(model, RoughnessScheme::kStutzMasin, 1.0) ==
          Approx(shear_tangent(model, RoughnessScheme::kArnoldHerle, 1.0)).epsilon(1e-12));
  }
}

}  // namespace iwb
