// The seed scatter pooled across a set's cells (issue 36): where Levene's test about the median
// does not reject equal relative scatter, each cell's SD becomes the pooled relative SD times its
// mean and its interval's t takes the pooled degrees of freedom; where it rejects, each cell keeps
// its own. The p-values are SciPy 1.10's levene(center='median') on the same relative values (run
// by hand, as in tests/statistics/test_equal_scatter.cpp).
#include <catch2/catch.hpp>
#include <cmath>

#include "comparison/replay/pooled_scatter.hpp"
#include "comparison/verdicts/verdicts.hpp"
#include "statistics/t_interval.hpp"

using namespace iwb;

namespace {

comparison::SeedScatter cell_of(const std::vector<double>& values) {
  comparison::SeedScatter s;
  double mean = 0.0, squares = 0.0;
  for (const double v : values) mean += v / double(values.size());
  for (const double v : values) squares += (v - mean) * (v - mean);
  for (std::size_t i = 0; i < values.size(); ++i) s.runs.push_back("run" + std::to_string(i));
  s.quantity_values["peak_friction"] = values;
  s.quantity_mean["peak_friction"] = mean;
  s.quantity_sd["peak_friction"] = std::sqrt(squares / double(values.size() - 1));
  return s;
}

}  // namespace

TEST_CASE("cells that scatter alike pool their SD, and the verdict's interval uses its dof",
          "[comparison]") {
  std::vector<comparison::SeedScatter> cells = {
      cell_of({1.00, 1.05, 0.93}), cell_of({0.50, 0.56, 0.47, 0.52}), cell_of({2.1, 1.8, 2.4}),
      cell_of({0.98, 1.02, 1.01})};
  const auto pooled = comparison::pool_scatter(cells);
  const auto& q = pooled.at("peak_friction");
  CHECK(q.levene_p == Approx(0.2888619222138269).epsilon(1e-9));  // SciPy
  CHECK(q.pooled);
  CHECK(q.cells == 4);
  CHECK(q.runs == 13);
  CHECK(q.dof == 9);
  CHECK(q.relative_sd == Approx(0.08519115987299912).epsilon(1e-12));
  auto cell = cells[2];
  comparison::apply_pooling(cell, pooled);
  CHECK(cell.quantity_sd.at("peak_friction") == Approx(0.08519115987299912 * 2.1).epsilon(1e-12));
  CHECK(cell.quantity_dof.at("peak_friction") == 9);
  CHECK(cell.quantity_note.at("peak_friction").find("pooled over the set's 4 cells") !=
        std::string::npos);
  // the interval of the cell's 3-seed mean: t_{0.975, 9} = 2.2622 (SciPy), not t_{0.975, 2} = 4.30
  const auto i = comparison::seed_interval(cell.quantity_sd.at("peak_friction"), 3, 0.10, 2.1, 9);
  CHECK(*i.ci == Approx(2.2621571627409915 * 0.08519115987299912 * 2.1 / std::sqrt(3.0)));
}

TEST_CASE("cells whose scatter differs keep their own, and say why", "[comparison]") {
  std::vector<comparison::SeedScatter> cells = {
      cell_of({1, 1.01, 0.99, 1.0, 1.005}), cell_of({2, 2.02, 1.98, 2.01, 1.99}),
      cell_of({0.5, 0.505, 0.495, 0.5, 0.502}), cell_of({0.2, 1.0, 1.8, 0.5, 1.5})};
  const auto pooled = comparison::pool_scatter(cells);
  CHECK(pooled.at("peak_friction").levene_p == Approx(0.00019351146846685564).epsilon(1e-6));
  CHECK_FALSE(pooled.at("peak_friction").pooled);
  auto cell = cells[0];
  const double own = cell.quantity_sd.at("peak_friction");
  comparison::apply_pooling(cell, pooled);
  CHECK(cell.quantity_sd.at("peak_friction") == own);
  CHECK(cell.quantity_dof.count("peak_friction") == 0);
  CHECK(cell.quantity_note.at("peak_friction").find("Levene's test rejects") != std::string::npos);
  // too few cells of three or more runs: nothing pooled
  CHECK(comparison::pool_scatter({cell_of({1, 1.1, 0.9}), cell_of({2, 2.2, 1.8})}).empty());
}
