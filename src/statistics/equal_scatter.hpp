#pragma once
// May the scatter of several small samples be pooled (issue 36)? Three DEM seeds measure an SD
// that is itself uncertain by a factor 2-3; cells of one scene family that scatter alike give a
// better SD together. Levene's test about the median (Brown & Forsythe 1974: robust to the small,
// skewed samples of a few seeds) tests equal scatter; where it does not reject, the pooled SD
// sqrt(sum (n_i - 1) s_i^2 / sum (n_i - 1)) with its sum (n_i - 1) degrees of freedom stands for
// each sample's.
#include <vector>

namespace iwb::statistics {

struct EqualScatterTest {
  double statistic =
      0.0;  // W = (N - k) / (k - 1) * sum n_i (Zbar_i - Zbar)^2 / sum (Z_ij - Zbar_i)^2
  double p_value = 1.0;  // 1 - F_{k-1, N-k}(W)
  int groups = 0, values = 0;
};

// Brown-Forsythe (Levene about the median) over `groups`, each of at least two values, at least two
// groups; std::invalid_argument otherwise. Every Z equal to its group's mean (no spread anywhere)
// gives W = 0, p = 1.
EqualScatterTest brown_forsythe(const std::vector<std::vector<double>>& groups);

struct PooledSd {
  double sd = 0.0;
  int degrees_of_freedom = 0;
};

// The pooled sample SD of groups of at least two values each.
PooledSd pooled_sd(const std::vector<std::vector<double>>& groups);

}  // namespace iwb::statistics
