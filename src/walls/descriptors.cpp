#include "walls/descriptors.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <unsupported/Eigen/FFT>

#include "walls/gauge_windows.hpp"

namespace iwb::walls {

namespace {

constexpr double kMetresPerMm = 1e-3;
constexpr int kLineSamplesPerD50 = 50;  // a sawtooth's apex falls within 2 % of a d50 window
constexpr int kBinsPerDecade = 5;
constexpr double kSelfAffineR2 = 0.9;  // below, the spectrum is not one power law
constexpr int kMinFitBins = 4;

// The surface on rows along x: an areal map at its own nodes (between them it is bilinear and
// would add a spectrum of its own), a line profile finely.
struct Samples {
  double h;
  int n;
  std::vector<std::vector<double>> rows;
};

Samples sample(const RoughnessProfile& p, double length, double width, double d50) {
  Samples s;
  const int rows = p.areal() ? p.map->ny() : 1;
  s.n = p.areal() ? p.map->nx() : 2 * int(std::ceil(0.5 * kLineSamplesPerD50 * length / d50));
  s.h = length / s.n;
  for (int j = 0; j < rows; ++j) {
    std::vector<double> z(s.n);
    for (int i = 0; i < s.n; ++i) z[i] = p.surface_at(i * s.h, width * j / rows);
    s.rows.push_back(std::move(z));
  }
  return s;
}

// R_max over every window of d50 along each row (periodic): the largest and the mean.
std::pair<double, double> gauge_ranges(const Samples& s, double d50) {
  const int w = std::max(1, int(std::lround(d50 / s.h)));
  GaugeRanges r;
  for (const auto& row : s.rows) {
    std::vector<double> z(row);
    for (int k = 0; k < w; ++k) z.push_back(row[k % s.n]);
    add_gauge_ranges(z, w, s.n, r);
  }
  return {r.largest, r.sum / r.windows};
}

// One-sided PSD along x (k = 1 .. n/2, m^3) and the autocovariance (lags 0 .. n/2), both averaged
// over the rows, each row about its own mean.
std::pair<std::vector<double>, std::vector<double>> spectra(const Samples& s, double length) {
  Eigen::FFT<double> fft;
  const int half = s.n / 2;
  std::vector<double> psd(half + 1, 0.0), acov(half + 1, 0.0);
  for (const auto& row : s.rows) {
    double mean = 0.0;
    for (double v : row) mean += v;
    mean /= s.n;
    std::vector<double> z(row);
    for (double& v : z) v -= mean;
    std::vector<std::complex<double>> Z;
    fft.fwd(Z, z);
    std::vector<std::complex<double>> power(s.n);
    for (int k = 0; k < s.n; ++k) power[k] = std::norm(Z[k]);
    for (int k = 1; k <= half; ++k)  // Nyquist's bin has no mirror image
      psd[k] += (k == half && s.n % 2 == 0 ? 1.0 : 2.0) * std::norm(Z[k]) * s.h * s.h / length;
    std::vector<std::complex<double>> c;
    fft.inv(c, power);  // Eigen's inverse divides by n: c[m] = sum_i z_i z_{i+m}
    for (int m = 0; m <= half; ++m) acov[m] += c[m].real() / s.n;
  }
  for (auto* v : {&psd, &acov})
    for (double& x : *v) x /= double(s.rows.size());
  return {psd, acov};
}

double correlation_length(const std::vector<double>& acov, double h) {
  if (acov[0] <= 0.0) return 0.0;
  for (std::size_t m = 1; m < acov.size(); ++m) {
    const double r0 = acov[m - 1] / acov[0], r1 = acov[m] / acov[0];
    if (r1 < std::exp(-1.0)) return h * (double(m - 1) + (r0 - std::exp(-1.0)) / (r0 - r1));
  }
  return h * double(acov.size() - 1);
}

std::vector<SpectrumBin> binned(const std::vector<double>& psd, double length) {
  std::vector<SpectrumBin> bins;
  const int half = int(psd.size()) - 1;
  int k = 1;
  while (k <= half) {
    // the bin's wavenumbers k .. k_end share one fifth of a decade of wavelength
    const int k_end = std::max(k, int(std::floor(k * std::pow(10.0, 1.0 / kBinsPerDecade) - 1e-9)));
    // the bin's wavelength: the power-weighted mean of its log wavelengths (a single line of a
    // periodic profile keeps its own), the plain mean where the bin holds no power
    double log_lambda = 0.0, weighted = 0.0, sum = 0.0;
    int count = 0;
    for (int j = k; j <= std::min(k_end, half); ++j, ++count) {
      log_lambda += std::log(length / j), weighted += psd[j] * std::log(length / j), sum += psd[j];
    }
    const double centre = sum > 0.0 ? weighted / sum : log_lambda / count;
    bins.push_back({std::exp(centre), sum / count, sum / length});
    k = k_end + 1;
  }
  return bins;
}

void fit_hurst(RoughnessDescriptors& r, double d50) {
  std::vector<double> x, y;
  double top = 0.0;
  for (const auto& b : r.spectrum) top = std::max(top, b.psd_m3);
  for (const auto& b : r.spectrum)
    if (b.wavelength_m >= 4.0 * r.sample_spacing_m && b.wavelength_m <= r.correlation_length_m &&
        b.psd_m3 > 1e-12 * top)
      x.push_back(std::log(1.0 / b.wavelength_m)), y.push_back(std::log(b.psd_m3));
  if (int(x.size()) < kMinFitBins) {
    r.hurst_note = fmt::format(
        "{} spectrum bins between 4 samples ({:.3g} d50) and lambda_c ({:.3g} d50); a fit needs {}",
        x.size(), 4.0 * r.sample_spacing_m / d50, r.correlation_length_m / d50, kMinFitBins);
    return;
  }
  const double n = double(x.size());
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < x.size(); ++i) mx += x[i] / n, my += y[i] / n;
  double sxx = 0, sxy = 0, syy = 0;
  for (std::size_t i = 0; i < x.size(); ++i)
    sxx += (x[i] - mx) * (x[i] - mx), sxy += (x[i] - mx) * (y[i] - my),
        syy += (y[i] - my) * (y[i] - my);
  const double slope = sxy / sxx;
  const double H = 0.5 * (-slope - 1.0);
  r.hurst_fit_r2 = syy > 0.0 ? sxy * sxy / (sxx * syy) : 0.0;
  const std::string range =
      fmt::format("over wavelengths {:.3g}-{:.3g} d50, {} bins", 4.0 * r.sample_spacing_m / d50,
                  r.correlation_length_m / d50, x.size());
  if (r.hurst_fit_r2 < kSelfAffineR2 || !(H > 0.0 && H <= 1.0)) {
    r.hurst_note = fmt::format("not self-affine: PSD ~ f^{:.3g} (H would be {:.3g}, R^2 {:.3f}) {}",
                               slope, H, r.hurst_fit_r2, range);
    return;
  }
  r.hurst = H;
  r.hurst_note = "fit " + range;
}

}  // namespace

RoughnessDescriptors describe_roughness(const RoughnessProfile& profile, double length,
                                        double width, double d50) {
  RoughnessDescriptors r;
  const Samples s = sample(profile, length, width, d50);
  r.sample_spacing_m = s.h;
  r.rows = int(s.rows.size());
  double mean = 0.0, lo = INFINITY, hi = -INFINITY;
  for (const auto& z : s.rows)
    for (double v : z) mean += v, lo = std::min(lo, v), hi = std::max(hi, v);
  const double count = double(s.n) * double(s.rows.size());
  mean /= count;
  for (const auto& z : s.rows)
    for (int i = 0; i < s.n; ++i) {
      r.R_a_m += std::abs(z[i] - mean) / count;
      r.R_q_m += (z[i] - mean) * (z[i] - mean) / count;
      r.mean_abs_slope += std::abs(z[(i + 1) % s.n] - z[i]) / s.h / count;
    }
  r.R_q_m = std::sqrt(r.R_q_m);
  r.R_max_m = hi - lo;
  const auto [largest, mean_range] = gauge_ranges(s, d50);
  r.R_n = largest / d50, r.R_n_mean = mean_range / d50;
  if (r.R_max_m == 0.0) {
    r.hurst_note = "flat";
    return r;
  }
  const auto [psd, acov] = spectra(s, length);
  r.correlation_length_m = correlation_length(acov, s.h);
  r.spectrum = binned(psd, length);
  fit_hurst(r, d50);
  return r;
}

nlohmann::json to_json(const RoughnessDescriptors& r, double d50) {
  nlohmann::json spectrum = nlohmann::json::array();
  for (const auto& b : r.spectrum)
    spectrum.push_back({{"wavelength_d50", b.wavelength_m / d50},
                        {"psd_mm3", b.psd_m3 / (kMetresPerMm * kMetresPerMm * kMetresPerMm)},
                        {"variance_mm2", b.variance_m2 / (kMetresPerMm * kMetresPerMm)}});
  return {{"R_n", r.R_n},
          {"R_n_mean", r.R_n_mean},
          {"R_max_d50", r.R_max_m / d50},
          {"R_a_d50", r.R_a_m / d50},
          {"R_q_d50", r.R_q_m / d50},
          {"mean_abs_slope", r.mean_abs_slope},
          {"correlation_length_d50", r.correlation_length_m / d50},
          {"hurst", r.hurst ? nlohmann::json(*r.hurst) : nlohmann::json()},
          {"hurst_fit_r2", r.hurst_fit_r2},
          {"hurst_note", r.hurst_note},
          {"sample_spacing_d50", r.sample_spacing_m / d50},
          {"rows", r.rows},
          {"spectrum", spectrum}};
}

std::string to_text(const RoughnessDescriptors& r, double d50) {
  std::string s = fmt::format(
      "  R_n = R_max(d50)/d50  {:.4g} (largest), {:.4g} (mean over windows)\n"
      "  R_max                 {:.4g} d50\n"
      "  R_a, R_q              {:.4g}, {:.4g} d50\n"
      "  mean |dz/dx|          {:.4g}\n"
      "  correlation length    {:.4g} d50\n"
      "  Hurst exponent        {} ({})\n"
      "  sampled               every {:.3g} d50 on {} row(s) along x\n",
      r.R_n, r.R_n_mean, r.R_max_m / d50, r.R_a_m / d50, r.R_q_m / d50, r.mean_abs_slope,
      r.correlation_length_m / d50, r.hurst ? fmt::format("{:.3g}", *r.hurst) : std::string("none"),
      r.hurst_note, r.sample_spacing_m / d50, r.rows);
  if (!r.spectrum.empty()) {
    s += "  spectrum along x      wavelength (d50)   PSD (mm^3)   share of R_q^2\n";
    double total = 0.0;
    for (const auto& b : r.spectrum) total += b.variance_m2;
    for (const auto& b : r.spectrum)
      if (b.variance_m2 > 1e-4 * total)
        s += fmt::format(
            "                        {:>10.4g}   {:>12.4g}   {:>8.1f} %\n", b.wavelength_m / d50,
            b.psd_m3 / (kMetresPerMm * kMetresPerMm * kMetresPerMm), 100.0 * b.variance_m2 / total);
  }
  return s;
}

}  // namespace iwb::walls
