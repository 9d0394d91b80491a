#pragma once
// A periodic, isotropic, self-affine Gaussian surface (Persson et al. 2005, "On the nature of
// surface roughness"): random phases over a power spectral density that is flat below the roll-off
// wavenumber q0 = 1 / correlation length and falls as q^-2(1+H) above it, H the Hurst exponent,
// scaled to the requested RMS height. Periodic in x and y over the box, so the wall tiles it.
#include <cstdint>

#include "walls/height_map.hpp"

namespace iwb::walls {

struct RandomSurfaceSpec {
  double rms_height_m = 0.0;
  double correlation_length_m = 0.0;
  double hurst = 0.8;
  std::uint64_t seed = 1;
};

// Sampled on a grid of spacing at most `spacing` (rounded so that whole cells fill the box); the
// lowest point is at 0 (the base plane) and the RMS exactly the spec's; modes down to the Nyquist
// wavelength, 2 spacings.
HeightMap random_surface(const RandomSurfaceSpec& spec, double length, double width,
                         double spacing);

}  // namespace iwb::walls
