// Derived quantities on synthetic contract tables whose answers are known.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "dem/analysis/summary.hpp"
#include "io/csv_table.hpp"
#include "io/run_directory.hpp"

using namespace iwb;

namespace {
dem::Scene scene() {
  return dem::parse_scene(io::read_file("data/scenes/smoke.toml"), "smoke.toml");
}

io::CsvTable series(double peak, double residual, double drift) {
  io::CsvTable t;
  t.columns = {"t_s", "u_x_mm", "u_n_mm", "sigma_n_kPa", "tau_kPa"};
  for (int i = 0; i <= 100; ++i) {
    const double u = 0.05 * i;  // 5 mm
    const double mu =
        u < 1.0 ? peak * u
                : (u < 2.0 ? peak - (peak - residual) * (u - 1.0) : residual + drift * (u - 2.0));
    t.rows.push_back({0.01 * i, u, 0.05 * u, 50.0, 50.0 * mu});
  }
  return t;
}

io::CsvTable profile(const std::function<double(double)>& v, double height) {
  io::CsvTable t;
  t.columns = {"u_x_mm_window", "z_over_d50",   "vx_over_vwall",
               "porosity",      "sigma_zz_kPa", "tau_zx_kPa"};
  for (double z = 0.25; z < height; z += 0.5) t.rows.push_back({4.0, z, v(z), 0.4, 50, 30});
  return t;
}
}  // namespace

TEST_CASE("peak, residual and the steadiness verdict", "[dem]") {
  const auto steady = dem::summarize(scene(), series(0.8, 0.6, 0.0), {});
  CHECK(steady.peak_friction == Approx(0.8));
  CHECK(steady.u_x_at_peak_mm == Approx(1.0));
  CHECK(steady.end_friction == Approx(0.6));
  CHECK(steady.steady());
  CHECK(steady.dilatancy_angle_deg == Approx(std::atan(0.05) * 180 / M_PI));
  // a friction still falling in a straight line at 0.05 per mm from 2 mm to the end (0.45 at 5 mm)
  // has no end in sight: whatever decay describes it has far more than 2.5 % of the last fifth's
  // mean (0.46) still to go
  const auto drifting = dem::summarize(scene(), series(0.8, 0.6, -0.05), {});
  CHECK_FALSE(drifting.steady());
  CHECK(dem::to_json(drifting)["residual_is"] == "not steady");
}

TEST_CASE(
    "the dilatancy rate at the peak is the slope within half a grain of it, with the blocks' "
    "interval",
    "[dem]") {
  // d50 2 mm: the span is the peak at 6 mm +- 1 mm, in 8 blocks of 0.25 mm. u_n = 0.2 u - 0.01 u^2
  // has the rate 0.2 - 0.02 u. Each block's slope is the rate at its rows' centre (rows every
  // 0.05 mm: 5.10, 5.35, ... 6.60, and 6.875 for the last block, which keeps its end row): their
  // mean 5.9781 gives 0.080438, their SD 0.61752 a slope SD of 0.012350 and a 95 % half-width of
  // t_{0.975,7} 0.012350 / sqrt 8 = 0.010325.
  io::CsvTable t;
  t.columns = {"t_s", "u_x_mm", "u_n_mm", "sigma_n_kPa", "tau_kPa"};
  for (int i = 0; i <= 400; ++i) {
    const double u = 0.05 * i;
    const double mu = u < 6.0 ? 0.1 * u : 0.6 - 0.01 * (u - 6.0);
    t.rows.push_back({0.01 * i, u, 0.2 * u - 0.01 * u * u, 50.0, 50.0 * mu});
  }
  const auto s = dem::summarize(scene(), t, {});
  REQUIRE(s.rate_at_peak);
  CHECK(s.rate_at_peak->blocks == 8);
  CHECK(s.rate_at_peak->from == Approx(5.0));
  CHECK(s.rate_at_peak->rate == Approx(0.080438).epsilon(1e-4));
  CHECK(s.rate_at_peak->half_width == Approx(0.010325).epsilon(1e-3));
  const auto j = dem::to_json(s);
  CHECK(j["dilatancy_rate_at_peak"]["ci95"].get<double>() == Approx(s.rate_at_peak->half_width));
}

TEST_CASE("a cyclic run's end state is named apart from a residual", "[dem]") {
  // a committed cyclic run (flat wall, CV, 10 cycles of 1 mm, then 5 mm of post-cyclic shear):
  // its summary names the end-of-path friction and the last cycle's mean, and no residual; the
  // last cycle's mean is recomputed here from the rows of its travel, 9 A 4 .. 10 A 4 (v t)
  const std::filesystem::path dir = "data/cyclic/cyclic_flat_cv/runs/flat_cv_s2";
  const auto manifest = nlohmann::json::parse(io::read_file(dir / "manifest.json"));
  const auto sc = dem::parse_scene(manifest["scene"]["text"].get<std::string>(), "manifest.json");
  REQUIRE(sc.shear.cyclic());
  const auto ts = io::read_csv_table(dir / "timeseries.csv");
  const auto j = dem::to_json(dem::summarize(sc, ts, io::read_csv_table(dir / "profiles.csv")));
  CHECK_FALSE(j.contains("residual_friction"));
  CHECK_FALSE(j.contains("residual_is"));
  REQUIRE(j.contains("end_of_path_friction"));
  const double A = sc.shear.amplitude_m * 1e3, v = sc.shear.velocity_m_s * 1e3;
  const auto time = ts.values("t_s"), tau = ts.values("tau_kPa"), sigma = ts.values("sigma_n_kPa");
  const double from = 4.0 * A * (sc.shear.cycles - 1), to = 4.0 * A * sc.shear.cycles;
  double sum = 0.0;
  int n = 0;
  for (std::size_t i = 0; i < time.size(); ++i) {
    const double s = v * (time[i] - time.front());
    if (s >= from && s <= to) sum += std::abs(tau[i] / sigma[i]), ++n;
  }
  REQUIRE(n > 100);
  CHECK(j["last_cycle_mean_friction"].get<double>() == Approx(sum / n).epsilon(0.01));
}

TEST_CASE(
    "the residual is the last fifth of the travel: a curve that softens and stops dilating at 3.9 "
    "of 5 mm",
    "[dem]") {
  // friction 0.7 and u_n rising at 0.1 per mm until u_x = 3.875 mm, then friction 0.5 and u_n
  // constant: over the last fifth (4..5 mm) the residual is 0.5, steady, with dilatancy angle 0;
  // a longer window would take in the 0.7 and the rise.
  io::CsvTable t;
  t.columns = {"t_s", "u_x_mm", "u_n_mm", "sigma_n_kPa", "tau_kPa"};
  for (int i = 0; i <= 100; ++i) {
    const double u = 0.05 * i;
    const bool before = u < 3.875;
    t.rows.push_back({0.01 * i, u, 0.1 * std::min(u, 3.875), 50.0, 50.0 * (before ? 0.7 : 0.5)});
  }
  const auto s = dem::summarize(scene(), t, {});
  CHECK(s.end_friction == Approx(0.5).epsilon(1e-12));
  CHECK(s.dilatancy_angle_deg == Approx(0.0).margin(1e-9));
  CHECK(s.peak_friction == Approx(0.7));
  CHECK(s.dilation_mm == Approx(0.3875));
}

TEST_CASE("a localised profile gives its band, a linear one is distributed shear", "[dem]") {
  // erfc profile centred 4 d50 above the wall, width w = 2 d50: 0.9 -> 0.1 spans 3.62 d50
  const auto band =
      dem::summarize(scene(), series(0.8, 0.6, 0),
                     profile([](double z) { return 0.5 * std::erfc((z - 4.0) / 2.0); }, 20.0));
  REQUIRE(band.shear_mode == "localised at the wall");
  CHECK(band.far_field_speed == Approx(0.0).margin(0.01));
  CHECK(band.band_thickness_erf_d50.value() == Approx(3.62).epsilon(0.05));
  CHECK(band.band_thickness_d50.value() == Approx(3.62).margin(0.6));  // bin resolution 0.5 d50
  CHECK(band.wall_slip == Approx(1.0 - 0.5 * std::erfc(-3.5 / 2.0)).margin(0.02));
  CHECK(band.e_band.value() == Approx(0.4 / 0.6));
  const auto linear = dem::summarize(scene(), series(0.8, 0.6, 0),
                                     profile([](double z) { return 1.0 - z / 20.0; }, 20.0));
  CHECK(linear.shear_mode == "distributed shear");
  CHECK_FALSE(linear.band_thickness_d50.has_value());
}

TEST_CASE(
    "shear split between the wall and the plate: no 0.9 -> 0.1 band, a wall band to the plateau",
    "[dem]") {
  // half the velocity drop next to the wall (width 1 d50 at z = 2), half next to the plate (z = 18)
  const auto split = dem::summarize(scene(), series(0.8, 0.6, 0),
                                    profile(
                                        [](double z) {
                                          return 0.5 + 0.5 * 0.5 * std::erfc((z - 2.0) / 1.0) -
                                                 0.5 * 0.5 * std::erfc((18.0 - z) / 1.0);
                                        },
                                        20.0));
  CHECK(split.shear_mode == "split between wall and plate");
  CHECK(split.far_field_speed == Approx(0.5).margin(0.02));
  CHECK_FALSE(split.band_thickness_d50.has_value());  // the far field moves: undefined
  REQUIRE(split.wall_band_d50.has_value());
  CHECK(split.wall_band_d50.value() == Approx(2.0 + 0.906).margin(0.5));
}

// The summary is computed from the engine's tables in memory and recomputed from profiles.csv,
// whose numbers carry 10 digits. A bin centre on the middle third's upper bound (14 of a 21 d50
// profile) that reads 14.0000000001 in memory must count as the 14 the file says, else the
// far-field median moves to the next bin (seen in a truth run: far field 0.083 against 0.062).
TEST_CASE("bin heights within round-off of the middle third's bound give one summary", "[dem]") {
  auto table = [](double upper_bound_bin) {
    io::CsvTable t;
    t.columns = {"u_x_mm_window", "z_over_d50",   "vx_over_vwall",
                 "porosity",      "sigma_zz_kPa", "tau_zx_kPa"};
    for (int k = 1; k <= 42; ++k) {
      const double z =
          0.5 * k == 14.0 ? upper_bound_bin : 0.5 * k;  // the top bin, 21 d50, sets the height
      t.rows.push_back({4.0, z, std::exp(-z / 3.0), 0.4, 50, 30});
    }
    return t;
  };
  const auto from_file = dem::summarize(scene(), series(0.8, 0.6, 0.0), table(14.0));
  const auto in_memory = dem::summarize(scene(), series(0.8, 0.6, 0.0), table(14.0 + 1e-10));
  // the middle third 7..14 d50: 15 bins, the median is the bin at 10.5 d50, relative to the first
  // layer's mean (the bins at 0.5 and 1 d50)
  const double first = 0.5 * (std::exp(-0.5 / 3.0) + std::exp(-1.0 / 3.0));
  CHECK(from_file.far_field_speed == Approx(std::exp(-10.5 / 3.0) / first));
  CHECK(in_memory.far_field_speed == from_file.far_field_speed);
  CHECK(in_memory.e_band == from_file.e_band);
}
