// The band measures (src/coarse_graining/band_measures.hpp) on profiles whose answer is known in
// closed form: a Gaussian shear-rate peak and the erfc velocity profile it integrates to.
#include <catch2/catch.hpp>
#include <cmath>

#include "coarse_graining/band_measures.hpp"

using namespace iwb::coarse_graining;

namespace {
constexpr double kSigma = 1.5, kCentre = 4.0, kH = 0.01;  // d50 units

struct Profile {
  std::vector<double> z, rate, velocity;
};

// v / v_wall = 1 at the wall, falling through the band: 1 - Phi((z - c) / sigma); its rate is the
// Gaussian density (per unit velocity drop).
Profile gaussian_band() {
  Profile p;
  for (double z = 0.0; z <= 12.0 + 1e-9; z += kH) {
    const double u = (z - kCentre) / kSigma;
    p.z.push_back(z);
    p.rate.push_back(std::exp(-0.5 * u * u) / (std::sqrt(2.0 * M_PI) * kSigma));
    p.velocity.push_back(0.5 * std::erfc(u / std::sqrt(2.0)));
  }
  return p;
}
}  // namespace

TEST_CASE("a Gaussian shear-rate peak has FWHM 2 sqrt(2 ln 2) sigma and unit area",
          "[coarse_graining]") {
  const auto p = gaussian_band();
  CHECK(peak_width_at_half_maximum(p.z, p.rate, {0.0, 6.0}) ==
        Approx(2.0 * std::sqrt(2.0 * std::log(2.0)) * kSigma).epsilon(1e-4));
  CHECK(integral(p.rate, kH) == Approx(0.5 * (std::erf(8.0 / (std::sqrt(2.0) * kSigma)) +
                                              std::erf(4.0 / (std::sqrt(2.0) * kSigma))))
                                    .epsilon(1e-6));
  // outside the search span the peak is not found
  CHECK(peak_width_at_half_maximum(p.z, std::vector<double>(p.z.size(), -1.0), {0.0, 6.0}) == 0.0);
}

TEST_CASE("its erfc velocity profile falls from 0.9 to 0.1 over 2 x 1.2816 sigma, 1.0883 FWHM",
          "[coarse_graining]") {
  const auto p = gaussian_band();
  const double width = velocity_band_width(p.z, p.velocity, 0.0);
  CHECK(width == Approx(2.0 * 1.2815515655446004 * kSigma).epsilon(1e-4));
  CHECK(width == Approx(kVelocityWidthPerFwhm * peak_width_at_half_maximum(p.z, p.rate, {0.0, 6.0}))
                     .epsilon(1e-4));
  // a profile that never falls below 0.1 has no band
  CHECK(velocity_band_width(p.z, std::vector<double>(p.z.size(), 0.5), 0.0) < 0.0);
}

TEST_CASE("a uniform field has no spread and its mean is its value", "[coarse_graining]") {
  const std::vector<double> z{0, 1, 2, 3, 4}, v{7, 7, 7, 7, 7}, ramp{1, 2, 3, 4, 5};
  CHECK(relative_spread(z, v, {1, 3}) == 0.0);
  CHECK(mean_over(z, v, {1, 3}) == 7.0);
  CHECK(relative_spread(z, ramp, {1, 3}) == Approx(2.0 / 3.0));
}

TEST_CASE("grains binned by centre give each bin the mean of its grains, empty bins left out",
          "[coarse_graining]") {
  // bins of 0.5 from 0: [0, 0.5) holds 1 and 3, [0.5, 1) none, [1, 1.5) holds 5; below 0 is not
  // binned
  const auto b = bin_means({0.1, 0.3, 1.2, -0.2}, {1.0, 3.0, 5.0, 100.0}, 0.0, 0.5);
  REQUIRE(b.z.size() == 2);
  CHECK(b.z[0] == Approx(0.25));
  CHECK(b.mean[0] == Approx(2.0));
  CHECK(b.z[1] == Approx(1.25));
  CHECK(b.mean[1] == Approx(5.0));
}

TEST_CASE("grains sampled from an erfc velocity profile and binned keep its 0.9 -> 0.1 width",
          "[coarse_graining]") {
  // 20 grains per 0.5 d50 bin, spread evenly through it. The crossings are interpolated linearly
  // between bin centres h = 0.5 apart, which moves each by up to |v''| h^2 / 8 / |v'| =
  // u h^2 / (8 sigma) at u = 1.2816, and a bin's mean is v + v'' h^2 / 24 at its centre: together
  // u h^2 / (6 sigma) = 0.036 d50 per crossing, so the width stays 2 x 1.2816 sigma within 0.072
  std::vector<double> z, v;
  for (double x = 0.0125; x < 12.0; x += 0.025) {
    z.push_back(x);
    v.push_back(0.5 * std::erfc((x - kCentre) / (kSigma * std::sqrt(2.0))));
  }
  const auto b = bin_means(z, v, 0.0, 0.5);
  CHECK(velocity_band_width(b.z, b.mean, 0.0) ==
        Approx(2.0 * 1.2815515655446004 * kSigma).margin(0.08));
}
