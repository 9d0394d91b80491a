// iwb run --study chapter8 (src/studies/): every case runs, the page holds its figures, and the
// study's numbers obey facts derived from the models' equations, not from the study's code.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>

#include "studies/chapter8_study.hpp"
#include "support/study_run.hpp"

using namespace iwb;
namespace fs = std::filesystem;

TEST_CASE(
    "chapter8 study: every case completes, the page holds every figure, the ends obey the critical "
    "state lines",
    "[studies]") {
  const auto dir = fs::path(IWB_TEST_RUNS_DIR) / "chapter8-study";
  const auto study = studies::chapter8_study();
  const auto json = test::run_study_checked(study, dir);
  REQUIRE(json["claims"].size() == 8);
  CHECK(study.figures.size() == 6);

  // Modified Cam clay: reduced = 3D (the return reads p and the deviator only)
  CHECK(json["claims"][0]["holds"] == true);
  // Under CV e stays at e0 on the isotropic NCL (p_e = 100 kPa); HCE's and Barodesy's critical
  // state lines are both ln(1+e) = N - lambda* ln(2p) (eqs. 6.7 with p_e* = 2p; 8.7), so both end
  // at p = p_e / 2 = 50 kPa; MCC at p0 / 2^((lambda - kappa)/lambda) (65.29 kPa for London's set).
  for (const std::string clay : {"london", "kaolin"})
    for (const std::string m : {"hce", "barodesy-clay", "barodesy-clay3d"}) {
      INFO(clay << " " << m);
      CHECK(test::last_history_value(dir / (clay + "_" + m), "mean_stress_kPa") ==
            Approx(50.0).epsilon(2e-3));
    }
  CHECK(test::last_history_value(dir / "london_mcc", "mean_stress_kPa") ==
        Approx(100.0 / std::pow(2.0, 0.099 / 0.161)).epsilon(1e-3));
}
