#include "assessment/sobol.hpp"

#include <algorithm>
#include <boost/math/distributions/lognormal.hpp>
#include <boost/math/distributions/normal.hpp>
#include <cmath>
#include <stdexcept>

#include "assessment/evaluate.hpp"

namespace iwb::assessment {

double Distribution::sample(std::mt19937_64& rng) const {
  switch (kind) {
    case Kind::kNormal:
      return std::normal_distribution<double>(mean, cov * std::abs(mean))(rng);
    case Kind::kLognormal: {  // the log's parameters from the mean and COV of the variable itself
      const double s2 = std::log(1.0 + cov * cov);
      return std::lognormal_distribution<double>(std::log(mean) - 0.5 * s2, std::sqrt(s2))(rng);
    }
    case Kind::kUniform: {
      const double half = std::sqrt(3.0) * cov * std::abs(mean);
      return std::uniform_real_distribution<double>(mean - half, mean + half)(rng);
    }
  }
  throw std::logic_error("unknown distribution");
}

double Distribution::quantile(double p) const {
  switch (kind) {
    case Kind::kNormal:
      return boost::math::quantile(boost::math::normal(mean, cov * std::abs(mean)), p);
    case Kind::kLognormal: {
      const double s2 = std::log(1.0 + cov * cov);
      return boost::math::quantile(boost::math::lognormal(std::log(mean) - 0.5 * s2, std::sqrt(s2)),
                                   p);
    }
    case Kind::kUniform: {
      const double half = std::sqrt(3.0) * cov * std::abs(mean);
      return mean - half + 2.0 * half * p;
    }
  }
  throw std::logic_error("unknown distribution");
}

namespace {

using Matrix = std::vector<std::vector<double>>;  // [row][column]

Matrix sample_matrix(const std::vector<Distribution>& p, int n, std::mt19937_64& rng) {
  Matrix m(std::size_t(n), std::vector<double>(p.size()));
  for (auto& row : m)
    for (std::size_t j = 0; j < p.size(); ++j) row[j] = p[j].sample(rng);
  return m;
}

// Jansen's total index over the rows `rows` of the outputs of A (ya) and A_B^i (yi) for one
// quantity.
double jansen(const std::vector<double>& ya, const std::vector<double>& yb,
              const std::vector<double>& yi, const std::vector<std::size_t>& rows) {
  double mean = 0.0, var = 0.0, num = 0.0;
  for (auto r : rows) mean += ya[r] + yb[r];
  mean /= 2.0 * double(rows.size());
  for (auto r : rows) var += (ya[r] - mean) * (ya[r] - mean) + (yb[r] - mean) * (yb[r] - mean);
  var /= 2.0 * double(rows.size()) - 1.0;
  for (auto r : rows) num += (ya[r] - yi[r]) * (ya[r] - yi[r]);
  // a quantity the samples do not move (sigma_n under CNL) has no variance to share: 0, not the
  // ratio of two round-offs
  return var > 1e-24 * (mean * mean + 1e-300) ? num / (2.0 * double(rows.size())) / var : 0.0;
}

}  // namespace

SobolResult total_sobol_indices(const std::vector<Distribution>& p,
                                const std::vector<std::string>& quantities, const Quantities& f,
                                int n, unsigned seed, int bootstrap, int threads) {
  if (n < 2 || p.empty())
    throw std::invalid_argument("Sobol indices need at least 2 samples and 1 parameter");
  std::mt19937_64 rng(seed);
  const Matrix A = sample_matrix(p, n, rng), B = sample_matrix(p, n, rng);
  const std::size_t k = p.size(), m = quantities.size();
  // outputs [matrix][quantity][row]: matrix 0 = A, 1 = B, 2 + i = A_B^i
  std::vector<Matrix> y(k + 2, Matrix(m, std::vector<double>(std::size_t(n))));
  SobolResult out{{}, quantities, {}, n, 0, 0};
  for (const auto& d : p) out.parameters.push_back(d.name);
  std::vector<std::vector<double>> x;  // every run's parameters: A, B, then each A_B^i, row by row
  for (std::size_t which = 0; which < k + 2; ++which)
    for (int r = 0; r < n; ++r) {
      x.push_back(which == 1 ? B[std::size_t(r)] : A[std::size_t(r)]);
      if (which >= 2) x.back()[which - 2] = B[std::size_t(r)][which - 2];
    }
  const auto q = evaluate_rows(x, f, threads);
  out.evaluations = long(q.size());
  std::vector<bool> ok(std::size_t(n), true);
  for (std::size_t which = 0; which < k + 2; ++which)
    for (int r = 0; r < n; ++r)
      for (std::size_t j = 0; j < m; ++j) {
        const double v = q[which * std::size_t(n) + std::size_t(r)].at(j);
        y[which][j][std::size_t(r)] = v;
        if (!std::isfinite(v)) ok[std::size_t(r)] = false;
      }
  std::vector<std::size_t> rows;
  for (int r = 0; r < n; ++r)
    if (ok[std::size_t(r)]) rows.push_back(std::size_t(r));
  out.failed = n - long(rows.size());
  if (rows.size() < 2)
    throw std::runtime_error("fewer than two sample rows with finite quantities");
  std::uniform_int_distribution<std::size_t> pick(0, rows.size() - 1);
  out.total.assign(m, std::vector<TotalIndex>(k));
  for (std::size_t j = 0; j < m; ++j)
    for (std::size_t i = 0; i < k; ++i) {
      const auto& ya = y[0][j];
      const auto& yb = y[1][j];
      const auto& yi = y[2 + i][j];
      std::vector<double> boot;
      for (int b = 0; b < bootstrap; ++b) {
        std::vector<std::size_t> resampled(rows.size());
        for (auto& r : resampled) r = rows[pick(rng)];
        boot.push_back(jansen(ya, yb, yi, resampled));
      }
      std::sort(boot.begin(), boot.end());
      const auto at = [&](double q) {
        return boot.empty() ? NAN : boot[std::size_t(q * double(boot.size() - 1))];
      };
      out.total[j][i] = {jansen(ya, yb, yi, rows), at(0.025), at(0.975)};
    }
  return out;
}

}  // namespace iwb::assessment
