#pragma once
// The Gaussian coarse-graining kernel (Goldhirsch 2010; Weinhart et al. 2012) of width w (its
// standard deviation), averaged over the periodic directions: over y for the x-z grid (a 2D
// Gaussian divided by L_y) and over x and y for the height profile (a 1D Gaussian divided by
// L_x L_y). Averaging a 3D Gaussian over a periodic direction of length L >> w gives exactly the
// lower-dimensional one over L, so both are the same field seen at two resolutions.
//
// The kernel is evaluated to kReach widths: beyond it the weight is below exp(-18) = 1.5e-8 of the
// peak and the tail's mass below 2e-9 (1D) of the whole; at 5 widths the truncation alone moved a
// lattice's gradient by 6e-6 (tests/coarse_graining).
#include <Eigen/Core>

namespace iwb::coarse_graining {

inline constexpr double kReach = 6.0;  // in widths

// Weight and its gradient at a grid point, for a particle at offset d = grid point - particle.
struct KernelValue {
  double phi = 0.0, dphi_dx = 0.0, dphi_dz = 0.0;
};

class GaussianKernel {
 public:
  explicit GaussianKernel(double width);
  double width() const { return w_; }
  double reach() const { return kReach * w_; }
  // The 2D (x-z) Gaussian and the 1D (z) one, for the offset d = grid point - particle; the grids
  // divide by the lengths averaged over (grid.hpp).
  KernelValue planar(double dx, double dz) const;
  KernelValue vertical(double dz) const;
  // The kernel integrated along a branch, int_0^1 phi(p - (a + s (b - a))) ds, in closed form
  // (erf), with a and b relative to the grid point p: planar uses (x, z), vertical uses z.
  double planar_along(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const;
  double vertical_along(double a, double b) const;

 private:
  double w_;
};

}  // namespace iwb::coarse_graining
