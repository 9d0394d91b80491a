// The report's first table has one row per cell (issue 59 item 5): comparisons judged on the same
// seeds are one row, whatever order they come in, and the row says what its runs say.
#include <catch2/catch.hpp>

#include "comparison/presentation/cell_glance.hpp"

using namespace iwb;
using nlohmann::json;

namespace {

// A compare.json with the fields the table reads: the run, the runs of its seed statistics, and the
// predicted variant's verdicts as (quantity, verdict, seeds needed, cause).
json glance_comparison(const std::string& run, const std::vector<std::string>& seeds,
                       const std::vector<json>& verdicts, double sigma_n0 = 50.0) {
  return {{"model", "hvwe"},
          {"dem",
           {{"dir", run},
            {"boundary", "CNL"},
            {"R_n", 0.5},
            {"d50_mm", 2.0},
            {"sigma_n0_kPa", sigma_n0}}},
          {"seeds", {{"runs", seeds}}},
          {"verdicts", {{"predicted_variant", 0}, {"fitted_variant", 0}}},
          {"variants", json::array({{{"verdicts", verdicts}}})}};
}

json glance_verdict(const std::string& q, const std::string& verdict, int seeds_needed = 0,
                    const std::string& cause = "") {
  json v = {{"quantity", q}, {"verdict", verdict}};
  if (seeds_needed > 0) v["seeds_needed"] = seeds_needed;
  if (!cause.empty()) v["cause_if_breaks"] = cause;
  return v;
}

std::string verdict_of(const comparison::CellRow& row, const std::string& q) {
  for (const auto& [key, text] : row.verdicts)
    if (key == q) return text;
  return "(none)";
}

}  // namespace

TEST_CASE("the report's first table has one row per cell of seeds, not one per run",
          "[comparison][report]") {
  const std::vector<std::string> rough = {"runs/rough_s1", "runs/rough_s2", "runs/./rough_s3"};
  std::vector<json> cmps = {
      glance_comparison("runs/rough_s2", rough,
                        {glance_verdict("peak_friction", "breaks", 0, "form"),
                         glance_verdict("total_dilation", "within DEM scatter", 7)},
                        51.0),
      glance_comparison("runs/flat_s1", {"runs/flat_s1", "runs/flat_s2"},
                        {glance_verdict("peak_friction", "holds")}),
      // the same seeds listed in another order and spelling: the same cell
      glance_comparison("runs/rough_s1", {"runs/rough_s3", "runs/rough_s1", "runs/rough_s2"},
                        {glance_verdict("peak_friction", "breaks", 0, "form"),
                         glance_verdict("total_dilation", "within DEM scatter", 9)},
                        49.0),
      glance_comparison("runs/rough_s3", rough,
                        {glance_verdict("peak_friction", "within DEM scatter", 4),
                         glance_verdict("total_dilation", "within DEM scatter", 5)},
                        50.0),
  };
  const auto rows = comparison::cell_rows(cmps);
  REQUIRE(rows.size() == 2);
  const auto& r = rows[0];
  CHECK(r.label == "rough_s*");
  CHECK(r.runs == std::vector<std::size_t>{0, 2, 3});
  CHECK(r.seeds == 3);
  CHECK(r.sigma_n0_kPa == Approx(50.0));  // (51 + 49 + 50) / 3
  // runs that differ are counted, not outvoted
  CHECK(verdict_of(r, "peak_friction") == "breaks (form) 2 · within DEM scatter 1");
  // undecided, with the most seeds any of its runs needs
  CHECK(verdict_of(r, "total_dilation") == "within DEM scatter (9 seeds)");
  CHECK(verdict_of(r, "residual_friction") == "(none)");
  CHECK(rows[1].label == "flat_s*");
  CHECK(rows[1].runs == std::vector<std::size_t>{1});
  CHECK(rows[1].seeds == 2);
  CHECK(verdict_of(rows[1], "peak_friction") == "holds");

  const std::string html = comparison::cell_glance_html(rows);
  CHECK_THAT(html, Catch::Contains("<a href=\"#run-0\">1</a> <a href=\"#run-2\">3</a>"));
  CHECK_THAT(html, Catch::Contains("<td class=\"scatter\">within DEM scatter (9 seeds)</td>"));
}
