// iwb run --study thermo (src/studies/): every case runs, the page holds its figures, and the CV
// ends obey the critical state line of Masin's law at each temperature, derived from its equations.
#include <fmt/core.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>

#include "studies/thermo_study.hpp"
#include "support/study_run.hpp"

using namespace iwb;
namespace fs = std::filesystem;

TEST_CASE(
    "thermo study: every case completes, the page holds every figure, CV ends on the heated "
    "critical state line",
    "[studies]") {
  const auto dir = fs::path(IWB_TEST_RUNS_DIR) / "thermo-study";
  const auto study = studies::thermo_study();
  const auto json = test::run_study_checked(study, dir);
  REQUIRE(json["claims"].size() == 8);
  // Table 6.5's CNL column starts outside its state boundary surface (e0 0.45 at 100 kPa above e
  // 0.42 there, alpha < 0): run as the seed ran it, with the model's warning (issue 60); Soil 1's
  // starts (e0 0.44 at 300 kPa) lie inside
  CHECK_THAT(json["cases"]["cnl_40C_n_t0"].value("warnings", nlohmann::json::array()).dump(),
             Catch::Contains("is taken as given for hcthm, though outside the state boundary"));
  CHECK_FALSE(json["cases"]["cnl_T25"].contains("warnings"));
  CHECK(json["claims"][0]["holds"] == true);  // reduced = 3D
  // Under CV e stays 0.44; Masin's critical state is f_d = 1 on the Matsuoka-Nakai cone, i.e.
  // p = p_e / 2 with p_e = exp[(N(T) - ln(1+e)) / lambda*], N(T) = 0.88 - 0.01 ln(T / 298.15) (Soil
  // 1)
  for (double T_C : {25.0, 40.0, 60.0}) {
    const double N = 0.88 - 0.01 * std::log((T_C + 273.15) / 298.15);
    const double p_cs = 0.5 * std::exp((N - std::log(1.44)) / 0.09);
    const auto run = dir / fmt::format("cv_T{:g}", T_C);
    INFO(T_C << " deg C: p at the end against p_e / 2 = " << p_cs);
    CHECK(test::last_history_value(run, "e") == Approx(0.44).epsilon(1e-12));
    CHECK(test::last_history_value(run, "mean_stress_kPa") == Approx(p_cs).epsilon(0.02));
  }
}
