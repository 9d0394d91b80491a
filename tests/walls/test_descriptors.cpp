// Roughness descriptors against closed forms: a sawtooth and a sinusoid of height h and pitch p
// have R_a, R_q, mean slope, R_n and spectra known by hand; a random surface made with a Hurst
// exponent gives it back from its spectrum.
#include <catch2/catch.hpp>
#include <cmath>
#include <memory>

#include "walls/descriptors.hpp"
#include "walls/random_surface.hpp"

using namespace iwb::walls;

namespace {
constexpr double kD50 = 1e-3;

double share_at(const RoughnessDescriptors& r, double wavelength) {
  double total = 0.0, at = 0.0, nearest = INFINITY;
  for (const auto& b : r.spectrum) total += b.variance_m2;
  for (const auto& b : r.spectrum)
    if (std::abs(std::log(b.wavelength_m / wavelength)) < nearest)
      nearest = std::abs(std::log(b.wavelength_m / wavelength)), at = b.variance_m2;
  return at / total;
}
}  // namespace

TEST_CASE(
    "sawtooth: R_a = h/4, R_q = h/sqrt 12, slope 2h/p, R_n and its window mean, odd harmonics",
    "[walls]") {
  const double h = 0.5 * kD50, p = 2.0 * kD50;
  const RoughnessProfile saw{ProfileKind::kSawtooth, p, h};
  const auto r = describe_roughness(saw, 24 * kD50, 4 * kD50, kD50);
  CHECK(r.R_a_m == Approx(h / 4).epsilon(1e-3));
  CHECK(r.R_q_m == Approx(h / std::sqrt(12.0)).epsilon(1e-3));
  CHECK(r.mean_abs_slope == Approx(2 * h / p).epsilon(1e-9));
  CHECK(r.R_max_m == Approx(h).epsilon(1e-9));
  CHECK(r.R_n == Approx(0.5).epsilon(1e-9));  // a window of d50 = p/2 spans a whole flank
  // windows straddling an apex (a fraction 2 d50/p of them) span 3/4 of a flank's rise on average:
  // mean R_max(d50) = (2 h d50 / p) (1 - d50 / (2 p))
  CHECK(r.R_n_mean * kD50 == Approx(2 * h * kD50 / p * (1 - kD50 / (2 * p))).epsilon(1e-2));
  // a triangle wave's harmonics fall as 1/n^2: the fundamental holds 96/pi^4 of the variance
  CHECK(share_at(r, p) == Approx(96 / std::pow(M_PI, 4)).epsilon(2e-3));
  double total = 0.0;
  for (const auto& b : r.spectrum) total += b.variance_m2;
  CHECK(total == Approx(r.R_q_m * r.R_q_m).epsilon(1e-9));  // Parseval
  CHECK_FALSE(r.hurst.has_value());
}

TEST_CASE(
    "sinusoid: R_a = h/pi, R_q = h/(2 sqrt 2), slope 2h/p, R_n = h sin(pi d50/p)/d50, one "
    "wavelength",
    "[walls]") {
  const double h = 0.4 * kD50, p = 4.0 * kD50;
  const RoughnessProfile sine{ProfileKind::kSinusoid, p, h};
  const auto r = describe_roughness(sine, 24 * kD50, 4 * kD50, kD50);
  CHECK(r.R_a_m == Approx(h / M_PI).epsilon(1e-3));
  CHECK(r.R_q_m == Approx(h / (2 * std::sqrt(2.0))).epsilon(1e-6));
  CHECK(r.mean_abs_slope == Approx(2 * h / p).epsilon(1e-3));
  CHECK(r.R_n == Approx(h * std::sin(M_PI * kD50 / p) / kD50).epsilon(1e-3));
  CHECK(share_at(r, p) == Approx(1.0).epsilon(1e-9));
  CHECK_FALSE(r.hurst.has_value());
}

TEST_CASE("a flat wall has no roughness", "[walls]") {
  const auto r = describe_roughness(RoughnessProfile{}, 24 * kD50, 4 * kD50, kD50);
  CHECK(r.R_n == 0.0);
  CHECK(r.R_q_m == 0.0);
  CHECK(r.spectrum.empty());
}

TEST_CASE(
    "a random self-affine surface: its RMS as asked, periodic, and its Hurst exponent back from "
    "the spectrum",
    "[walls]") {
  const double length = 128 * kD50, width = 32 * kD50;
  for (double H : {0.5, 0.8}) {
    INFO("H = " << H);
    // roll-off at wavelength 2 pi xi = L/2: self-affine from there down to the grid
    const RandomSurfaceSpec spec{0.2 * kD50, length / (4 * M_PI), H, 7};
    const auto map =
        std::make_shared<const HeightMap>(random_surface(spec, length, width, 0.25 * kD50));
    double square = 0.0, mean = map->mean();
    for (int j = 0; j < map->ny(); ++j)
      for (int i = 0; i < map->nx(); ++i) square += std::pow(map->node(i, j) - mean, 2);
    CHECK(std::sqrt(square / (map->nx() * map->ny())) == Approx(0.2 * kD50).epsilon(1e-9));
    CHECK(map->min() == Approx(0.0).margin(1e-15));
    CHECK(map->at(0.3 * kD50, 0.1 * kD50) ==
          Approx(map->at(0.3 * kD50 + length, 0.1 * kD50 - width)).epsilon(1e-12));
    const RoughnessProfile wall{ProfileKind::kRandom, 0.0, map->max(), map};
    const auto r = describe_roughness(wall, length, width, kD50);
    REQUIRE(r.hurst.has_value());
    CHECK(*r.hurst == Approx(H).margin(0.1));
  }
}
