#pragma once
// The rate of a DEM curve over a stated span, with its uncertainty (issue 59: "the peak dilatancy
// rate is the largest 1 mm windowed slope: it grows with the noise and spans a different shear
// strain in every cell"). A maximum over windows picks the window whose noise is largest; a span
// fixed before looking at the slope (here: centred on the peak of the friction, which stress-
// dilatancy ties to the largest rate) is not selected on its own noise.
//
// The span is cut into blocks; each block's least-squares slope is one value, and the rate is
// their mean with a 95 % Student-t interval over the blocks. Slopes of disjoint blocks of a curve
// like u_n (an accumulated quantity) are close to independent where the block exceeds the grains'
// stick-slip, whereas the rows' own residuals about one line are not (they would give an interval
// far too narrow).
#include <optional>
#include <vector>

namespace iwb::statistics {

struct LocalRate {
  double rate = 0.0;        // mean of the blocks' slopes
  double half_width = 0.0;  // its 95 % t half-width over the blocks
  int blocks = 0;
  double from = 0.0, to = 0.0;  // the span actually used (clamped to the rows)
};

// dy/ds over [centre - half_span, centre + half_span], clamped to the rows' range and shifted to
// keep its length where it meets an end, in blocks of `block`; nullopt with fewer than 3 blocks of
// at least 3 rows each, or a span the rows do not cover. s ascending.
std::optional<LocalRate> local_rate(const std::vector<double>& s, const std::vector<double>& y,
                                    double centre, double half_span, double block);

}  // namespace iwb::statistics
