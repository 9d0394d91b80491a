#include "dem/scene/wall_geometry.hpp"

#include <fmt/core.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>

#include "io/run_directory.hpp"

namespace iwb::dem {

namespace {

// Breakpoints along x and the profile height at each, over one pitch.
std::vector<std::pair<double, double>> one_pitch(const RoughnessProfile& p) {
  switch (p.kind) {
    case ProfileKind::kSawtooth:
      return {{0.0, 0.0}, {0.5 * p.pitch_m, p.height_m}};
    case ProfileKind::kSinusoid: {
      constexpr int kSegmentsPerPitch = 16;  // chord error < 2 % of R_max
      std::vector<std::pair<double, double>> pts;
      for (int i = 0; i < kSegmentsPerPitch; ++i) {
        const double x = p.pitch_m * i / kSegmentsPerPitch;
        pts.push_back({x, 0.5 * p.height_m * (1.0 - std::cos(2.0 * M_PI * x / p.pitch_m))});
      }
      return pts;
    }
    case ProfileKind::kFlat:
    case ProfileKind::kGlued:   // the mesh is the flat base; the spheres are engine particles
    case ProfileKind::kRandom:  // areal: meshed from the map
    case ProfileKind::kFile:
      return {{0.0, 0.0}};
  }
  return {};
}

// A quadrilateral cell p00 p10 p11 p01 as two triangles, counter-clockwise seen from the particles:
// the normals point into the granular layer.
void push_cell(std::vector<Triangle>& out, const Eigen::Vector3d& p00, const Eigen::Vector3d& p10,
               const Eigen::Vector3d& p11, const Eigen::Vector3d& p01, bool facing_down) {
  if (facing_down) {
    out.push_back({p00, p11, p10});
    out.push_back({p00, p01, p11});
  } else {
    out.push_back({p00, p10, p11});
    out.push_back({p00, p11, p01});
  }
}

// An areal height map: two triangles per grid cell, the far edges on the first row and column.
std::vector<Triangle> areal_surface(const walls::HeightMap& map, double z_base, bool facing_down) {
  const double sign = facing_down ? -1.0 : 1.0;
  auto point = [&](int i, int j) {
    return Eigen::Vector3d(map.length() * i / map.nx(), map.width() * j / map.ny(),
                           z_base + sign * map.node(i, j));
  };
  std::vector<Triangle> out;
  for (int j = 0; j < map.ny(); ++j)
    for (int i = 0; i < map.nx(); ++i)
      push_cell(out, point(i, j), point(i + 1, j), point(i + 1, j + 1), point(i, j + 1),
                facing_down);
  return out;
}

}  // namespace

std::vector<Triangle> profile_surface(const RoughnessProfile& profile, double length, double width,
                                      double z_base, bool facing_down, double max_edge) {
  if (profile.areal()) return areal_surface(*profile.map, z_base, facing_down);
  // x breakpoints over the whole length
  std::vector<std::pair<double, double>> xs;
  // A flat wall (and the base of a glued one) is cut into equal strips no longer than max_edge;
  // profiles repeat their pitch, which divides the length (checked when the scene is read).
  const bool flat_mesh = profile.kind == ProfileKind::kFlat || profile.kind == ProfileKind::kGlued;
  const int pitches = flat_mesh ? std::max(1, int(std::ceil(length / max_edge)))
                                : int(std::lround(length / profile.pitch_m));
  const double pitch = length / pitches;
  for (int k = 0; k < pitches; ++k)
    for (const auto& [x, h] : one_pitch(profile)) xs.push_back({k * pitch + x, h});
  xs.push_back({length, 0.0});
  const int ny = std::max(2, int(std::ceil(width / max_edge)));
  const double sign = facing_down ? -1.0 : 1.0;
  auto point = [&](std::size_t i, int j) {
    return Eigen::Vector3d(xs[i].first, width * j / ny, z_base + sign * xs[i].second);
  };
  std::vector<Triangle> out;
  for (std::size_t i = 0; i + 1 < xs.size(); ++i) {
    for (int j = 0; j < ny; ++j) {
      push_cell(out, point(i, j), point(i + 1, j), point(i + 1, j + 1), point(i, j + 1),
                facing_down);
    }
  }
  return out;
}

std::string to_stl(const std::vector<Triangle>& triangles, const std::string& name) {
  std::string s = "solid " + name + "\n";
  for (const auto& t : triangles) {
    const Eigen::Vector3d n = (t.b - t.a).cross(t.c - t.a).normalized();
    s += fmt::format("facet normal {:.9g} {:.9g} {:.9g}\nouter loop\n", n.x(), n.y(), n.z());
    for (const auto* v : {&t.a, &t.b, &t.c})
      s += fmt::format("vertex {:.12g} {:.12g} {:.12g}\n", v->x(), v->y(), v->z());
    s += "endloop\nendfacet\n";
  }
  return s + "endsolid " + name + "\n";
}

int densest_triangles(const std::vector<Triangle>& triangles, double reach) {
  std::map<std::pair<long, long>, int> bins;  // by the centre's bin of side `reach`
  for (const auto& t : triangles) {
    const Eigen::Vector3d c = (t.a + t.b + t.c) / 3.0;
    ++bins[{std::lround(std::floor(c.x() / reach)), std::lround(std::floor(c.y() / reach))}];
  }
  int densest = 0;
  for (const auto& [bin, n] : bins) {
    int around = 0;
    for (long i = -1; i <= 1; ++i)
      for (long j = -1; j <= 1; ++j)
        if (const auto it = bins.find({bin.first + i, bin.second + j}); it != bins.end())
          around += it->second;
    densest = std::max(densest, around);
  }
  return densest;
}

int densest_scene_triangles(const Scene& s, double plate_z, double reach) {
  const double max_edge = s.particles.d50_m;
  return std::max(
      densest_triangles(profile_surface(s.wall, s.length_m, s.width_m, 0.0, false, max_edge),
                        reach),
      densest_triangles(profile_surface(s.plate, s.length_m, s.width_m, plate_z, true, max_edge),
                        reach));
}

SceneMeshes scene_meshes(const Scene& s, double plate_z) {
  const double max_edge = s.particles.d50_m;
  return {to_stl(profile_surface(s.wall, s.length_m, s.width_m, 0.0, false, max_edge), "wall"),
          to_stl(profile_surface(s.plate, s.length_m, s.width_m, plate_z, true, max_edge), "top")};
}

void write_scene_meshes(const Scene& s, double plate_z, const std::filesystem::path& dir) {
  const SceneMeshes meshes = scene_meshes(s, plate_z);
  io::write_atomically(dir / "wall.stl", meshes.wall_stl);
  io::write_atomically(dir / "top.stl", meshes.top_stl);
}

}  // namespace iwb::dem
