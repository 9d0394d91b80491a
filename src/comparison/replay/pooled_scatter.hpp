#pragma once
// The seed scatter pooled across the cells of a run set (issue 36): three seeds measure an SD that
// is itself uncertain by a factor 2-3, and cells of one campaign often scatter alike relative to
// their means (data/reference/README.md: Levene p 0.73-0.81 over 17 cells). Per quantity, each
// run's value relative to its cell's mean, over the cells of at least kPoolingMinSeeds runs;
// where there are at least kPoolingMinCells such cells and Levene's test about the median does not
// reject equal scatter at kPoolingSignificance, the pooled relative SD (with sum (n_i - 1) degrees
// of freedom) stands for each cell's own: a cell's SD becomes pooled SD x |its mean| and its
// interval's t takes the pooled degrees of freedom. Where the test rejects, each cell keeps its
// own, and the verdict says why.
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "comparison/replay/seed_scatter.hpp"

namespace iwb::comparison {

inline constexpr double kPoolingSignificance = 0.05;
inline constexpr std::size_t kPoolingMinSeeds = 3;
inline constexpr std::size_t kPoolingMinCells = 3;

struct PooledQuantity {
  int cells = 0, runs = 0;
  double levene_p = 1.0;
  bool pooled = false;
  double relative_sd = 0.0;
  int dof = 0;
};
using PooledScatter = std::map<std::string, PooledQuantity>;

// Per quantity over `cells` (one SeedScatter per cell of the set). Quantities with too few cells,
// or a cell mean of 0, are left out.
PooledScatter pool_scatter(const std::vector<SeedScatter>& cells);

// `scatter`'s SD replaced by the pooled one where pooled (quantity_sd, quantity_dof and a note);
// a note where Levene rejected pooling.
void apply_pooling(SeedScatter& scatter, const PooledScatter& pooled);

nlohmann::json to_json(const PooledScatter& pooled);

}  // namespace iwb::comparison
