#pragma once
// R_max over gauge windows (Uesugi & Kishida 1986): the peak-to-valley height within each window of
// `window` + 1 consecutive samples starting at 0 .. starts - 1, its largest and its mean. `z` holds
// at least starts + window samples (a periodic profile repeats its first ones at the end).
#include <algorithm>
#include <utility>
#include <vector>

namespace iwb::walls {

struct GaugeRanges {
  double largest = 0.0, sum = 0.0;
  int windows = 0;
};

inline void add_gauge_ranges(const std::vector<double>& z, int window, int starts, GaugeRanges& r) {
  for (int i = 0; i < starts; ++i) {
    const auto [lo, hi] = std::minmax_element(z.begin() + i, z.begin() + i + window + 1);
    r.largest = std::max(r.largest, *hi - *lo), r.sum += *hi - *lo, ++r.windows;
  }
}

}  // namespace iwb::walls
