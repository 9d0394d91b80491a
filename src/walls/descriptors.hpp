#pragma once
// Roughness descriptors of a wall (issue 36): is R_n enough to say how a wall shears, or does a
// wall of another shape at the same R_n shear differently? Every descriptor a user may try against
// the DEM, computed from the surface sampled along x (the shear direction) on every row of an
// areal surface:
//   R_n       R_max over a gauge length d50, over d50 (Uesugi & Kishida 1986), the largest and the
//             mean over all window positions;
//   R_a, R_q  mean absolute and RMS deviation from the mean height (ISO 4287);
//   slope     mean |dz/dx| (ISO 4287's R_Delta_a, with absolute values);
//   spectrum  the one-sided power spectral density along x, averaged over rows, log-binned;
//   lambda_c  the correlation length: the lag where the autocorrelation along x falls to 1/e;
//   H         the Hurst exponent from the spectrum's slope between 4 samples and lambda_c, where
//             the profile is self-affine (a line scan of a self-affine surface has PSD ~
//             f^-(1+2H)).
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "walls/profile.hpp"

namespace iwb::walls {

struct SpectrumBin {
  double wavelength_m;  // the power-weighted geometric mean of the bin's wavelengths
  double psd_m3;        // mean one-sided PSD over the bin (m^2 per 1/m)
  double variance_m2;   // the bin's share of R_q^2 (the bins sum to R_q^2: Parseval)
};

struct RoughnessDescriptors {
  double sample_spacing_m = 0.0;
  int rows = 1;
  double R_n = 0.0, R_n_mean = 0.0;
  double R_max_m = 0.0;  // peak to valley over the whole surface
  double R_a_m = 0.0, R_q_m = 0.0;
  double mean_abs_slope = 0.0;
  double correlation_length_m = 0.0;  // 0: flat
  std::vector<SpectrumBin> spectrum;
  std::optional<double> hurst;  // where the profile is self-affine
  double hurst_fit_r2 = 0.0;
  std::string hurst_note;  // why there is none, or the fit's range
};

// The descriptors of `profile` over one box length x width (the surface repeats with the box).
RoughnessDescriptors describe_roughness(const RoughnessProfile& profile, double length,
                                        double width, double d50);

// In d50 where a length scales with the grains, and in mm.
nlohmann::json to_json(const RoughnessDescriptors& r, double d50);
std::string to_text(const RoughnessDescriptors& r, double d50);

}  // namespace iwb::walls
