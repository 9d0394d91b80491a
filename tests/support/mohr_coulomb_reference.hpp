#pragma once
// A reference "run" made by a model whose answers are known: the league's and the plan's tests
// calibrate models to it (issue 17).
#include <catch2/catch.hpp>

#include "comparison/replay/replay.hpp"
#include "support/fixtures.hpp"

namespace iwb::test {

// Mohr-Coulomb at phi_i 30 deg, psi 8 deg, E 20 MPa, d_s 10 mm, under CNL at 50 kPa to 10 mm: the
// DEM's place taken by a model whose answers are known.
inline comparison::DemRun mohr_coulomb_reference() {
  comparison::DemRun dem;
  dem.dir = "mohr-coulomb-reference";
  dem.boundary = driver::BoundaryKind::kCNL;
  dem.sigma_n0_kPa = 50.0, dem.d50_mm = 2.0, dem.R_n = 0.5, dem.K_kPa_per_mm = 0.0;
  for (int i = 0; i <= 500; ++i) {
    dem.t_s.push_back(0.01 * i), dem.u_x_mm.push_back(0.02 * i), dem.sigma_n_kPa.push_back(50.0);
    dem.tau_kPa.push_back(0.0), dem.u_n_mm.push_back(0.0), dem.e_band.push_back(0.6);
  }
  auto in = shipped("table_4_3_mohr_coulomb.toml");
  in.tables["mohr_coulomb"]["phi_i_deg"] = 30.0, in.tables["mohr_coulomb"]["psi_deg"] = 8.0;
  in.tables["mohr_coulomb"]["E_kPa"] = 2e4;
  const auto r = comparison::replay(dem, {"truth", "mc", in, 10.0});
  REQUIRE(r.status == "complete");
  dem.tau_kPa = r.tau_kPa, dem.u_n_mm = r.u_n_mm;
  return dem;
}

}  // namespace iwb::test
