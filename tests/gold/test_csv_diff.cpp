// The gold-file comparer itself (tests/support/csv_diff.hpp): it must pass equal files and fail,
// naming column and row, on exactly the changes the gold tests exist to catch.
#include <catch2/catch.hpp>

#include "common/errors.hpp"
#include "io/toml_reader.hpp"
#include "support/csv_diff.hpp"

using namespace iwb;

namespace {

const std::string kGold =
    "increment,sigma_n_kPa,sigma_p_kPa,tau_x_kPa,e\n"
    "0,100,57.4,0,0.7\n"
    "10,100,61.2,20.5,0.6995\n"
    "20,100,64.8,38.25,0.6991\n";

test::CsvTolerances tight() {
  test::CsvTolerances t;
  t.fallback = {1e-6, 1e-6};
  return t;
}

}  // namespace

TEST_CASE("gold: csv diff: equal files pass, empty cells included", "[gold]") {
  CHECK_FALSE(test::diff_csv(kGold, kGold, tight()).failed);
  const std::string hp1d = "sigma_n_kPa,sigma_p_kPa\n100,\n";  // hp1d has no sigma_p
  CHECK_FALSE(test::diff_csv(hp1d, hp1d, tight()).failed);
  CHECK(test::diff_csv(hp1d, "sigma_n_kPa,sigma_p_kPa\n100,0\n", tight()).failed);
}

TEST_CASE("gold: csv diff: a 1 % change of one value fails a 1e-6 column and names column and row",
          "[gold]") {
  std::string changed = kGold;
  changed.replace(changed.find("38.25"), 5, "38.6325");  // tau_x in data row 3, +1 %
  const auto d = test::diff_csv(kGold, changed, tight());
  CHECK(d.failed);
  CHECK(d.column == "tau_x_kPa");
  CHECK(d.row == 3);
  CHECK_THAT(d.message, Catch::Contains("column 'tau_x_kPa', row 3") &&
                            Catch::Contains("expected 38.25, got 38.6325") &&
                            Catch::Contains("abs 1e-06 or rel 1e-06"));
}

TEST_CASE("gold: csv diff: a value within the column's own tolerance passes", "[gold]") {
  std::string changed = kGold;
  changed.replace(changed.find("38.25"), 5, "38.2501");
  auto t = tight();
  CHECK(test::diff_csv(kGold, changed, t).failed);
  t.columns["tau_x_kPa"] = {1e-3, 0.0};  // absolute
  CHECK_FALSE(test::diff_csv(kGold, changed, t).failed);
  t.columns["tau_x_kPa"] = {0.0, 1e-5};  // relative
  CHECK_FALSE(test::diff_csv(kGold, changed, t).failed);
  t.columns["tau_x_kPa"].skip = true;
  changed.replace(changed.find("38.2501"), 7, "99");
  CHECK_FALSE(test::diff_csv(kGold, changed, t).failed);
}

TEST_CASE("gold: csv diff: a different header or row count fails", "[gold]") {
  std::string renamed = kGold;
  renamed.replace(renamed.find("tau_x_kPa"), 9, "tau_y_kPa");
  const auto d = test::diff_csv(kGold, renamed, tight());
  CHECK(d.failed);
  CHECK_THAT(d.message, Catch::Contains("headers differ"));
  const auto shorter = kGold.substr(0, kGold.rfind("20,"));
  CHECK_THAT(test::diff_csv(kGold, shorter, tight()).message,
             Catch::Contains("row counts differ: expected 3, got 2"));
  CHECK(test::diff_csv_files("no/such/gold.csv", "no/such/run.csv", tight()).failed);
}

TEST_CASE("gold: csv diff: tolerances are read from TOML with the keys named", "[gold]") {
  const auto root = io::parse_toml_text(R"(
[tolerance]
rel = 1e-4
skip = ["rate_evaluations"]
[tolerance.columns]
tau_x_kPa = { abs = 1e-3, rel = 2e-4 }
)",
                                        "gold.toml");
  const auto t = test::read_tolerances(root, "gold.toml");
  CHECK(t.of("e").rel == 1e-4);
  CHECK(t.of("tau_x_kPa").abs == 1e-3);
  CHECK(t.of("rate_evaluations").skip);
  const auto typo = io::parse_toml_text(
      "[tolerance]\nrel = 1e-4\n[tolerance.columns]\ne = { abs = 1, rell = 2 }\n", "g.toml");
  CHECK_THROWS_WITH(test::read_tolerances(typo, "g.toml"), Catch::Contains("rell"));
}
