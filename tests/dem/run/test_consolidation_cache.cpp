// Consolidate once, shear many (issue 20 item 2): the consolidation key follows exactly what the
// consolidation reads; a run that differs from a cached one only in the shear stage starts from
// its specimen and ends with the results of a run that consolidated itself; a corrupt cached
// specimen is rebuilt, never used.
#include <catch2/catch.hpp>
#include <filesystem>

#include "dem/engines/engines.hpp"
#include "dem/run/consolidation_cache.hpp"
#include "dem/run/run.hpp"
#include "io/checksum_record.hpp"
#include "io/run_directory.hpp"
#include "support/replaced.hpp"
#include "support/smoke_specimens.hpp"

using namespace iwb;
using iwb::test::replaced;
namespace fs = std::filesystem;

namespace {

std::string key_of(const dem::Engine& engine, const std::string& text) {
  return dem::consolidation_key(engine, dem::parse_scene(text, "smoke variant"));
}

void key_follows_consolidation(const std::string& engine_name) {
  const auto engine = dem::make_engine(engine_name);
  const std::string smoke = io::read_file("data/scenes/smoke.toml");
  const std::string key = key_of(*engine, smoke);
  // the shear stage and what is only written: the same specimen
  for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{
           {"type = \"CNL\"", "type = \"CNS\"\nK_kPa_per_mm = 50"},
           {"type = \"CNL\"", "type = \"CV\""},
           {"inertial_number = 1e-3", "inertial_number = 5e-4"},
           {"displacement_mm = 2.0", "displacement_mm = 4.0"},
           {"timeseries_every_mm = 0.02", "timeseries_every_mm = 0.05"},
           {"friction = 0.5", "friction = 0.4"},  // the test friction, set after consolidation
           {"description = \"smoke:", "description = \"another smoke:"}}) {
    INFO(to);
    CHECK(key_of(*engine, replaced(smoke, from, to)) == key);
  }
  // what the consolidation reads: another specimen
  for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{
           {"seed = 1", "seed = 2"},
           {"sigma_n_kPa = 50", "sigma_n_kPa = 60"},
           {"height_d50 = 0.5", "height_d50 = 1.0"},  // the wall under test
           {"consolidation_friction = 0.1", "consolidation_friction = 0.2"},
           {"youngs_modulus_Pa = 1.0e8", "youngs_modulus_Pa = 2.0e8"},
           {"particles = 400", "particles = 420"}}) {
    INFO(to);
    CHECK(key_of(*engine, replaced(smoke, from, to)) != key);
  }
  if (engine_name == "liggghts") {  // YADE refuses a rolling resistance of consolidation's own
    CHECK(key_of(*engine, replaced(smoke, "consolidation_friction = 0.1",
                                   "consolidation_friction = 0.1\n"
                                   "consolidation_rolling_friction = 0.5")) != key);
  }
  CHECK(key != key_of(*dem::make_engine(engine_name == "yade" ? "liggghts" : "yade"), smoke));
}

dem::RunOptions reusing(const fs::path& dir) {
  return {dir, 1, false, true, "tests", nullptr, nullptr, dir.parent_path() / "consolidated"};
}

nlohmann::json manifest_of(const fs::path& dir) {
  return nlohmann::json::parse(io::read_file(dir / "manifest.json"));
}

}  // namespace

TEST_CASE("LIGGGHTS: the consolidation key follows what consolidation reads, not the shear stage",
          "[dem][liggghts]") {
  key_follows_consolidation("liggghts");
}
TEST_CASE("YADE: the consolidation key follows what consolidation reads, not the shear stage",
          "[dem][yade]") {
  key_follows_consolidation("yade");
}

TEST_CASE(
    "LIGGGHTS: a CNS run after a CNL run of the same scene does not consolidate, with the results "
    "of one "
    "that did, and a corrupt cached specimen is rebuilt",
    "[dem][liggghts][heavy]") {
  const fs::path root = fs::path(IWB_TEST_RUNS_DIR) / "dem" / "liggghts" / "consolidate_once";
  fs::remove_all(root);
  const auto engine = dem::make_engine("liggghts");
  const auto run = [&](const std::string& file, const std::string& name) {
    // half a millimetre of shear: what is compared is the specimen each run starts from
    const std::string text = test::smoke_sheared_over(file, 0.5);
    const auto outcome =
        dem::run_scene(dem::parse_scene(text, file), text, *engine, reusing(root / name));
    REQUIRE(outcome.complete());
    return outcome.manifest["stages"]["consolidate"]["consolidation"];
  };
  const auto cnl = run("data/scenes/smoke.toml", "cnl");
  CHECK(cnl["reused"] == false);
  const fs::path entry = root / "consolidated" / cnl["key"].get<std::string>();
  CHECK(fs::path(cnl["entry"].get<std::string>()) == entry);
  REQUIRE_FALSE(io::checksum_problem(entry / "consolidated.restart"));

  const auto cns = run("data/scenes/smoke_cns.toml", "cns");
  CHECK(cns["reused"] == true);
  CHECK(cns["key"] == cnl["key"]);
  CHECK_THAT(cns["consolidated_in"].get<std::string>(), Catch::EndsWith("cnl"));
  CHECK_FALSE(fs::exists(root / "cns" / "liggghts" /
                         "log.consolidate.liggghts"));  // LIGGGHTS never consolidated here
  CHECK(manifest_of(root / "cns")["stages"]["consolidate"]["facts"]["particles"] == 400);

  // the cached restart cut short: not used; this run consolidates itself and repairs the entry
  fs::resize_file(entry / "consolidated.restart", 1000);
  const auto rebuilt = run("data/scenes/smoke_cns.toml", "cns_rebuilt");
  CHECK(rebuilt["reused"] == false);
  CHECK_THAT(rebuilt.value("rebuilt_because", ""),
             Catch::Contains("has 1000 bytes, its record says"));
  CHECK(fs::exists(root / "cns_rebuilt" / "liggghts" / "log.consolidate.liggghts"));
  CHECK_FALSE(io::checksum_problem(entry / "consolidated.restart"));
  // one rank: LIGGGHTS is deterministic, so the shear from the reused specimen is the same bytes
  // as the shear of the run that consolidated itself
  CHECK(io::read_file(root / "cns" / "timeseries.csv") ==
        io::read_file(root / "cns_rebuilt" / "timeseries.csv"));
  CHECK(io::read_file(root / "cns" / "summary.json") ==
        io::read_file(root / "cns_rebuilt" / "summary.json"));
}
