#include "coarse_graining/grid.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace iwb::coarse_graining {

namespace {

int points_up_to(double z_lo, double z_hi, double h) {
  if (!(h > 0.0) || !(z_hi >= z_lo))
    throw std::invalid_argument("coarse-graining grid: spacing or height range invalid");
  return int(std::floor((z_hi - z_lo) / h + 1e-9)) + 1;
}

// Index range [first, last] of points z_lo + j h within `reach` of [lo, hi], clipped to [0, n).
std::pair<int, int> z_range(double lo, double hi, double reach, double z_lo, double h, int n) {
  return {std::max(0, int(std::ceil((lo - reach - z_lo) / h))),
          std::min(n - 1, int(std::floor((hi + reach - z_lo) / h)))};
}

double wrapped(double x, double length) {
  const double w = std::fmod(x, length);
  return w < 0.0 ? w + length : w;
}

std::size_t periodic_index(int k, int n) {
  return std::size_t(((k % n) + n) % n);
}

}  // namespace

PlaneGrid::PlaneGrid(const GaussianKernel& kernel, const PeriodicCell& cell, double spacing,
                     double z_lo, double z_hi)
    : kernel_(kernel),
      cell_(cell),
      h_(spacing),
      z_lo_(z_lo),
      nz_(points_up_to(z_lo, z_hi, spacing)) {
  nx_ = std::max(1, int(std::lround(cell.length_x / spacing)));
  hx_ = cell.length_x / nx_;
}

// Unwrapped point indices k: each k is one periodic image's offset, so a kernel wider than the
// cell still sums every image once.
void PlaneGrid::around_point(const Eigen::Vector3d& r, std::vector<CellWeight>& out) const {
  out.clear();
  const double x = wrapped(r.x(), cell_.length_x), reach = kernel_.reach();
  const auto [j0, j1] = z_range(r.z(), r.z(), reach, z_lo_, h_, nz_);
  const int k0 = int(std::ceil((x - reach) / hx_)), k1 = int(std::floor((x + reach) / hx_));
  for (int j = j0; j <= j1; ++j)
    for (int k = k0; k <= k1; ++k) {
      KernelValue v = kernel_.planar(k * hx_ - x, z_lo_ + j * h_ - r.z());
      v.phi /= cell_.length_y, v.dphi_dx /= cell_.length_y, v.dphi_dz /= cell_.length_y;
      out.push_back({std::size_t(j) * std::size_t(nx_) + periodic_index(k, nx_), v});
    }
}

void PlaneGrid::along_branch(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                             std::vector<CellWeight>& out) const {
  out.clear();
  const double shift = wrapped(a.x(), cell_.length_x) - a.x(), reach = kernel_.reach();
  const Eigen::Vector2d pa(a.x() + shift, a.z()), pb(b.x() + shift, b.z());
  const auto [j0, j1] =
      z_range(std::min(pa.y(), pb.y()), std::max(pa.y(), pb.y()), reach, z_lo_, h_, nz_);
  const int k0 = int(std::ceil((std::min(pa.x(), pb.x()) - reach) / hx_));
  const int k1 = int(std::floor((std::max(pa.x(), pb.x()) + reach) / hx_));
  for (int j = j0; j <= j1; ++j)
    for (int k = k0; k <= k1; ++k) {
      const Eigen::Vector2d p(k * hx_, z_lo_ + j * h_);
      const double phi = kernel_.planar_along(pa - p, pb - p) / cell_.length_y;
      out.push_back({std::size_t(j) * std::size_t(nx_) + periodic_index(k, nx_), {phi, 0.0, 0.0}});
    }
}

HeightProfile::HeightProfile(const GaussianKernel& kernel, const PeriodicCell& cell, double spacing,
                             double z_lo, double z_hi)
    : kernel_(kernel),
      area_(cell.length_x * cell.length_y),
      h_(spacing),
      z_lo_(z_lo),
      n_(points_up_to(z_lo, z_hi, spacing)) {}

void HeightProfile::around_point(const Eigen::Vector3d& r, std::vector<CellWeight>& out) const {
  out.clear();
  const auto [j0, j1] = z_range(r.z(), r.z(), kernel_.reach(), z_lo_, h_, n_);
  for (int j = j0; j <= j1; ++j) {
    KernelValue v = kernel_.vertical(z(std::size_t(j)) - r.z());
    v.phi /= area_, v.dphi_dz /= area_;
    out.push_back({std::size_t(j), v});
  }
}

void HeightProfile::along_branch(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                 std::vector<CellWeight>& out) const {
  out.clear();
  const auto [j0, j1] =
      z_range(std::min(a.z(), b.z()), std::max(a.z(), b.z()), kernel_.reach(), z_lo_, h_, n_);
  for (int j = j0; j <= j1; ++j) {
    const double zj = z(std::size_t(j));
    out.push_back(
        {std::size_t(j), {kernel_.vertical_along(a.z() - zj, b.z() - zj) / area_, 0.0, 0.0}});
  }
}

}  // namespace iwb::coarse_graining
