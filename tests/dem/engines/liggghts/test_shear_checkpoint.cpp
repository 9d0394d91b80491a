// A LIGGGHTS shear stage stopped part-way resumes from its last checkpoint
// (src/dem/engines/liggghts/shear_checkpoint.hpp). The reference is the same scene run without a
// stop: on one rank LIGGGHTS is deterministic, so the stopped attempt is that run up to the stop,
// and the resumed attempt must carry on from the state the checkpoint holds: a wall mesh put back
// at its starting place, contacts that forgot their tangential history or a servo restarted from
// rest would show in the first row after the checkpoint as a jump of tau or sigma_n of the order of
// the values themselves.
#include <atomic>
#include <catch2/catch.hpp>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

#include "dem/engines/contract_outputs.hpp"
#include "dem/engines/engines.hpp"
#include "dem/engines/liggghts/shear_checkpoint.hpp"
#include "dem/run/run.hpp"
#include "dem/scene/numerics.hpp"
#include "io/csv_table.hpp"
#include "io/run_directory.hpp"
#include "support/smoke_specimens.hpp"

using namespace iwb;
namespace fs = std::filesystem;

namespace {

dem::Numerics numerics(long shear_steps, long profile_every, long profile_repeat) {
  dem::Numerics n{};
  n.shear_steps = shear_steps;
  n.profile_every = profile_every;
  n.profile_repeat = profile_repeat;
  return n;
}

bool divides(long d, long n) {
  return n % d == 0;
}

}  // namespace

TEST_CASE("shear checkpoints lie on divisors of the profile period, about 1/50 of the shear apart",
          "[dem][liggghts]") {
  // C_u 2.2 scene: 484540 shear steps, profiles every 96900 = 2^2 3 5^2 17 19 steps: 1/50 of the
  // shear is 9690, and 96900 / 10 = 9690 is the largest divisor not beyond it
  CHECK(dem::checkpoint_every(numerics(484540, 96900, 100)) == 9690);
  // cyclic smoke scene: 37856 steps, profiles every 18920 = 2^3 5 11 43: 1/50 is 757, below the
  // 1000-step floor; the divisors from 1000 up are 1720, 1892, 2365, ...: the smallest, 1720
  CHECK(dem::checkpoint_every(numerics(37856, 18920, 100)) == 1720);
  // a prime period has no divisor between 1000 and itself: the period
  CHECK(dem::checkpoint_every(numerics(200000, 10007, 100)) == 10007);
  // whatever the numbers: a divisor of the period, never below the sampling window
  for (const long period : {20000L, 30030L, 99990L, 123450L}) {
    const long c = dem::checkpoint_every(numerics(50 * period, period, 100));
    CHECK(divides(c, period));
    CHECK(c >= 1000);
  }
}

TEST_CASE("a resumed attempt's rows replace the stopped attempt's rows from the same time on",
          "[dem]") {
  const std::string file = "data/scenes/smoke.toml";
  const auto scene = dem::parse_scene(io::read_file(file), file);
  const auto n = dem::derive(scene);
  const fs::path raw = fs::path(IWB_TEST_RUNS_DIR) / "dem" / "later_wins" / "timeseries.raw";
  fs::create_directories(raw.parent_path());
  const auto row = [](double t, double tau) {
    return fmt::format("{} 0 0.02 50000 {} 50000 1e-6 1e-6 5 400 0\n", t, tau);
  };
  // the stopped attempt wrote t = 0..4, the checkpoint was at t = 2, the resumed one writes 3..5
  io::write_atomically(raw, "t_s ux_m ...\n" + row(0, 0) + row(1, 10) + row(2, 20) + row(3, 30) +
                                row(4, 40) + row(3, 31) + row(4, 41) + row(5, 51));
  const auto t = dem::timeseries_table(scene, n, raw, 0.02);
  REQUIRE(t.rows.size() == 6);
  CHECK(t.rows[2][4] == Approx(0.020));  // kPa: the rows before the checkpoint stay
  CHECK(t.rows[3][4] == Approx(0.031));  // the resumed attempt's
  CHECK(t.rows[5][4] == Approx(0.051));
}

TEST_CASE("LIGGGHTS: a shear stage stopped after a checkpoint resumes from it, not from the start",
          "[dem][liggghts]") {
  // 1 mm of the smoke scene: a checkpoint every 1470 steps, the first at u_x ~0.1 mm, where tau
  // is still rising (the resumed run by hand: the cyclic scene at +-A, CNS, CV, a clamp, a glued
  // wall and two ranks, src/dem/README.md)
  const std::string file = "data/scenes/smoke.toml";
  const std::string text = test::smoke_sheared_over(file, 1.0);
  const auto scene = dem::parse_scene(text, file);
  const fs::path base = fs::path(IWB_TEST_RUNS_DIR) / "dem" / "liggghts" / "checkpoint";
  const auto engine = dem::make_engine("liggghts");
  const dem::RunOptions whole{base / "whole", 1,       false,   true,
                              "tests",        nullptr, nullptr, test::smoke_specimens()};
  REQUIRE(dem::run_scene(scene, text, *engine, whole).complete());

  // stopped as soon as the first checkpoint is there
  std::atomic<bool> stop{false};
  const fs::path dir = base / "stopped";
  const fs::path work = dir / "liggghts";
  fs::remove_all(dir);
  std::thread watcher([&] {
    while (!stop && !fs::exists(work / dem::kShearCheckpoint))
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    stop = true;
  });
  dem::RunOptions first{dir, 1, false, true, "tests", &stop, nullptr, test::smoke_specimens()};
  const auto stopped = dem::run_scene(scene, text, *engine, first);
  stop = true;
  watcher.join();
  REQUIRE(stopped.status == "interrupted at stage shear");
  // as if killed while writing a row: half of one, no newline
  std::ofstream(work / "timeseries.raw", std::ios::app) << "0.0291 0.00012 0.0143";

  const dem::RunOptions again{dir, 1, true, false, "tests", nullptr, nullptr, {}};
  const auto resumed = dem::run_scene(scene, text, *engine, again);
  INFO(resumed.status);
  REQUIRE(resumed.complete());
  const auto& facts = resumed.manifest["stages"]["shear"]["facts"];
  REQUIRE(facts.contains("resumed_at_step"));
  const long step0 = facts["step0"], at = std::lround(facts["resumed_at_step"].get<double>());
  CHECK(at > step0);

  const auto ref = io::read_csv_table(base / "whole" / "timeseries.csv");
  const auto got = io::read_csv_table(dir / "timeseries.csv");
  REQUIRE(got.rows.size() == ref.rows.size());
  const double t_resumed =
      double(at - step0) * resumed.manifest["numerics"]["timestep_s"].get<double>();
  std::size_t first_after = 0;
  for (std::size_t i = 0; i < ref.rows.size(); ++i) {
    CHECK(got.rows[i][0] == Approx(ref.rows[i][0]).margin(1e-12));  // the same output steps
    if (ref.rows[i][0] <= t_resumed + 1e-12) {
      CHECK(got.rows[i] == ref.rows[i]);  // before the checkpoint: the same run
    } else if (first_after == 0) {
      first_after = i;
    }
  }
  REQUIRE(first_after > 0);
  const auto& a = got.rows[first_after];
  const auto& b = ref.rows[first_after];
  INFO("first row after the checkpoint, u_x " << b[1] << " mm: sigma_n " << a[3] << " / " << b[3]
                                              << ", tau " << a[4] << " / " << b[4] << ", u_n "
                                              << a[2] << " / " << b[2]);
  CHECK(std::abs(b[4]) > 1.0);                // the wall is loaded there (kPa)
  CHECK(a[3] == Approx(b[3]).margin(0.5));    // 1 % of sigma_n0 (measured 0.0006 kPa)
  CHECK(a[4] == Approx(b[4]).margin(0.5));    // measured 0.005 kPa of 13.8
  CHECK(a[2] == Approx(b[2]).margin(0.005));  // mm (measured 1e-5)
  // every profile window and snapshot of the whole run
  CHECK(io::read_csv_table(dir / "profiles.csv").rows.size() ==
        io::read_csv_table(base / "whole" / "profiles.csv").rows.size());
  CHECK(resumed.manifest["files"].size() ==
        nlohmann::json::parse(io::read_file(base / "whole" / "manifest.json"))["files"].size());
}
