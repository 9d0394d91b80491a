// The committed reference campaign (data/reference/, README there): every run passes the
// comparison layer's ingest of the DEM contract, and what each run records is what its sweep
// asked for. Reads a few hundred kB of CSV: well under a second.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <string>

#include "comparison/dem_run.hpp"
#include "io/run_directory.hpp"

using namespace iwb;
namespace fs = std::filesystem;

namespace {

const fs::path kReference = "data/reference";

// The wall a job name asks for: flat_..., sawtooth-2-0.25_..., d1_sawtooth-4-1_... The sawtooth's
// R_n is its height over the d50 gauge window's share of a rise (pitch 2 d50: the whole rise,
// pitch 4 d50: half of it).
double expected_R_n(const std::string& job) {
  if (job.rfind("flat", 0) == 0) return 0.0;
  const auto at = job.find("sawtooth-");
  REQUIRE(at != std::string::npos);
  std::size_t used = 0;
  const std::string rest = job.substr(at + 9);
  const double pitch_d50 = std::stod(rest, &used);
  const double height_d50 = std::stod(rest.substr(used + 1));
  return height_d50 * std::min(1.0, 2.0 / pitch_d50);
}

}  // namespace

TEST_CASE("every committed reference run passes the DEM contract and records its wall and shear",
          "[comparison][reference]") {
  int runs = 0;
  double pair_R_n[2] = {-1.0, -1.0};  // R_n 0.5 at d50 2 mm and 1 mm: the same wall in mm
  for (const auto* sweep : {"reference_rn", "reference_d50"}) {
    for (const auto& entry : fs::directory_iterator(kReference / sweep / "runs")) {
      const std::string job = entry.path().filename().string();
      INFO(entry.path().string());
      const auto run = comparison::load_dem_run(entry.path());  // refuses anything incomplete
      ++runs;
      CHECK(run.status == "complete");
      CHECK(run.R_n == Approx(expected_R_n(job)).margin(1e-9));
      if (job.rfind("sawtooth-2-0.5_", 0) == 0) pair_R_n[0] = run.R_n;
      if (job.rfind("d1_", 0) == 0) pair_R_n[1] = run.R_n;
      // sheared the same number of grain diameters: 4 mm of 2 mm grains, 2 mm of 1 mm grains
      CHECK(run.u_x_mm.back() == Approx(2.0 * run.d50_mm).margin(0.02 * run.d50_mm));
      CHECK(run.summary.is_object());
    }
  }
  // every job the committed sweeps record as complete is committed, and nothing else
  int complete_jobs = 0;
  for (const auto* sweep : {"reference_rn", "reference_d50"}) {
    const auto s = nlohmann::json::parse(io::read_file(kReference / sweep / "sweep.json"));
    for (const auto& job : s["jobs"]) complete_jobs += job["status"] == "complete";
  }
  CHECK(runs == complete_jobs);
  CHECK(runs >= 24);
  CHECK(pair_R_n[0] == Approx(0.5));
  CHECK(pair_R_n[1] == Approx(pair_R_n[0]));
}
