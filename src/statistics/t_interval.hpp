#pragma once
// Student's t intervals for a mean over a few DEM seeds (issue 36): with n seeds the SD is itself
// uncertain (by a factor 2-3 at n = 3), and the interval of the mean is t_{(1+c)/2, n-1} SD /
// sqrt(n), not 2 SD / sqrt(n): at n = 3 and 95 % the factor is 4.30, not 2.
#include <optional>

namespace iwb::statistics {

inline constexpr double kConfidence = 0.95;  // two-sided, every interval of the workbench

// The two-sided quantile t_{(1 + confidence) / 2, dof} (Boost.Math); dof >= 1.
double t_quantile(int degrees_of_freedom, double confidence = kConfidence);

// Half-width of the t-interval of a mean of n values with sample SD `sd`; nullopt for n < 2 (one
// run has no interval).
std::optional<double> t_half_width(double sd, int n, double confidence = kConfidence);

// The fewest values (>= 2) whose t-interval half-width, for a sample SD `sd` as measured, is at
// most `half_width`; nullopt when sd is 0 or not finite (nothing to resolve) or when more than
// `at_most` would be needed.
std::optional<int> values_needed(double sd, double half_width, int at_most = 1000,
                                 double confidence = kConfidence);

}  // namespace iwb::statistics
