#pragma once
// Total Sobol indices (issue 17, seed chapter 4, eqs. 4.5-4.9): how much of a quantity's variance a
// parameter carries, its interactions included. Saltelli's (2010) sampling: two independent N x k
// sample matrices A and B and, per parameter i, A with its column i taken from B; Jansen's (1999)
// estimator S_Ti = mean((f(A) - f(A_B^i))^2) / (2 Var f), which stays non-negative and is the
// recommended one of Saltelli et al. (2010, Table 2). Confidence intervals by bootstrap over the N
// rows. Pure numerics: the model runs are the caller's function.
#include <functional>
#include <random>
#include <string>
#include <vector>

namespace iwb::assessment {

// A parameter's distribution as Table 4.8 gives it: a mean and a coefficient of variation.
struct Distribution {
  enum class Kind { kNormal, kLognormal, kUniform };
  std::string name;
  Kind kind = Kind::kNormal;
  double mean = 0.0, cov = 0.0;  // kUniform: mean +- sqrt(3) cov mean (the same SD)
  double sample(std::mt19937_64& rng) const;
  double quantile(double probability) const;  // the inverse CDF, for Latin hypercube samples
};

struct TotalIndex {
  double value, low, high;  // estimate and the bootstrap's 95 % interval
};

struct SobolResult {
  std::vector<std::string> parameters, quantities;
  std::vector<std::vector<TotalIndex>> total;  // [quantity][parameter]
  int base_samples = 0;
  long evaluations = 0;
  long failed = 0;  // runs whose quantities were not finite: dropped row-wise
};

// f maps a parameter vector to the quantities of interest (NaN where a run fails). It is called
// from several threads at once (evaluate.hpp); threads 0: every core.
using Quantities = std::function<std::vector<double>(const std::vector<double>&)>;

SobolResult total_sobol_indices(const std::vector<Distribution>& parameters,
                                const std::vector<std::string>& quantities, const Quantities& f,
                                int base_samples, unsigned seed, int bootstrap = 200,
                                int threads = 0);

}  // namespace iwb::assessment
