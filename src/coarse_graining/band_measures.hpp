#pragma once
// What a height profile of the coarse-grained fields says about the run (issue 21), as pure
// functions of the profile so that each is tested on profiles whose answer is known.
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
double peak_width_at_half_maximum(const std::vector<double>& z, const std::vector<double>& rate, Span search);
// The velocity measure of the run summary (DEM.md): from `from` up, the heights where v / v_wall
// first falls below 0.9 and below 0.1; their distance, or a negative value if either is missing.
double velocity_band_width(const std::vector<double>& z, const std::vector<double>& v_over_v_wall, double from);

// For a Gaussian shear-rate peak (an erfc velocity profile) the 0.9 -> 0.1 velocity width is
// 2 x 1.2816 sigma and the FWHM 2 sqrt(2 ln 2) sigma: the ratio 1.0883 turns one into the other.
inline constexpr double kVelocityWidthPerFwhm = 2.0 * 1.2815515655446004 / 2.3548200450309493;

}  // namespace iwb::coarse_graining
