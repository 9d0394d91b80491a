// A looser specimen than sliding friction alone can make ([specimen]
// consolidation_rolling_friction). Frictional spheres that come together under a load stop at
// random loose packing (solid fraction ~0.55, e ~0.8) however high their friction: the truth's
// specimen sits at e 0.81 after consolidation friction 1, 3 or 10 alike (data/grains/README.md).
// Resistance to rolling lets grains lock in arches that sliding friction would let roll apart,
// so packings assembled with it are looser (random packings of spheres with rolling resistance:
// solid fractions down to ~0.5). The test friction of the shear stage stays the grains' own.
// Whatever the preparation, the shear stage starts once the specimen has settled at the test's
// contacts (both engines: shear.in, interface_shear.py's settle).
#include <catch2/catch.hpp>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "dem/engines/engines.hpp"
#include "dem/run/run.hpp"
#include "io/csv_table.hpp"
#include "io/run_directory.hpp"
#include "support/smoke_specimens.hpp"

using namespace iwb;
namespace fs = std::filesystem;

namespace {

// The smoke scene prepared with consolidation friction 1 (and the given rolling resistance while
// consolidating, if any), sheared over 0.1 mm (the first row holds the specimen's void ratio when
// shear starts). Its 400 grains, locked in arches by rolling resistance, jam and let go: the
// plate's stress swings by +-6 % and never holds the default 2 % for three windows (60 windows
// tried), so both accept 10 %.
std::string prepared_text(const std::string& rolling) {
  const std::string consolidation =
      "consolidation_friction = 1.0" +
      (rolling.empty() ? "" : "\nconsolidation_rolling_friction = " + rolling);
  return test::replaced(test::smoke_sheared_over("data/scenes/smoke.toml", 0.1),
                        "consolidation_friction = 0.1", consolidation) +
         "\n[consolidation]\nsigma_tolerance = 0.1\n";
}

// The grains tested frictionless: they cannot stand in a loose packing at all and settle towards
// random close packing (e ~0.56).
std::string tested_frictionless(const std::string& text) {
  return test::replaced(test::replaced(text, "\nfriction = 0.5\n", "\nfriction = 0.0\n"),
                        "\nrolling_friction = 0.1\n", "\nrolling_friction = 0.0\n");
}

fs::path run(const fs::path& dir, const std::string& text, const std::string& engine_name) {
  fs::remove_all(dir);
  const auto engine = dem::make_engine(engine_name);
  const dem::RunOptions opt{dir, 1, false, true, "tests", nullptr, nullptr, {}};
  REQUIRE(dem::run_scene(dem::parse_scene(text, "loose.toml"), text, *engine, opt).complete());
  return dir;
}

nlohmann::json facts(const fs::path& dir, const std::string& stage) {
  return nlohmann::json::parse(io::read_file(dir / "manifest.json"))["stages"][stage]["facts"];
}

// A collapsing specimen: the shear stage waited (settle_windows > 0) and started at sigma_n0 with
// the plate at rest.
void check_settled_collapse(const fs::path& dir) {
  const double windows = facts(dir, "shear")["settle_windows"].get<double>();
  const auto ts = io::read_csv_table(dir / "timeseries.csv");
  const auto sigma = ts.values("sigma_n_kPa"), u_n = ts.values("u_n_mm");
  INFO(dir << ": settled after " << windows << " windows; first row sigma_n " << sigma[0]
           << " kPa; u_n at the end " << u_n.back() << " mm");
  CHECK(windows > 0);
  CHECK(sigma.front() == Approx(50.0).epsilon(0.1));  // the scene's accepted 10 %
  // over 0.1 mm of shear a settled specimen moves the plate by microns, a collapsing one by a
  // good part of a grain (the truth's specimen: -1 mm within the first 0.14 mm)
  CHECK(std::abs(u_n.back()) < 0.05);
}

}  // namespace

// Two smoke specimens prepared with friction 1: one rolls as the grains do (0.1), the other
// resists rolling (0.5) while consolidating and is then tested frictionless. The second must
// consolidate higher (looser), and, since frictionless grains cannot stand in a loose packing at
// all (they settle towards random close packing, e ~0.56), collapse when the test's contacts take
// over.
TEST_CASE("LIGGGHTS: a looser preparation, and a shear that waits for it to settle",
          "[dem][liggghts][heavy]") {
  const auto base = fs::path(IWB_TEST_RUNS_DIR) / "dem" / "liggghts" / "loose_preparation";
  const auto sliding = run(base / "sliding", prepared_text("0.1"), "liggghts");
  const auto rolling = run(base / "rolling", tested_frictionless(prepared_text("0.5")), "liggghts");
  const double z_sliding = facts(sliding, "consolidate")["zplate_m"].get<double>(),
               z_rolling = facts(rolling, "consolidate")["zplate_m"].get<double>();
  INFO("plate after consolidation with rolling resistance 0.1: " << z_sliding << " m, 0.5: "
                                                                 << z_rolling << " m");
  // the truth's specimen: plate 46.9 -> 49.9 mm (+6 %, e 0.81 -> ~0.93); this one 15.65 -> 16.14 mm
  // (+3.1 %, plate teeth included); half that gain is asked
  CHECK(z_rolling > 1.015 * z_sliding);
  check_settled_collapse(rolling);
  // the rolling resistance of consolidation only: the shear stage rolls as the grains do
  const std::string consolidate_in = io::read_file(rolling / "liggghts" / "consolidate.in");
  CHECK(consolidate_in.find("coefficientRollingFriction peratomtypepair 1 0.5") !=
        std::string::npos);
  const std::string shear_in = io::read_file(rolling / "liggghts" / "shear.in");
  CHECK(shear_in.find("coefficientRollingFriction peratomtypepair 1 0\n") != std::string::npos);
}

// YADE's shear stage waits for the specimen as LIGGGHTS's does. Its rolling law is one functor for
// every stage (consolidation_rolling_friction is refused), so its loose specimen is one
// consolidated at friction 1 with the grains' own rolling resistance, here none: tested
// frictionless, it must collapse as the LIGGGHTS one does.
// (A lower specimen than the smoke scene's, 250 grains in 5 d50 instead of 400 in 8: the test
// asks for a collapse and a settle, which any height shows, at 60 % of the cost.)
TEST_CASE("YADE: a specimen that collapses at the test's contacts settles before shear starts",
          "[dem][yade][heavy]") {
  const auto dir = fs::path(IWB_TEST_RUNS_DIR) / "dem" / "yade" / "loose_preparation";
  const std::string lower =
      test::replaced(test::replaced(prepared_text(""), "height_d50 = 8\n", "height_d50 = 5\n"),
                     "particles = 400", "particles = 250");
  check_settled_collapse(run(dir, tested_frictionless(lower), "yade"));
}
