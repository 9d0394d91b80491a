// Measured walls from files: a tilted sawtooth written as a line profile tiles the box as the
// sawtooth itself (the tilt is the straight line through the window's ends, and it goes); a map
// is cut to the box; files that cannot be used are refused naming the file and the row.
#include <fmt/core.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "common/errors.hpp"
#include "walls/descriptors.hpp"
#include "walls/measured_surface.hpp"

using namespace iwb;
using namespace iwb::walls;
namespace fs = std::filesystem;

namespace {
constexpr double kGrain = 2e-3;

fs::path written_file(const std::string& name, const std::string& text) {
  const fs::path p = fs::temp_directory_path() / ("iwb_measured_" + name);
  std::ofstream(p) << text;
  return p;
}

// A sawtooth of pitch 4 mm and height 1 mm sampled every 0.01 mm from x0 over `span` mm, tilted by
// `tilt` mm per mm.
std::string tilted_sawtooth(double x0, double span, double tilt) {
  std::string s = "# a test profile\nx_mm,z_mm\n";
  for (int i = 0; i <= int(std::lround(span / 0.01)); ++i) {
    const double x = x0 + 0.01 * i, u = std::fmod(x, 4.0);
    s += fmt::format("{:.4f},{:.9f}\n", x, (u < 2.0 ? u : 4.0 - u) / 2.0 + tilt * x);
  }
  return s;
}

std::string measured_refusal(const MeasuredSurfaceSpec& spec) {
  try {
    measured_surface(spec, 24e-3, 8e-3, kGrain);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}
}  // namespace

TEST_CASE(
    "a tilted sawtooth read as a line profile is the sawtooth again: the tilt goes, the "
    "descriptors stay",
    "[walls]") {
  const auto file = written_file("saw.csv", tilted_sawtooth(0.0, 40.0, 0.02));
  const auto m =
      measured_surface({file.string(), MeasuredLayout::kLine, 0.0, 8e-3, 1.0}, 24e-3, 8e-3, kGrain);
  const auto map = std::make_shared<const HeightMap>(m.map);
  const auto r =
      describe_roughness({ProfileKind::kFile, 0.0, map->max(), map}, 24e-3, 8e-3, kGrain);
  const double h = 1e-3, p = 4e-3;  // R_a = h/4, R_q = h/sqrt 12, slope 2h/p, R_n = 2h d50/p / d50
  CHECK(r.R_a_m == Approx(h / 4).epsilon(1e-3));
  CHECK(r.R_q_m == Approx(h / std::sqrt(12.0)).epsilon(1e-3));
  CHECK(r.mean_abs_slope == Approx(2 * h / p).epsilon(1e-3));
  CHECK(r.R_n == Approx(0.5).epsilon(1e-3));
  CHECK(m.map.node(3, 0) == m.map.node(3, 2));  // extruded along y
  CHECK(m.window_r_max_m / kGrain ==
        Approx(0.5 + 0.02 * kGrain / kGrain).epsilon(2e-3));  // the tilt was in it
}

TEST_CASE("a height map is cut to the box from its offset and tiles it in x and y", "[walls]") {
  std::string text = "# heights in mm\n";
  for (int j = 0; j < 50; ++j) {
    for (int i = 0; i < 150; ++i)
      text += fmt::format("{}{:.6f}", i ? "," : "",
                          0.3 * std::sin(2 * M_PI * i * 0.2 / 4.0) + 0.001 * i + 0.002 * j);
    text += "\n";
  }
  const auto file = written_file("map.csv", text);
  const auto m = measured_surface({file.string(), MeasuredLayout::kMap, 0.2e-3, 2e-3, 1.0}, 24e-3,
                                  8e-3, kGrain);
  CHECK(m.map.nx() == 120);
  CHECK(m.map.ny() == 40);
  CHECK(m.map.min() == Approx(0.0).margin(1e-15));
  // the sinusoid's whole periods fill the box: its peak-to-valley stays, the tilts go
  CHECK(m.map.max() - m.map.min() == Approx(0.6e-3).epsilon(1e-3));
}

TEST_CASE("measured surfaces that cannot be used are refused naming the file and the row",
          "[walls]") {
  const auto line = [](const std::string& name, const std::string& text) {
    return MeasuredSurfaceSpec{written_file(name, text).string(), MeasuredLayout::kLine, 0.0, 0.0,
                               1.0};
  };
  CHECK_THAT(measured_refusal(line("nan.csv", "x_mm,z_mm\n0,0\n0.1,nan\n")),
             Catch::Contains("nan.csv:3: column 2 is \"nan\""));
  CHECK_THAT(measured_refusal(line("text.csv", "x_mm,z_mm\n0,0\n0.1,high\n")),
             Catch::Contains("text.csv:3:"));
  CHECK_THAT(measured_refusal(line("back.csv", "x_mm,z_mm\n0,0\n0.1,0\n0.05,0\n")),
             Catch::Contains("back.csv:4: x_mm = 0.05 does not increase"));
  CHECK_THAT(measured_refusal(line("header.csv", "x,z\n0,0\n")),
             Catch::Contains("header.csv:1: the header is \"x,z\""));
  CHECK_THAT(measured_refusal(line("short.csv", tilted_sawtooth(0.0, 20.0, 0.0))),
             Catch::Contains("the profile spans 20 mm; from offset_mm = 0 the box needs 24 mm"));
  CHECK_THAT(measured_refusal(line("coarse.csv", "x_mm,z_mm\n0,0\n1,0.1\n2,0\n30,0\n")),
             Catch::Contains("coarser than d50/4"));
  CHECK_THAT(measured_refusal({"/nonexistent/profile.csv", MeasuredLayout::kLine, 0.0, 0.0, 1.0}),
             Catch::Contains("no such file"));
  CHECK_THAT(measured_refusal({written_file("ragged.csv", "0,1,2\n0,1\n").string(),
                               MeasuredLayout::kMap, 0.2e-3, 0.0, 1.0}),
             Catch::Contains("ragged.csv:2: 2 heights; the first row has 3"));
  CHECK_THAT(measured_refusal({written_file("small.csv", "0,1,2\n0,1,2\n").string(),
                               MeasuredLayout::kMap, 0.2e-3, 0.0, 1.0}),
             Catch::Contains("needs 121 x 41 heights"));
}
