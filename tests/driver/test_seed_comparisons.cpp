// The seed's qualitative orderings of section 5.7.2 (Table 5.1 sand), asserted where they hold
// and documented where they do not. See src/models/hvwe/README.md for the numbers.
#include <catch2/catch.hpp>

#include "support/fixtures.hpp"

using namespace iwb;
using driver::BoundaryKind;

namespace {
test::Run run(const std::string& model, driver::BoundaryCondition bc, double sigma_n, double e0,
              double K0 = test::kK0Oedometric51) {
  test::ShearSpec s;
  s.model = model;
  s.bc = bc;
  s.sigma_n = sigma_n;
  s.e0 = e0;
  s.K0 = K0;
  s.gamma = 0.3;
  s.increments = 1500;
  s.output_every = 10;
  auto r = test::shear(s);
  REQUIRE(r.result.complete());
  return r;
}
}  // namespace

TEST_CASE("5.7.2 CV (e0 = 0.8): AH gives the highest, HvWE the lowest shear stress", "[seed]") {
  for (double sigma0 : {100.0, 300.0, 500.0}) {
    const double ah = run("ah", {BoundaryKind::kCV, 0.0}, sigma0, 0.80).last().tau_x;
    const double ahe = run("ahe", {BoundaryKind::kCV, 0.0}, sigma0, 0.80).last().tau_x;
    const double hvwe = run("hvwe", {BoundaryKind::kCV, 0.0}, sigma0, 0.80).last().tau_x;
    INFO("sigma_0 = " << sigma0 << ": tau AH " << ah << ", AHE " << ahe << ", HvWE " << hvwe);
    CHECK(ah > ahe);
    CHECK(ahe > hvwe);
  }
}

TEST_CASE("ERRATA 3: from an isotropic start under CV, AHE and HvWE coincide", "[seed]") {
  const auto ahe = run("ahe", {BoundaryKind::kCV, 0.0}, 100.0, 0.80, 1.0);
  const auto hvwe = run("hvwe", {BoundaryKind::kCV, 0.0}, 100.0, 0.80, 1.0);
  for (std::size_t i = 0; i < ahe.result.rows.size(); ++i) {
    CHECK(hvwe.stress(i).tau_x == Approx(ahe.stress(i).tau_x).epsilon(1e-10));
    CHECK(hvwe.stress(i).sigma_n == Approx(ahe.stress(i).sigma_n).epsilon(1e-10));
  }
}

TEST_CASE("5.7.2 CNL (e0 = 0.85): AHE and HvWE share their asymptotic stress, AH's differs",
          "[seed][slow]") {
  // "Asymptotic": at gamma = 0.3 none of them is stationary (AH 0.541, AHE 0.532, HvWE 0.537 at
  // 100 kPa), so the seed's statement is tested at the critical state.
  auto stationary = [](const std::string& m) {
    test::ShearSpec s;
    s.model = m;
    s.e0 = 0.85;
    s.gamma = 15.0;
    s.increments = 3000;
    s.output_every = 100;
    const auto r = test::shear(s);
    REQUIRE(r.result.complete());
    return r.last_ratio();
  };
  const double ah = stationary("ah"), ahe = stationary("ahe"), hvwe = stationary("hvwe");
  INFO("stationary tau/sigma_n: AH " << ah << ", AHE " << ahe << ", HvWE " << hvwe);
  CHECK(ahe == Approx(hvwe).epsilon(1e-4));
  CHECK(ah - hvwe > 0.005);
}

TEST_CASE("5.7.2 CNS (e0 = 0.85, K = 1000 kPa/mm, d_s = 1 mm): HvWE highest only at 50 kPa",
          "[seed]") {
  // The seed reports HvWE with the largest shear stress at all three normal stresses. We find it
  // at 50 kPa, where HvWE dilates twice as much as AH and the spring raises its sigma_n most; at
  // 100 and 150 kPa AH is highest, because its a (eq. 5.21) puts its stationary ratio at
  // tan(phi_c), above the Matsuoka-Nakai simple-shear value HvWE and AHE tend to. Asserted as
  // measured so that a change to either model is noticed (numbers in src/models/hvwe/README.md).
  auto tau = [](const std::string& m, double sigma0) {
    return run(m, {BoundaryKind::kCNS, 1000.0}, sigma0, 0.85).last().tau_x;
  };
  CHECK(tau("hvwe", 50.0) > tau("ah", 50.0));
  CHECK(tau("hvwe", 50.0) > tau("ahe", 50.0));
  for (double sigma0 : {100.0, 150.0}) {
    const double ah = tau("ah", sigma0), hvwe = tau("hvwe", sigma0);
    INFO("sigma_0 = " << sigma0 << ": tau AH " << ah << ", HvWE " << hvwe);
    CHECK(ah > hvwe);
  }
}
