// The report's cyclic section (issue 34, item 4) on a committed cyclic DEM run (R_n 0.5, CV,
// A 1 mm, 10 cycles, then 5 mm): the loops are the DEM's own rows of each cycle and sigma_n over
// N is the DEM's sigma_n at the cycle's end, both found here from timeseries.csv and the scene's
// wall speed alone (travel = v t), and so are the three seeds' mean and t-interval drawn beside it;
// hvwe and hvwe-igs, judged along the run in one call, stand side by side.
#include <fmt/core.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "comparison/presentation/verdict_table.hpp"
#include "io/csv_table.hpp"
#include "io/json_file.hpp"
#include "io/run_directory.hpp"
#include "support/cli.hpp"

using namespace iwb;
namespace fs = std::filesystem;

namespace {

const fs::path kCyclicWork = fs::path(IWB_TEST_RUNS_DIR) / "cyclic_report";
const fs::path kCyclicRun = "data/cyclic/cyclic_rn05/runs/cv_s1";
const fs::path kSeeds[] = {"data/cyclic/cyclic_rn05/runs/cv_s2",
                           "data/cyclic/cyclic_rn05/runs/cv_s3"};
// a parameter file with an intergranular-strain table, so that hvwe-igs can run beside hvwe
const fs::path kIgsParams = "data/params/truth_grains_epsd2_igs.toml";

// hvwe and hvwe-igs judged along the run in one call, into OUT/hvwe and OUT/hvwe-igs
std::pair<fs::path, fs::path> compared_by_both() {
  const fs::path out = kCyclicWork / "both";
  const auto r = test::run_iwb({"compare", kCyclicRun.string(), "--seeds", kSeeds[0].string(),
                                kSeeds[1].string(), "--params", kIgsParams.string(), "--model",
                                "hvwe,hvwe-igs", "-o", out.string(), "--force"});
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.output, Catch::Contains("Cycles, model beside model"));
  return {out / "hvwe", out / "hvwe-igs"};
}

// A figure's CSV: an x and a y column per curve, padded with nan (which read_csv_table refuses).
std::vector<std::vector<double>> figure_rows(const fs::path& csv) {
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);  // header
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::stringstream cells(line);
    std::vector<double> row;
    for (std::string cell; std::getline(cells, cell, ',');) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}

// The last curve of a figure (the DEM's: it is drawn last), its nan padding dropped.
std::vector<std::pair<double, double>> last_curve(const fs::path& csv) {
  std::vector<std::pair<double, double>> points;
  for (const auto& r : figure_rows(csv))
    if (!std::isnan(r[r.size() - 2])) points.push_back({r[r.size() - 2], r.back()});
  return points;
}

double interpolated(const std::vector<double>& x, const std::vector<double>& y, double at) {
  const auto k = std::size_t(std::lower_bound(x.begin(), x.end(), at) - x.begin());
  if (k == 0) return y.front();
  if (k == x.size()) return y.back();
  return y[k - 1] + (y[k] - y[k - 1]) * (at - x[k - 1]) / (x[k] - x[k - 1]);
}

// sigma_n / sigma_n0 of `run` at the end of cycle n, from its time series and wall speed alone
double ratio_at_cycle_end(const fs::path& run, int n) {
  const auto ts = io::read_csv_table(run / "timeseries.csv");
  const auto shear = io::read_json_file(run / "manifest.json")["scene"]["resolved"]["shear"];
  const double v = shear["velocity_mm_s"], A = shear["amplitude_mm"];
  const auto t = ts.values("t_s"), sigma_n = ts.values("sigma_n_kPa");
  std::vector<double> travel;
  for (double ti : t) travel.push_back(v * (ti - t.front()));
  return interpolated(travel, sigma_n, 4 * A * n) / sigma_n.front();
}

// The curve of a figure's CSV at column pair `k` (x_k, y_k), nan padding dropped.
std::vector<std::pair<double, double>> curve(const fs::path& csv, std::size_t k) {
  std::vector<std::pair<double, double>> points;
  for (const auto& r : figure_rows(csv))
    if (!std::isnan(r[2 * k])) points.push_back({r[2 * k], r[2 * k + 1]});
  return points;
}

}  // namespace

TEST_CASE(
    "report: a cyclic run's section draws each judged cycle's own loop, sigma_n over N and the CV "
    "stress path, and puts models judged along one run side by side",
    "[comparison][cyclic]") {
  const auto [hvwe, igs] = compared_by_both();
  const fs::path html = kCyclicWork / "report" / "report.html";
  const auto r = test::run_iwb({"report", hvwe.string(), igs.string(), "-o", html.string()});
  INFO(r.output);
  REQUIRE(r.exit_code == 0);

  // the DEM's rows and travel, from its files alone
  const auto ts = io::read_csv_table(kCyclicRun / "timeseries.csv");
  const auto shear = io::read_json_file(kCyclicRun / "manifest.json")["scene"]["resolved"]["shear"];
  const double v = shear["velocity_mm_s"], A = shear["amplitude_mm"];
  const int cycles = shear["cycles"];
  REQUIRE(cycles == 10);
  const auto t = ts.values("t_s"), u_x = ts.values("u_x_mm"), tau = ts.values("tau_kPa"),
             sigma_n = ts.values("sigma_n_kPa");
  std::vector<double> travel;
  for (double ti : t) travel.push_back(v * (ti - t.front()));

  const fs::path figures = kCyclicWork / "report" / "report_files" / "0-hvwe";
  for (int n : {1, 2, 5, 10}) {
    // cycle n: from the last row at or before travel 4 A (n - 1) to the first at or after 4 A n
    std::size_t first = 0, last = travel.size() - 1;
    for (std::size_t k = 0; k < travel.size(); ++k) {
      if (travel[k] <= 4 * A * (n - 1)) first = k;
      if (travel[k] >= 4 * A * n) {
        last = k;
        break;
      }
    }
    const auto loop = last_curve(figures / fmt::format("loop_{}.csv", n));
    INFO("cycle " << n);
    REQUIRE(loop.size() == last - first + 1);
    CHECK(loop.front().first == Approx(u_x[first]).margin(1e-7));
    CHECK(loop.front().second == Approx(tau[first]).margin(1e-5));
    CHECK(loop.back().second == Approx(tau[last]).margin(1e-5));
    // the wall went to +A and -A within the cycle (to a row's spacing)
    const auto [lo, hi] = std::minmax_element(loop.begin(), loop.end());
    double row = 0.0;  // the largest row spacing in the cycle
    for (std::size_t k = first; k < last; ++k) row = std::max(row, travel[k + 1] - travel[k]);
    CHECK(hi->first == Approx(A).margin(row));
    CHECK(lo->first == Approx(-A).margin(row));
  }
  CHECK_FALSE(fs::exists(figures / "loop_3.csv"));  // only the cycles the verdicts judge

  // sigma_n at each cycle's end over sigma_n0, interpolated at travel 4 A N
  const auto ratio = last_curve(figures / "sigma_n_ratio_n.csv");
  REQUIRE(ratio.size() == std::size_t(cycles));
  for (const auto& [n, value] : ratio)
    CHECK(value ==
          Approx(interpolated(travel, sigma_n, 4 * A * n) / sigma_n.front()).epsilon(1e-6));
  // the three seeds' mean and 95 % t-interval (t(0.975, 2) = 4.303) at the judged cycles, drawn
  // after the three variants: the means, then one bar per cycle
  const auto means = curve(figures / "sigma_n_ratio_n.csv", 3);
  REQUIRE(means.size() == 4);  // cycles 1, 2, 5, 10
  for (std::size_t i = 0; i < means.size(); ++i) {
    const int n = int(means[i].first);
    std::vector<double> seeds = {ratio_at_cycle_end(kCyclicRun, n),
                                 ratio_at_cycle_end(kSeeds[0], n),
                                 ratio_at_cycle_end(kSeeds[1], n)};
    const double mean = (seeds[0] + seeds[1] + seeds[2]) / 3.0;
    double square = 0.0;
    for (double x : seeds) square += (x - mean) * (x - mean);
    const double half = 4.303 * std::sqrt(square / 2.0) / std::sqrt(3.0);
    INFO("cycle " << n);
    CHECK(means[i].second == Approx(mean).epsilon(1e-6));
    const auto bar = curve(figures / "sigma_n_ratio_n.csv", 4 + i);
    REQUIRE(bar.size() == 2);
    CHECK(bar[1].second - bar[0].second == Approx(2.0 * half).epsilon(1e-3));
  }
  // CV: the stress path is drawn, u_n (held) is not
  CHECK(fs::exists(figures / "stress_path.svg"));
  CHECK_FALSE(fs::exists(figures / "u_n_n.csv"));
  CHECK(fs::exists(figures / "post_cyclic.svg"));

  const std::string page = io::read_file(html);
  const auto per_cycle = page.find("Verdicts per cycle");
  REQUIRE(per_cycle != std::string::npos);
  CHECK(per_cycle < page.find("Verdicts on the whole path"));
  CHECK_THAT(page, Catch::Contains("Cyclic verdicts, model beside model") &&
                       Catch::Contains("<th>hvwe-igs fitted</th>"));
  // each model's column beside the other's holds that model's own per-cycle verdicts
  const auto cmp_hvwe = io::read_json_file(hvwe / "compare.json");
  const auto cmp_igs = io::read_json_file(igs / "compare.json");
  const auto beside = comparison::cyclic_models_table({cmp_hvwe, cmp_igs});
  const auto own = comparison::cyclic_verdict_table(cmp_igs);
  REQUIRE(beside.rows.size() == own.rows.size());
  for (std::size_t i = 0; i < own.rows.size(); ++i) {
    CHECK(beside.rows[i][5] == own.rows[i][3] + " " + own.rows[i][7]);  // hvwe-igs predicted
    CHECK(beside.rows[i][6] == own.rows[i][4] + " " + own.rows[i][8]);  // hvwe-igs fitted
  }
}
