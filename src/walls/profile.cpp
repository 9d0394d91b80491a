#include "walls/profile.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "walls/gauge_windows.hpp"

namespace iwb::walls {

namespace {

constexpr double kMm = 1e-3;

// R_max over a sliding gauge window of length d50 along x on the surface sampled `samples` times
// over one period, the largest over `rows` lines along x (Uesugi & Kishida's definition on a trace,
// applied to every trace).
double sampled_r_max(const RoughnessProfile& p, double period, int samples, double width, int rows,
                     double d50) {
  const double dx = period / samples;
  const int window = std::max(1, int(std::lround(d50 / dx)));
  GaugeRanges r;
  for (int row = 0; row < rows; ++row) {
    const double y = width * row / rows;
    std::vector<double> z(samples + window);  // at (i + j) dx: past the period the profile repeats
    for (int i = 0; i < samples + window; ++i) z[i] = p.surface_at(i * dx, y);
    add_gauge_ranges(z, window, samples, r);
  }
  return r.largest;
}

}  // namespace

double RoughnessProfile::surface_at(double x, double y) const {
  if (kind == ProfileKind::kFlat) return 0.0;
  if (areal()) return map->at(x, y);
  const double u = x - pitch_m * std::floor(x / pitch_m);  // position within one period
  switch (kind) {
    case ProfileKind::kSawtooth:
      return height_m * (u < 0.5 * pitch_m ? u : pitch_m - u) / (0.5 * pitch_m);
    case ProfileKind::kSinusoid:
      return 0.5 * height_m * (1.0 - std::cos(2.0 * M_PI * u / pitch_m));
    case ProfileKind::kGlued: {  // spheres centred at pitch/2 (+- pitch for overlapping ones)
      const double r = 0.5 * height_m;
      double z = 0.0;
      for (double c : {-0.5 * pitch_m, 0.5 * pitch_m, 1.5 * pitch_m}) {
        const double dx = u - c;
        if (std::abs(dx) <= r) z = std::max(z, r + std::sqrt(r * r - dx * dx));
      }
      return z;
    }
    case ProfileKind::kFlat:
    case ProfileKind::kRandom:
    case ProfileKind::kFile:
      break;
  }
  return 0.0;
}

double RoughnessProfile::normalized_roughness(double d50) const {
  if (kind == ProfileKind::kFlat) return 0.0;
  if (kind == ProfileKind::kGlued) return sampled_r_max(*this, pitch_m, 4000, 0.0, 1, d50) / d50;
  if (areal()) {  // 50 samples a d50 along every row of the map
    const int samples = int(std::ceil(50.0 * map->length() / d50));
    return sampled_r_max(*this, map->length(), samples, map->width(), map->ny(), d50) / d50;
  }
  const double half = 0.5 * pitch_m;  // a rise from valley to peak spans half a pitch
  if (d50 >= half) return height_m / d50;
  if (kind == ProfileKind::kSawtooth) return height_m * (d50 / half) / d50;
  return height_m * std::sin(M_PI * d50 / pitch_m) / d50;  // sinusoid: steepest window
}

double RoughnessProfile::mean_height_m() const {
  if (areal()) return map->mean();
  if (kind != ProfileKind::kGlued) return 0.5 * height_m;
  constexpr int kSamples = 2000;
  double sum = 0.0;
  for (int i = 0; i < kSamples; ++i) sum += surface_at((i + 0.5) * pitch_m / kSamples);
  return sum / kSamples;
}

double RoughnessProfile::max_height_m() const {
  if (areal()) return map->max();
  return height_m;  // line profiles: R_max; glued: the sphere diameter
}

std::string RoughnessProfile::describe() const {
  if (kind == ProfileKind::kFlat) return "flat";
  if (kind == ProfileKind::kGlued)
    return fmt::format("glued spheres of {:g} mm at {:g} mm spacing", height_m / kMm,
                       pitch_m / kMm);
  if (kind == ProfileKind::kRandom)
    return fmt::format("random self-affine, R_max {:.4g} mm over a {} x {} grid", height_m / kMm,
                       map->nx(), map->ny());
  if (kind == ProfileKind::kFile)
    return fmt::format("measured ({}), R_max {:.4g} mm over a {} x {} grid", file, height_m / kMm,
                       map->nx(), map->ny());
  return fmt::format("{} pitch {:g} mm, R_max {:g} mm", to_string(kind), pitch_m / kMm,
                     height_m / kMm);
}

const char* to_string(ProfileKind k) {
  switch (k) {
    case ProfileKind::kFlat:
      return "flat";
    case ProfileKind::kSawtooth:
      return "sawtooth";
    case ProfileKind::kSinusoid:
      return "sinusoid";
    case ProfileKind::kGlued:
      return "glued";
    case ProfileKind::kRandom:
      return "random";
    case ProfileKind::kFile:
      return "file";
  }
  return "?";
}

}  // namespace iwb::walls
