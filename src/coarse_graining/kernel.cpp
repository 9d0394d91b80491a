#include "coarse_graining/kernel.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace iwb::coarse_graining {

namespace {
// A branch shorter than this many widths (a contact along y only) is a point at its middle: the
// closed forms divide by the branch's length.
constexpr double kPointBranch = 1e-9;
}  // namespace

GaussianKernel::GaussianKernel(double width) : w_(width) {
  if (!(width > 0.0) || !std::isfinite(width))
    throw std::invalid_argument("coarse-graining width must be positive");
}

KernelValue GaussianKernel::planar(double dx, double dz) const {
  const double phi =
      std::exp(-(dx * dx + dz * dz) / (2.0 * w_ * w_)) / (2.0 * std::numbers::pi * w_ * w_);
  // d/dx of phi(p - r_i) at the grid point p: -(dx / w^2) phi
  return {phi, -dx / (w_ * w_) * phi, -dz / (w_ * w_) * phi};
}

KernelValue GaussianKernel::vertical(double dz) const {
  const double phi =
      std::exp(-dz * dz / (2.0 * w_ * w_)) / (std::sqrt(2.0 * std::numbers::pi) * w_);
  return {phi, 0.0, -dz / (w_ * w_) * phi};
}

// The grid point sits at the origin; the branch runs from a to b. With e the branch's direction,
// |q(t)|^2 = d_perp^2 + (t + t_a)^2 along it, so the integral separates into a Gaussian of the
// perpendicular distance and an erf difference along the branch.
double GaussianKernel::planar_along(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const {
  const Eigen::Vector2d ab = b - a;
  const double length = ab.norm();
  if (length < kPointBranch * w_) {
    const Eigen::Vector2d mid = 0.5 * (a + b);
    return planar(-mid.x(), -mid.y()).phi;
  }
  const Eigen::Vector2d e = ab / length;
  const double t_a = a.dot(e);
  const double d_perp2 = std::max(0.0, a.squaredNorm() - t_a * t_a);
  const double s = std::sqrt(2.0) * w_;
  const double along =
      std::sqrt(std::numbers::pi / 2.0) * w_ * (std::erf((t_a + length) / s) - std::erf(t_a / s));
  return std::exp(-d_perp2 / (2.0 * w_ * w_)) / (2.0 * std::numbers::pi * w_ * w_) * along / length;
}

double GaussianKernel::vertical_along(double a, double b) const {
  const double length = b - a;
  if (std::abs(length) < kPointBranch * w_) return vertical(-0.5 * (a + b)).phi;
  const double s = std::sqrt(2.0) * w_;
  return 0.5 * (std::erf(b / s) - std::erf(a / s)) / length;
}

}  // namespace iwb::coarse_graining
