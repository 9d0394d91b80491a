// The seed scatter of soil tests given with several seeds: which tests are replicates, and the
// residual scales measured over them, against sample standard deviations worked by hand.
#include <catch2/catch.hpp>
#include <cmath>

#include "calibration/calibrate.hpp"
#include "calibration/seed_scatter.hpp"

using namespace iwb;
using soil_test::SoilTest;

namespace {

SoilTest cv_test(int seed, double tau_offset, double e_offset, std::string specimen = "dense") {
  SoilTest t;
  t.kind = soil_test::SoilTestKind::kSimpleShear;
  t.boundary = driver::BoundaryKind::kCV;
  t.sigma0_kPa = 200.0;
  t.source = "dem:liggghts";
  t.specimen = std::move(specimen);
  t.seed = seed;
  t.control = {0.0, 0.1, 0.2};
  t.tau_kPa = {0.0, 400.0 + tau_offset, 800.0 + tau_offset};
  t.sigma_n_kPa = {200.0, 700.0, 1400.0};  // the seeds agree here: the declared floor stands
  t.e = {0.55, 0.55 + e_offset, 0.55 + e_offset};
  return t;
}

}  // namespace

TEST_CASE("seed scatter: replicates weigh their residuals by the sample SD across their seeds",
          "[calibration]") {
  // tau differs by -50/+50 kPa in every row: sample SD sqrt((50^2 + 50^2) / 1) = 70.71 kPa.
  // e differs by 0 / 0.01: SD 0.00707, above the declared 0.002.
  std::vector<SoilTest> tests = {cv_test(1, -50.0, 0.0), cv_test(2, 50.0, 0.01),
                                 cv_test(1, 0.0, 0.0, "loose")};
  calibration::measure_seed_scatter(tests);
  for (int i : {0, 1}) {
    CHECK(tests[i].scales.replicates == 2);
    CHECK(tests[i].scales.tau_kPa == Approx(50.0 * std::sqrt(2.0)).epsilon(1e-12));
    CHECK(tests[i].scales.e == Approx(0.01 / std::sqrt(2.0)).epsilon(1e-12));
    // sigma_n identical across the seeds: never below the declared 0.01 sigma0 = 2 kPa
    CHECK(tests[i].scales.sigma_n_kPa == Approx(calibration::kStressRatioScale * 200.0));
  }
  // another preparation is another design: run once, the declared scales (0 = declared)
  CHECK(tests[2].scales.replicates == 1);
  CHECK(tests[2].scales.tau_kPa == 0.0);
}

TEST_CASE("seed scatter: a test at another stress or boundary is not a replicate",
          "[calibration]") {
  auto a = cv_test(1, 0.0, 0.0), b = cv_test(2, 10.0, 0.0);
  CHECK(calibration::same_design(a, b));
  b.sigma0_kPa = 50.0;
  CHECK_FALSE(calibration::same_design(a, b));
  b.sigma0_kPa = 203.0;  // the stress a servo reached, not another design
  CHECK(calibration::same_design(a, b));
  b = cv_test(2, 10.0, 0.0);
  b.boundary = driver::BoundaryKind::kCNL;
  CHECK_FALSE(calibration::same_design(a, b));
}
