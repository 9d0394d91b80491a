#pragma once
// Where the fields are evaluated: an x-z image of the periodic cell (averaged over y, for the .vti
// pictures) or a height profile (averaged over x and y, for the profile CSVs and the checks). A
// grid hands the accumulation (fields.hpp) the kernel's weights per unit volume, so that the same
// sums serve both.
#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "coarse_graining/kernel.hpp"
#include "coarse_graining/particles.hpp"

namespace iwb::coarse_graining {

struct CellWeight {
  std::size_t cell;
  KernelValue value;  // per unit volume; along a branch only phi is set
};

class SamplingGrid {
 public:
  virtual ~SamplingGrid() = default;
  virtual std::size_t size() const = 0;
  // The cells within the kernel's reach of r (all periodic images), replacing `out`'s content.
  virtual void around_point(const Eigen::Vector3d& r, std::vector<CellWeight>& out) const = 0;
  // The cells within reach of the branch a -> b, with the kernel integrated along it.
  virtual void along_branch(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                            std::vector<CellWeight>& out) const = 0;
};

// Points (k h_x, z_lo + j h), k < n_x along the periodic x (h_x = L_x / n_x, the spacing closest to
// h), j < n_z up to z_hi; cell index j n_x + k, the order of VTK's ImageData.
class PlaneGrid : public SamplingGrid {
 public:
  PlaneGrid(const GaussianKernel& kernel, const PeriodicCell& cell, double spacing, double z_lo,
            double z_hi);
  std::size_t size() const override { return std::size_t(nx_) * std::size_t(nz_); }
  void around_point(const Eigen::Vector3d& r, std::vector<CellWeight>& out) const override;
  void along_branch(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                    std::vector<CellWeight>& out) const override;
  int nx() const { return nx_; }
  int nz() const { return nz_; }
  double hx() const { return hx_; }
  double hz() const { return h_; }
  double z_lo() const { return z_lo_; }

 private:
  GaussianKernel kernel_;
  PeriodicCell cell_;
  double h_, hx_, z_lo_;
  int nx_, nz_;
};

// Points z_lo + j h, j < n up to z_hi.
class HeightProfile : public SamplingGrid {
 public:
  HeightProfile(const GaussianKernel& kernel, const PeriodicCell& cell, double spacing, double z_lo,
                double z_hi);
  std::size_t size() const override { return std::size_t(n_); }
  void around_point(const Eigen::Vector3d& r, std::vector<CellWeight>& out) const override;
  void along_branch(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                    std::vector<CellWeight>& out) const override;
  double z(std::size_t j) const { return z_lo_ + double(j) * h_; }
  double spacing() const { return h_; }

 private:
  GaussianKernel kernel_;
  double area_, h_, z_lo_;
  int n_;
};

}  // namespace iwb::coarse_graining
