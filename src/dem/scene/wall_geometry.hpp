#pragma once
// Triangle meshes of the roughness profiles for the engines. The profile runs along x with ridges
// along y; the surface is cut into strips no wider than `max_edge` in both x and y so that no
// triangle spans a periodic length (LIGGGHTS: a triangle must not touch its own periodic image).
#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products of triangle edges
#include <filesystem>
#include <string>
#include <vector>

#include "dem/scene/scene.hpp"

namespace iwb::dem {

struct Triangle {
  Eigen::Vector3d a, b, c;
};

// The surface z = z_base + f(x) (facing up) or z_base - f(x) (facing down, for the top plate),
// over [0, length] x [0, width].
std::vector<Triangle> profile_surface(const RoughnessProfile& profile, double length, double width,
                                      double z_base, bool facing_down, double max_edge);

std::string to_stl(const std::vector<Triangle>& triangles, const std::string& name);

// The most triangles whose centres, seen from above, lie in one square of side 3 `reach` (the 3 x 3
// bins of a grain's neighbour stencil, each `reach` = d_max + skin wide): what the mesh neighbour
// list of one grain can hold at most.
int densest_triangles(const std::vector<Triangle>& triangles, double reach);
// The same over the scene's wall and plate meshes.
int densest_scene_triangles(const Scene& scene, double plate_z, double reach);

// wall.stl (the tested wall's surface on z = 0) and top.stl (the plate's, facing down from
// plate_z), as both engines read them; edges no longer than d50.
struct SceneMeshes {
  std::string wall_stl, top_stl;
};
SceneMeshes scene_meshes(const Scene& scene, double plate_z);
// The same, written into dir.
void write_scene_meshes(const Scene& scene, double plate_z, const std::filesystem::path& dir);

}  // namespace iwb::dem
