#include "comparison/replay/pooled_scatter.hpp"

#include <fmt/core.h>

#include <cmath>

#include "statistics/equal_scatter.hpp"

namespace iwb::comparison {

PooledScatter pool_scatter(const std::vector<SeedScatter>& cells) {
  std::map<std::string, std::vector<std::vector<double>>> relative;
  for (const auto& c : cells)
    for (const auto& [key, values] : c.quantity_values) {
      if (values.size() < kPoolingMinSeeds) continue;
      const double mean = c.quantity_mean.at(key);
      if (!(std::abs(mean) > 0.0)) continue;
      std::vector<double> r;
      for (const double v : values) r.push_back(v / mean);
      relative[key].push_back(r);
    }
  PooledScatter out;
  for (const auto& [key, groups] : relative) {
    if (groups.size() < kPoolingMinCells) continue;
    PooledQuantity q;
    q.cells = int(groups.size());
    for (const auto& g : groups) q.runs += int(g.size());
    q.levene_p = statistics::brown_forsythe(groups).p_value;
    const auto p = statistics::pooled_sd(groups);
    q.relative_sd = p.sd, q.dof = p.degrees_of_freedom;
    q.pooled = q.levene_p > kPoolingSignificance;
    out[key] = q;
  }
  return out;
}

void apply_pooling(SeedScatter& scatter, const PooledScatter& pooled) {
  for (const auto& [key, q] : pooled) {
    const auto mean = scatter.quantity_mean.find(key);
    if (mean == scatter.quantity_mean.end() || !scatter.from_seeds()) continue;
    if (!q.pooled) {
      scatter.quantity_note[key] = fmt::format(
          "own seed scatter: Levene's test rejects equal scatter across the set's {} cells (p = "
          "{:.3g})",
          q.cells, q.levene_p);
      continue;
    }
    scatter.quantity_sd[key] = q.relative_sd * std::abs(mean->second);
    scatter.quantity_dof[key] = q.dof;
    scatter.quantity_note[key] = fmt::format(
        "scatter pooled over the set's {} cells ({} runs; Levene p = {:.2g}): relative SD {:.3g} "
        "with {} degrees of freedom",
        q.cells, q.runs, q.levene_p, q.relative_sd, q.dof);
  }
}

nlohmann::json to_json(const PooledScatter& pooled) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [key, q] : pooled)
    j[key] = {{"cells", q.cells},
              {"runs", q.runs},
              {"levene_p", q.levene_p},
              {"pooled", q.pooled},
              {"relative_sd", q.relative_sd},
              {"degrees_of_freedom", q.dof}};
  return j;
}

}  // namespace iwb::comparison
