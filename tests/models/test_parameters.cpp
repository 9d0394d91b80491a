// Parameter tables: validation names the source, the key, the value and the allowed range.
#include <catch2/catch.hpp>

#include "common/errors.hpp"
#include "models/hypoplastic/parameters.hpp"
#include "support/fixtures.hpp"

using namespace iwb;

namespace {
models::ParameterValues values() {
  return test::table_5_1().tables.at("hypoplastic");
}
std::string message(const models::ParameterValues& v) {
  try {
    models::HypoplasticParameters::from(v, "sand.toml [hypoplastic]");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST_CASE("a valid set loads, angles in radians", "[parameters]") {
  const auto p = models::HypoplasticParameters::from(values(), "x");
  CHECK(p.phi_c == Approx(28.0 * M_PI / 180.0));
  CHECK(p.hs == 2.0e6);
}

TEST_CASE("missing, unknown and out-of-range keys are named with value and range", "[parameters]") {
  auto v = values();
  v.erase("n");
  CHECK_THAT(message(v), Catch::Contains("sand.toml [hypoplastic]") &&
                             Catch::Contains("missing key 'n'") && Catch::Contains("(0, 1)"));
  v = values();
  v["phi_c"] = 30;
  CHECK_THAT(message(v), Catch::Contains("unknown key 'phi_c'") && Catch::Contains("phi_c_deg"));
  v = values();
  v["phi_c_deg"] = 95;
  CHECK_THAT(message(v), Catch::Contains("'phi_c_deg' = 95 is out of range; allowed (0, 90) deg"));
  v = values();
  v["hs_kPa"] = -1;
  CHECK_THAT(message(v), Catch::Contains("'hs_kPa' = -1") && Catch::Contains("(0, 1e+09] kPa"));
  v = values();
  v["ec0"] = 1.2;
  CHECK_THAT(message(v), Catch::Contains("ed0 < ec0 < ei0") && Catch::Contains("ec0 = 1.2"));
}

TEST_CASE(
    "a value inside its bounds but outside the range calibrated soils span is warned of, by key",
    "[parameters]") {
  const auto& table = models::HypoplasticParameters::table();
  CHECK(models::implausible_values(table, values(), "sand.toml [hypoplastic]")
            .empty());  // a sand's set
  auto v = values();
  v["phi_c_deg"] = 0.4887;  // 28 degrees written in radians: admissible, (0, 90) deg
  CHECK_NOTHROW(models::HypoplasticParameters::from(v, "sand.toml [hypoplastic]"));
  const auto warnings = models::implausible_values(table, v, "sand.toml [hypoplastic]");
  REQUIRE(warnings.size() == 1);
  CHECK_THAT(
      warnings[0],
      Catch::Contains("sand.toml [hypoplastic]: phi_c_deg = 0.4887 deg lies outside [15, 50]"));
}

TEST_CASE("a set von Wolffersdorff's condition does not admit is refused, naming the condition",
          "[parameters]") {
  // the truth grains' calibrated set (data/params/truth_grains_epsd2.toml): a = 3.7326 from phi_c
  // by eq. 5.15, (ei0 - ed0)/(ec0 - ed0) = 4.3638, so 3 + a^2 > sqrt3 a 4.3638^alpha needs alpha <
  // 0.65348 (by hand); issue 38 saw tau turn negative at alpha 0.8 and 1.5
  models::ParameterValues v = {{"phi_c_deg", 25.013059}, {"hs_kPa", 65186.0},  {"n", 0.439},
                               {"ec0", 0.842533444},     {"ed0", 0.611319493}, {"ei0", 1.62027681},
                               {"alpha", 0.177097846},   {"beta", 1.306}};
  CHECK(message(v).empty());
  v["alpha"] = 0.653;
  CHECK(message(v).empty());
  for (double alpha : {0.654, 0.8, 1.5}) {
    v["alpha"] = alpha;
    CHECK_THAT(message(v),
               Catch::Contains("sand.toml [hypoplastic]") && Catch::Contains("inadmissible") &&
                   Catch::Contains("3 + a^2 - sqrt(3) a ((ei0 - ed0)/(ec0 - ed0))^alpha > 0") &&
                   Catch::Contains("alpha must lie below 0.6535"));
  }
}
