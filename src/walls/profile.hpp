#pragma once
// A wall's rough surface (../shared/spec/DEM.md): line profiles along x with ridges along y
// (sawtooth, sinusoid; R_max = height, period = pitch), a square layer of glued spheres of diameter
// `height_m` at centre spacing `pitch_m` on a flat base, or an areal height map (random, file).
#include <memory>
#include <string>

#include "walls/height_map.hpp"

namespace iwb::walls {

enum class ProfileKind { kFlat, kSawtooth, kSinusoid, kGlued, kRandom, kFile };

struct RoughnessProfile {
  ProfileKind kind = ProfileKind::kFlat;
  double pitch_m = 0.0;
  double height_m = 0.0;
  std::shared_ptr<const HeightMap> map = nullptr;  // kRandom, kFile: the surface, its minimum at 0
  std::string file = {};                           // kFile: where it was read
  std::string file_sha256 = {};  // kFile: its content's, when it was read (the scene's identity)
  double untiled_r_max_m = 0.0;  // kFile: the measurement's largest R_max over d50 before tiling

  // Height of the surface above the base plane at (x, y); line profiles and glued walls do not
  // depend on y (glued: along a row of centres).
  double surface_at(double x, double y = 0.0) const;
  bool areal() const { return map != nullptr; }

  // Normalized roughness R_n = R_max(L = d50) / d50 (Uesugi & Kishida 1986): the largest
  // peak-to-valley height within any gauge window of length d50 along x, over d50.
  double normalized_roughness(double d50) const;
  double mean_height_m() const;  // mean surface height above the base plane
  double max_height_m() const;   // the highest point above the base plane
  std::string describe() const;
};

const char* to_string(ProfileKind k);

}  // namespace iwb::walls
