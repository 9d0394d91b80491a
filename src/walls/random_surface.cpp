#include "walls/random_surface.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <random>
#include <unsupported/Eigen/FFT>

namespace iwb::walls {

namespace {

// The surface's spectral density at wavenumber q (rad/m), up to a factor the RMS fixes.
double density(double q, const RandomSurfaceSpec& s) {
  const double qq = q * s.correlation_length_m;
  return std::pow(1.0 + qq * qq, -(1.0 + s.hurst));
}

// The signed wavenumber index of FFT slot k of n (0, 1, .., n/2, -(n/2 - 1), .., -1).
int signed_index(int k, int n) {
  return k <= n / 2 ? k : k - n;
}

}  // namespace

HeightMap random_surface(const RandomSurfaceSpec& spec, double length, double width,
                         double spacing) {
  const int nx = std::max(4, int(std::ceil(length / spacing))),
            ny = std::max(4, int(std::ceil(width / spacing)));
  std::mt19937_64 rng(spec.seed);
  std::uniform_real_distribution<double> phase(0.0, 2.0 * M_PI);
  // Random phases over the whole plane; the real part of the inverse transform is a sum of
  // cosines, one per wavevector, each with an amplitude sqrt(C(q)) and its own phase.
  std::vector<std::vector<std::complex<double>>> rows(ny, std::vector<std::complex<double>>(nx));
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const double qx = 2.0 * M_PI * signed_index(i, nx) / length,
                   qy = 2.0 * M_PI * signed_index(j, ny) / width;
      const double a = (i == 0 && j == 0) ? 0.0 : std::sqrt(density(std::hypot(qx, qy), spec));
      rows[j][i] = std::polar(a, phase(rng));
    }
  Eigen::FFT<double> fft;
  std::vector<std::complex<double>> line;
  for (auto& r : rows) fft.inv(line, r), r = line;  // along x
  std::vector<std::complex<double>> column(ny);
  std::vector<double> z(std::size_t(nx) * ny);
  for (int i = 0; i < nx; ++i) {  // along y
    for (int j = 0; j < ny; ++j) column[j] = rows[j][i];
    fft.inv(line, column);
    for (int j = 0; j < ny; ++j) z[std::size_t(j) * nx + i] = line[j].real();
  }
  double mean = 0.0, square = 0.0;
  for (double v : z) mean += v;
  mean /= double(z.size());
  for (double& v : z) v -= mean, square += v * v;
  const double scale = spec.rms_height_m / std::sqrt(square / double(z.size()));
  double lowest = 0.0;
  for (double& v : z) v *= scale, lowest = std::min(lowest, v);
  for (double& v : z) v -= lowest;  // on the wall's base plane
  return HeightMap(nx, ny, length, width, std::move(z));
}

}  // namespace iwb::walls
