#include "assessment/uncertainty.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <stdexcept>

#include "assessment/evaluate.hpp"

namespace iwb::assessment {

std::vector<std::vector<double>> latin_hypercube(const std::vector<Distribution>& p, int n,
                                                 unsigned seed) {
  if (n < 1) throw std::invalid_argument("a Latin hypercube needs at least one sample");
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> within(0.0, 1.0);
  std::vector<std::vector<double>> x(std::size_t(n), std::vector<double>(p.size()));
  std::vector<int> strata(static_cast<std::size_t>(n));
  for (std::size_t j = 0; j < p.size(); ++j) {
    std::iota(strata.begin(), strata.end(), 0);
    std::shuffle(strata.begin(), strata.end(), rng);
    for (int i = 0; i < n; ++i)
      x[std::size_t(i)][j] = p[j].quantile((strata[std::size_t(i)] + within(rng)) / n);
  }
  return x;
}

UncertaintyResult summarize(const std::vector<std::string>& names,
                            const std::vector<std::vector<double>>& outputs) {
  UncertaintyResult out;
  out.samples = int(outputs.size());
  std::vector<std::vector<double>> values(names.size());
  for (const auto& q : outputs) {
    if (!std::all_of(q.begin(), q.end(), [](double v) { return std::isfinite(v); })) {
      ++out.failed;
      continue;
    }
    for (std::size_t j = 0; j < names.size(); ++j) values[j].push_back(q.at(j));
  }
  for (std::size_t j = 0; j < names.size(); ++j) {
    const auto& v = values[j];
    const double count = double(v.size());
    const double mean = count > 0 ? std::accumulate(v.begin(), v.end(), 0.0) / count : NAN;
    double ss = 0.0;
    for (double y : v) ss += (y - mean) * (y - mean);
    const double sd = count > 1 ? std::sqrt(ss / (count - 1.0)) : NAN;
    // a quantity the samples leave at 0 (the dilation of a model without dilatancy) has no spread
    const double cv = std::abs(mean) > 0.0 ? sd / std::abs(mean) : sd == 0.0 ? 0.0 : NAN;
    out.quantities.push_back({names[j], mean, sd, cv});
  }
  return out;
}

UncertaintyResult parameter_uncertainty(const std::vector<Distribution>& p,
                                        const std::vector<std::string>& names, const Quantities& f,
                                        int n, unsigned seed, int threads) {
  return summarize(names, evaluate_rows(latin_hypercube(p, n, seed), f, threads));
}

}  // namespace iwb::assessment
