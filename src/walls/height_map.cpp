#include "walls/height_map.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace iwb::walls {

HeightMap::HeightMap(int nx, int ny, double length, double width, std::vector<double> heights)
    : nx_(nx), ny_(ny), length_(length), width_(width), z_(std::move(heights)) {
  if (nx < 1 || ny < 1 || z_.size() != std::size_t(nx) * std::size_t(ny))
    throw std::invalid_argument("HeightMap: the grid and its heights do not match");
}

double HeightMap::node(int i, int j) const {
  i = ((i % nx_) + nx_) % nx_;
  j = ((j % ny_) + ny_) % ny_;
  return z_[std::size_t(j) * nx_ + i];
}

double HeightMap::at(double x, double y) const {
  const double u = x / length_ * nx_, v = y / width_ * ny_;
  const double i0 = std::floor(u), j0 = std::floor(v);
  const double fu = u - i0, fv = v - j0;
  const int i = int(i0), j = int(j0);
  return (1 - fu) * (1 - fv) * node(i, j) + fu * (1 - fv) * node(i + 1, j) +
         (1 - fu) * fv * node(i, j + 1) + fu * fv * node(i + 1, j + 1);
}

double HeightMap::mean() const {
  return std::accumulate(z_.begin(), z_.end(), 0.0) / double(z_.size());
}
double HeightMap::max() const {
  return *std::max_element(z_.begin(), z_.end());
}
double HeightMap::min() const {
  return *std::min_element(z_.begin(), z_.end());
}

}  // namespace iwb::walls
