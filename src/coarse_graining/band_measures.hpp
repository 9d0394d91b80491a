#pragma once
// What a height profile of the coarse-grained fields says about the run (issue 21), as pure
// functions of the profile so that each is tested on profiles whose answer is known.
#include <cmath>
#include <vector>

namespace iwb::coarse_graining {

struct Span {
  double lo, hi;  // heights, m
};

double mean_over(const std::vector<double>& z, const std::vector<double>& values, Span span);
// (max - min) / |mean| over the span: how far a field is from uniform.
double relative_spread(const std::vector<double>& z, const std::vector<double>& values, Span span);
// Trapezoidal integral over the whole profile (uniform spacing h).
double integral(const std::vector<double>& values, double h);
// Full width at half maximum of the largest peak of `rate` within `search` (the wall's band: the
// lower half of the specimen), interpolated linearly between points; 0 if no peak is positive.
double peak_width_at_half_maximum(const std::vector<double>& z, const std::vector<double>& rate,
                                  Span search);
// The velocity measure of the run summary (DEM.md): from `from` up, the heights where v / v_wall
// first falls below 0.9 and below 0.1; their distance, or a negative value if either is missing.
double velocity_band_width(const std::vector<double>& z, const std::vector<double>& v_over_v_wall,
                           double from);

// Means of `values` in bins of width `bin` stacked from `from` up, sorted into them by `z` (grains
// by their centres, as the engines bin profiles.csv): the kernel-free profile of the same instant
// that a coarse-grained one is checked against. Empty bins are left out; z is each bin's centre.
struct BinnedProfile {
  std::vector<double> z, mean;
};
BinnedProfile bin_means(const std::vector<double>& z, const std::vector<double>& values,
                        double from, double bin);

// For a Gaussian shear-rate peak (an erfc velocity profile) the 0.9 -> 0.1 velocity width is
// 2 x 1.2816 sigma and the FWHM 2 sqrt(2 ln 2) sigma: the ratio 1.0883 turns one into the other.
inline constexpr double kVelocityWidthPerSigma = 2.0 * 1.2815515655446004;
inline constexpr double kVelocityWidthPerFwhm = kVelocityWidthPerSigma / 2.3548200450309493;

// The 0.9 -> 0.1 width that a band of the grains' velocity `width` wide has in a field coarse-
// grained by a Gaussian kernel of standard deviation `kernel_width`: the field is the grains'
// profile convolved with the kernel, and an erfc band of sigma convolved with a Gaussian of w is an
// erfc band of sqrt(sigma^2 + w^2). A step (width 0) appears 2.563 w wide.
inline double coarse_grained_band_width(double width, double kernel_width) {
  const double smear = kVelocityWidthPerSigma * kernel_width;
  return std::sqrt(width * width + smear * smear);
}

}  // namespace iwb::coarse_graining
