// The hypothesis checks of DEM.md over sets of runs: the verdict logic on constructed records
// (numbers chosen so that each verdict is decided by a known margin), and `iwb compare --runs`
// end to end on synthetic run directories written by a continuum model.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>

#include "comparison/compare/compare.hpp"
#include "comparison/compare/hypotheses.hpp"
#include "comparison/compare/run_set.hpp"
#include "io/run_directory.hpp"
#include "support/synthetic_dem.hpp"

using namespace iwb;
using comparison::RunRecord;
namespace fs = std::filesystem;

namespace {

// Seeds of one configuration: fitted kappa_r (no fit uncertainty) and DEM friction/dilation.
std::vector<RunRecord> seeds(const std::string& tag, double R_n, double d50,
                             const std::vector<double>& kappa, const std::vector<double>& peak = {},
                             double dilation_d50 = 0.3) {
  std::vector<RunRecord> out;
  for (std::size_t i = 0; i < kappa.size(); ++i) {
    const double p = peak.empty() ? 0.6 : peak[i];
    out.push_back({.name = tag + std::to_string(i),
                   .R_n = R_n,
                   .d50_mm = d50,
                   .kappa_r_fit = kappa[i],
                   .d_s_fit_d50 = 7.0,
                   .peak_friction = p,
                   .residual_friction = p - 0.1,
                   .dilation_mm = dilation_d50 * d50,
                   .shear_mode = "localised at the wall",
                   .band_d50 = 7.0});
  }
  return out;
}

std::vector<RunRecord> joined(std::vector<RunRecord> a, const std::vector<RunRecord>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

std::vector<RunRecord> with_bands(const std::vector<double>& bands) {
  auto runs = seeds("b", 0.1, 0.2, std::vector<double>(bands.size(), 0.8));
  for (std::size_t i = 0; i < bands.size(); ++i) runs[i].band_d50 = bands[i];
  return runs;
}

}  // namespace

TEST_CASE("R_n groups: 2 % relative, and round-off joins R_n = 0", "[comparison][hypotheses]") {
  const auto g = comparison::group_close({0.1, 0.0, 0.101, 5e-5, 0.11, 0.5},
                                         comparison::kSameRnRelative, comparison::kSameRnAbsolute);
  REQUIRE(g.size() == 4);
  CHECK(g[0] == std::vector<std::size_t>{1, 3});  // 0 and 5e-5
  CHECK(g[1] == std::vector<std::size_t>{0, 2});  // 0.1 and 0.101 (1 %)
  CHECK(g[2] == std::vector<std::size_t>{4});     // 0.11 is 10 % away
  CHECK(g[3] == std::vector<std::size_t>{5});
}

TEST_CASE("kappa_r: within scatter of eq. 5.35 follows, 5 SD off misses, flat wall names the floor",
          "[comparison][hypotheses]") {
  // lg: R_n = 0.1 gives 0.80, R_n = 0.01 gives 0.55; seeds scatter by SD 0.01
  const auto runs = joined(joined(seeds("on", 0.1, 0.2, {0.79, 0.80, 0.81}),
                                  seeds("off", 0.01, 0.2, {0.59, 0.60, 0.61})),
                           seeds("flat", 0.0, 0.2, {0.62}));
  const auto c = comparison::check_kappa_r(runs);
  REQUIRE(c.groups.size() == 3);
  const auto& flat = c.groups[0];
  const auto& off = c.groups[1];
  const auto& on = c.groups[2];
  CHECK(on.bases[0].formula == Approx(0.80).margin(1e-12));
  CHECK(on.fit.sd == Approx(0.01).margin(1e-12));
  CHECK(on.bases[0].in_scatter.value() == Approx(0.0).margin(1e-9));
  CHECK(on.bases[0].follows);
  CHECK(off.bases[0].formula == Approx(0.55).margin(1e-12));
  CHECK(off.bases[0].in_scatter.value() == Approx(5.0).epsilon(1e-9));
  CHECK_FALSE(off.bases[0].follows);
  CHECK(flat.bases[0].formula == models::kKappaRFloor);  // single run: absolute difference only
  CHECK_FALSE(flat.bases[0].in_scatter.has_value());
  CHECK(flat.bases[0].difference == Approx(0.57));
  // ln: R_n = 0.1 gives 0.25 ln 0.1 + 1.05 = 0.474, far below the fits
  CHECK(on.bases[1].formula == Approx(0.25 * std::log(0.1) + 1.05));
  CHECK_FALSE(on.bases[1].follows);
  CHECK(c.outcome[0] == "partly follows");
  CHECK(c.outcome[1] == "misses");
  INFO(c.verdict[0]);
  CHECK_THAT(
      c.verdict[0],
      Catch::Contains("follows within scatter at 1 of 3 R_n") &&
          Catch::Contains("R_n = 0 (flat) (floor: formula gives 0.050, fit 0.620 (one run)") &&
          Catch::Contains("R_n = 0.01 (formula gives 0.550, fit 0.600 +- 0.010; +5.0 SD)"));
  CHECK_THAT(c.verdict_overall, Catch::Contains("favour log base 10"));
}

TEST_CASE("kappa_r: a single run follows within 0.05 absolute, not beyond",
          "[comparison][hypotheses]") {
  CHECK(comparison::check_kappa_r(seeds("a", 0.1, 0.2, {0.84})).groups[0].bases[0].follows);
  CHECK_FALSE(comparison::check_kappa_r(seeds("a", 0.1, 0.2, {0.86})).groups[0].bases[0].follows);
}

TEST_CASE("band thickness: 7 +- 1 d50 holds, distributed shear is counted apart and never measured",
          "[comparison][hypotheses]") {
  auto runs = with_bands({6.0, 7.0, 8.0});
  runs.push_back(runs[0]);
  runs.back().name = "spread";
  runs.back().shear_mode = "distributed shear";
  runs.back().band_d50 = 3.0;  // must not be used
  const auto c = comparison::check_band_thickness(runs);
  CHECK(c.band.n == 3);
  CHECK(c.band.mean == Approx(7.0));
  CHECK(c.band.sd == Approx(1.0));
  CHECK(c.inside == 3);
  CHECK(c.distributed == std::vector<std::string>{"spread"});
  CHECK(c.outcome == "holds");
  CHECK_THAT(c.verdict,
             Catch::Contains("7.00 +- 1.00 d50 over 3 localised run(s), 3 of 3 inside [5, 10]") &&
                 Catch::Contains("1 run(s) with distributed shear"));
  CHECK(comparison::check_band_thickness(with_bands({4.0, 7.0, 9.0})).outcome ==
        "holds on average");
  const auto thick = comparison::check_band_thickness(with_bands({12.0, 13.0}));
  CHECK(thick.outcome == "does not hold");
  CHECK(thick.inside == 0);
  auto none = with_bands({7.0});
  none[0].band_d50.reset();
  none[0].shear_mode = "localised at the plate";
  CHECK(comparison::check_band_thickness(none).outcome == "not testable");
}

TEST_CASE("band thickness per R_n and d50: each wall and grain size with its own seed scatter",
          "[comparison][hypotheses]") {
  auto slipping = seeds("flat", 0.0, 2.0, {0.5, 0.5, 0.5});
  for (std::size_t i = 0; i < 2; ++i) slipping[i].band_d50 = 2.0 + double(i) * 2.0;  // 2, 4
  slipping[2].shear_mode = "distributed shear";
  auto rough = seeds("rough", 0.5, 2.0, {0.8, 0.8, 0.8});
  for (std::size_t i = 0; i < 3; ++i) rough[i].band_d50 = 6.0 + double(i);  // 6, 7, 8
  auto fine = seeds("fine", 0.5, 1.0, {0.8, 0.8});
  fine[0].band_d50 = 9.0, fine[1].band_d50 = 11.0;
  const auto runs = joined(joined(slipping, rough), fine);
  const auto c = comparison::check_band_thickness(runs);
  REQUIRE(c.groups.size() == 3);  // R_n 0; R_n 0.5 at d50 1 mm and 2 mm
  CHECK(c.groups[0].R_n == 0.0);
  CHECK(c.groups[0].band.mean == Approx(3.0));
  CHECK(c.groups[0].band.sd == Approx(std::sqrt(2.0)));
  CHECK(c.groups[0].inside == 0);
  CHECK(c.groups[0].without_band == 1);
  CHECK(c.groups[1].d50_mm == 1.0);
  CHECK(c.groups[1].band.mean == Approx(10.0));
  CHECK(c.groups[1].inside == 1);  // 9 in, 11 out
  CHECK(c.groups[2].d50_mm == 2.0);
  CHECK(c.groups[2].band.sd == Approx(1.0));
  CHECK(c.groups[2].inside == 3);
  CHECK_THAT(c.verdict,
             Catch::Contains("R_n = 0 (flat), d50 2 mm: 3.00 +- 1.41 d50, 0 of 2 inside") &&
                 Catch::Contains("R_n = 0.5, d50 2 mm: 7.00 +- 1.00 d50, 3 of 3 inside"));
  const auto h = comparison::to_json(comparison::check_hypotheses(runs), runs);
  const auto& rows = h["checks"][1]["group_table"]["rows"];
  REQUIRE(rows.size() == 3);
  CHECK(rows[2][3] == "7.00 ± 1.00");
  CHECK(rows[0][5] == "1");
  CHECK_THAT(comparison::to_markdown(h),
             Catch::Contains("| wall band (d50): mean ± SD over seeds |"));
}

TEST_CASE(
    "collapse over d50: equal friction collapses, 20 % apart does not, one d50 is not testable",
    "[comparison][hypotheses]") {
  const std::vector<double> p = {0.60, 0.62, 0.61};  // SD 0.01 over seeds
  const auto same = comparison::check_d50_collapse(
      joined(seeds("s", 0.1, 1.0, {0.8, 0.8, 0.8}, p),
             seeds("l", 0.1, 2.0, {0.8, 0.8, 0.8}, {0.61, 0.60, 0.62})));
  REQUIRE(same.groups.size() == 1);
  REQUIRE(same.groups[0].quantities.size() == 3);
  const auto& peak = same.groups[0].quantities[0];
  CHECK(peak.difference == Approx(0.0).margin(1e-12));
  CHECK(peak.pooled_sd == Approx(0.01));
  CHECK(peak.dof == 4);
  CHECK(peak.collapses);
  CHECK(same.outcome == "collapses");

  const auto apart = comparison::check_d50_collapse(
      joined(seeds("s", 0.1, 1.0, {0.8, 0.8, 0.8}, p),
             seeds("l", 0.1, 2.0, {0.8, 0.8, 0.8}, {0.72, 0.744, 0.732})));
  const auto& q = apart.groups[0].quantities[0];
  CHECK(q.difference == Approx(0.122));
  // pooled SD sqrt((0.01^2 + 0.012^2)/2), standard error of the difference times sqrt(2/3)
  CHECK(q.in_scatter.value() ==
        Approx(0.122 / (std::sqrt((1e-4 + 1.44e-4) / 2.0) * std::sqrt(2.0 / 3.0))));
  CHECK_FALSE(q.collapses);
  CHECK(apart.groups[0].quantities[2].collapses);  // u_n / d50 equal: dilation scales with d50
  CHECK(apart.outcome == "does not collapse");
  CHECK_THAT(apart.verdict, Catch::Contains("peak friction differs by 0.122"));

  const auto single = comparison::check_d50_collapse(seeds("s", 0.1, 1.0, {0.8, 0.8}, {0.6, 0.61}));
  CHECK(single.outcome == "not testable");
  CHECK_THAT(single.verdict, Catch::Contains("not testable: need runs with two d50 at equal R_n"));
}

TEST_CASE("collapse over d50 without seeds: differences against the stated resolution",
          "[comparison][hypotheses]") {
  auto runs = joined(seeds("s", 0.1, 1.0, {0.8}, {0.60}), seeds("l", 0.1, 2.0, {0.8}, {0.615}));
  CHECK(comparison::check_d50_collapse(runs).outcome == "collapses");  // 0.015 < 0.02
  runs[1].peak_friction = 0.63;
  const auto c = comparison::check_d50_collapse(runs);
  CHECK(c.outcome == "does not collapse");
  CHECK_FALSE(c.groups[0].quantities[0].in_scatter.has_value());
  CHECK_THAT(c.verdict, Catch::Contains("no seed scatter, resolution 0.02"));
}

TEST_CASE("iwb compare --runs: fits, verdicts and report over synthetic runs",
          "[comparison][hypotheses][cli]") {
  // Two d50 at one R_n, each sheared through a band of 7 d50 by hvwe with kappa_r = 0.7: the
  // fit must find 0.7, the band 7 d50, and u_x, u_n scale with d50 so the set collapses. A third
  // run shears over the whole specimen: counted as distributed, no band. R_n = 10^-1.4 makes
  // eq. 5.35 (lg) give exactly 0.7.
  const double R_n = std::pow(10.0, -1.4);
  std::vector<fs::path> dirs;
  for (const double d50 : {0.2, 0.4})
    dirs.push_back(test::write_synthetic_dem({.name = fmt::format("hyp_d50_{}", d50),
                                              .kappa_r = 0.7,
                                              .d_s_mm = 7.0 * d50,
                                              .R_n = R_n,
                                              .d50_mm = d50}));
  dirs.push_back(test::write_synthetic_dem({.name = "hyp_distributed",
                                            .kappa_r = 1.0,
                                            .d_s_mm = 4.0,
                                            .R_n = 1.0,
                                            .d50_mm = 0.2,
                                            .distributed = true}));
  const fs::path out = fs::path(IWB_TEST_RUNS_DIR) / "hypotheses-cli";
  fs::remove_all(out);
  const std::string cmd = fmt::format(
      "{} compare --runs {} {} {} --model hvwe --params data/params/table_5_1_evaluation.toml "
      "-o {} > {}.log 2>&1",
      IWB_BINARY, dirs[0].string(), dirs[1].string(), dirs[2].string(), out.string(), out.string());
  REQUIRE(std::system(cmd.c_str()) == 0);
  const auto h = nlohmann::json::parse(io::read_file(out / "hypotheses.json"));
  const auto& kappa = h["checks"][0]["groups"];
  REQUIRE(kappa.size() == 2);
  INFO(h["checks"][0]["verdict"].get<std::string>());
  CHECK(kappa[0]["fit"]["n"] == 2);
  CHECK(kappa[0]["fit"]["mean"].get<double>() == Approx(0.7).margin(0.01));
  CHECK(kappa[0]["bases"][0]["formula"].get<double>() == Approx(0.7).margin(1e-9));
  CHECK(std::abs(kappa[0]["bases"][0]["difference"].get<double>()) < 0.01);
  CHECK(kappa[0]["bases"][0]["follows"].get<bool>());  // identical seeds: the resolution decides
  CHECK(kappa[0]["bases"][1]["formula"].get<double>() == Approx(0.25 * std::log(R_n) + 1.05));
  CHECK_FALSE(kappa[0]["bases"][1]["follows"].get<bool>());  // ln gives 0.24: far from 0.7
  const auto& band = h["checks"][1];
  INFO(band["verdict"].get<std::string>());
  CHECK(band["band"]["n"] == 2);
  CHECK(band["band"]["mean"].get<double>() == Approx(7.0).margin(1.0));  // profile bins of d50 / 2
  CHECK(band["inside"] == 2);
  CHECK(band["distributed"] == nlohmann::json::array({"hyp_distributed"}));
  const auto& collapse = h["checks"][2];
  INFO(collapse["verdict"].get<std::string>());
  CHECK(collapse["outcome"] == "collapses");
  CHECK(collapse["groups"][0]["quantities"][0]["difference"].get<double>() < 1e-3);
  CHECK(fs::exists(out / "hypotheses.md"));
  CHECK_THAT(io::read_file(out.string() + ".log"),
             Catch::Contains("Band thickness against d_s = k d50"));

  // again: every comparison is reused, the verdicts are the same
  REQUIRE(std::system(cmd.c_str()) == 0);
  CHECK_THAT(io::read_file(out.string() + ".log"), Catch::Contains("3 run(s) compared (3 reused)"));
  CHECK(nlohmann::json::parse(io::read_file(out / "hypotheses.json"))["checks"] == h["checks"]);

  // the report of the set leads with the verdict tables (OUT/* passes the set's own files too)
  const std::string rep = fmt::format(
      "{0} report {1}/* -o {1}-report/report.html > {1}-report.log 2>&1", IWB_BINARY, out.string());
  REQUIRE(std::system(rep.c_str()) == 0);
  const std::string html = io::read_file(out.string() + "-report/report.html");
  CHECK(html.find("Hypothesis checks over 3 DEM runs") < html.find("<svg"));
  CHECK_THAT(html, Catch::Contains("<th>wall band (d50)</th>") &&
                       Catch::Contains("<td>hyp_distributed</td>"));
  std::size_t svgs = 0;
  for (auto p = html.find("<svg"); p != std::string::npos; p = html.find("<svg", p + 1)) ++svgs;
  CHECK(svgs == 12);  // four figures for each of the three runs

  // the set's directory alone names the same runs
  const std::string rep_dir =
      fmt::format("{0} report {1} -o {1}-report-dir/report.html > {1}-report-dir.log 2>&1",
                  IWB_BINARY, out.string());
  REQUIRE(std::system(rep_dir.c_str()) == 0);
  CHECK_THAT(io::read_file(out.string() + "-report-dir.log"), Catch::Contains("(12 figures)"));
}

TEST_CASE("a fit without a sigma (singular Jacobian) is read as NaN and a missing one is refused",
          "[comparison]") {
  const fs::path dir = fs::path(IWB_TEST_RUNS_DIR) / "comparison" / "record_sigma";
  const fs::path dem = dir / "dem", cmp = dir / "cmp";
  fs::create_directories(dem), fs::create_directories(cmp);
  io::write_atomically(dem / "summary.json",
                       R"({"peak_friction": 0.6, "residual_friction": 0.5, "dilation_mm": 1.0,
                           "shear_mode": "localised at the wall"})");
  const auto with_fit = [&](const std::string& fit) {
    io::write_atomically(cmp / "compare.json",
                         R"({"dem": {"dir": ")" + dem.string() +
                             R"(", "R_n": 0.5, "d50_mm": 2.0}, "fit": {"kappa_r": 0.9, )" + fit +
                             R"("d_s_over_d50": 5.0}})");
  };
  with_fit(R"("sigma_kappa_r": null, )");
  CHECK(std::isnan(comparison::load_run_record(cmp).sigma_kappa_r_fit));
  with_fit(R"("sigma_kappa_r": 0.02, )");
  CHECK(comparison::load_run_record(cmp).sigma_kappa_r_fit == 0.02);
  with_fit("");
  CHECK_THROWS_WITH(comparison::load_run_record(cmp), Catch::Contains("/fit/sigma_kappa_r"));
}

TEST_CASE("a seed whose fit has no sigma leaves the group judged on its seeds' scatter",
          "[comparison][hypotheses]") {
  // kappa_r 0.80, 0.84, 0.88: SD 0.04 exactly; the fits' sigmas 0.03 and (none): the group's
  // scatter is hypot(0.04, 0.03) = 0.05, and its test one of scatter, not a single run's
  auto runs = seeds("nosigma", 0.1, 0.2, {0.80, 0.84, 0.88});
  runs[0].sigma_kappa_r_fit = 0.03, runs[1].sigma_kappa_r_fit = 0.03;
  runs[2].sigma_kappa_r_fit = std::numeric_limits<double>::quiet_NaN();
  const auto g = comparison::check_kappa_r(runs).groups.at(0);
  CHECK(g.scatter == Approx(0.05).epsilon(1e-9));
  CHECK(g.bases[0].in_scatter.has_value());
}
