#pragma once
// A periodic height field z(x, y) sampled on a regular grid over one period length x width, read
// between the nodes by bilinear interpolation: the surface of an areal rough wall (a random
// self-affine surface, a measured map) as the mesh, the descriptors and the band's origin read it.
#include <vector>

namespace iwb::walls {

class HeightMap {
 public:
  // heights[j * nx + i] at (i length / nx, j width / ny); the grid does not repeat its first row or
  // column at the far edge (periodic).
  HeightMap(int nx, int ny, double length, double width, std::vector<double> heights);

  double at(double x, double y) const;  // any x, y: wrapped into the period
  double node(int i, int j) const;      // i, j wrapped
  int nx() const { return nx_; }
  int ny() const { return ny_; }
  double length() const { return length_; }
  double width() const { return width_; }
  double mean() const;
  double max() const;
  double min() const;

 private:
  int nx_, ny_;
  double length_, width_;
  std::vector<double> z_;
};

}  // namespace iwb::walls
