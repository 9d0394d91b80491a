// Why a model breaks, in one line (issue 38, item 5; comparison/verdicts/form_limit_causes.hpp), on
// a constructed form-limit record whose counts are known by construction: three CNL runs on R_n 0.5
// whose residual the prediction breaks in all three, the form limit in two (the record's cause:
// form) and a set the soil tests accept holds the third (calibration); whose dilation the
// prediction breaks in all three and the form limit in none, in a record written before the soil
// tests judged a set (so "calibration (unchecked)"); and runs of another wall and another boundary
// that must not be counted.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "comparison/verdicts/form_limit_causes.hpp"

using namespace iwb;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

json quantity(const std::string& predicted, const std::string& limit,
              const std::string& cause = "") {
  json q = {{"soil_test_predicted", {{"verdict", predicted}}},
            {"form_limit", {{"verdict", limit}}}};
  if (!cause.empty()) q["cause_if_breaks"] = cause;
  return q;
}

json run(const std::string& wall, const std::string& boundary, const std::string& residual_limit) {
  return {{"wall", wall},
          {"boundary", boundary},
          {"quantities",
           {{"residual_friction", quantity("breaks", residual_limit,
                                           residual_limit == "breaks" ? "form" : "calibration")},
            {"total_dilation", quantity("breaks", "holds")},
            {"peak_friction", quantity("holds", "holds")}}}};
}

json record(const std::string& model) {
  return {{"kind", "form_limit"},
          {"model", model},
          {"runs",
           {run("R_n 0.5, d50 2 mm", "CNL", "breaks"), run("R_n 0.5, d50 2 mm", "CNL", "breaks"),
            run("R_n 0.5, d50 2 mm", "CNL", "within DEM scatter"),
            run("R_n 0.1, d50 2 mm", "CNL", "breaks"), run("R_n 0.5, d50 2 mm", "CNS", "breaks")}}};
}

void write(const fs::path& file, const json& j) {
  fs::create_directories(file.parent_path());
  std::ofstream(file) << j.dump();
}

}  // namespace

TEST_CASE("form-limit causes: counted per quantity on one wall and boundary, by cause",
          "[comparison]") {
  const auto c = comparison::causes_on(record("hvwe"), "R_n 0.5, d50 2 mm", "CNL");
  REQUIRE(c.size() == 3);
  CHECK(c.at("residual_friction").runs == 3);
  CHECK(c.at("residual_friction").predicted_breaks == 3);
  CHECK(c.at("residual_friction").by_cause.at("form") == 2);
  CHECK(c.at("residual_friction").by_cause.at("calibration") == 1);
  CHECK(c.at("total_dilation").by_cause.at("calibration (unchecked)") == 3);
  CHECK(c.at("peak_friction").predicted_breaks == 0);
  CHECK(comparison::causes_line(c) ==
        "residual_friction: form 2, calibration 1 of 3; total_dilation: calibration (unchecked) 3 "
        "of 3");
  CHECK(comparison::causes_on(record("hvwe"), "R_n 0.25, d50 2 mm", "CNL").empty());
  CHECK(comparison::causes_line({}) == "");
  CHECK(comparison::causes_line({{"peak_friction", {3, 0, {}}}}) == "nothing breaks");
}

TEST_CASE("form-limit causes: the record of the model with runs on the wall and boundary is found",
          "[comparison]") {
  const fs::path dir = fs::path(IWB_TEST_RUNS_DIR) / "form_limit_causes";
  fs::remove_all(dir);
  write(dir / "a_other_model" / "form_limit.json", record("ahe"));
  write(dir / "b_not_a_record" / "form_limit.json",
        json{{"kind", "comparison"}, {"model", "hvwe"}});
  write(dir / "c_hvwe" / "form_limit.json", record("hvwe"));
  const auto found = comparison::find_form_limit(dir, "hvwe", "R_n 0.5, d50 2 mm", "CNS");
  REQUIRE(found.has_value());
  CHECK(*found == dir / "c_hvwe" / "form_limit.json");
  CHECK_FALSE(comparison::find_form_limit(dir, "hvwe", "R_n 0.25, d50 2 mm", "CNL").has_value());
  CHECK_FALSE(comparison::find_form_limit(dir, "mc", "R_n 0.5, d50 2 mm", "CNL").has_value());
  const auto cell = comparison::form_limit_cell(dir, "hvwe", "R_n 0.5, d50 2 mm", "CNS");
  CHECK(cell["causes"] ==
        "residual_friction: form 1 of 1; total_dilation: calibration (unchecked) 1 of 1");
  CHECK(comparison::form_limit_cell(dir, "mc", "R_n 0.5, d50 2 mm", "CNL")["causes"] ==
        "no form-limit record");
}
