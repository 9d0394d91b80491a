// Wall meshes: inside the periodic box, the profile's heights, normals into the granular layer,
// no triangle longer than the strip size.
#include <catch2/catch.hpp>
#include <cmath>

#include "dem/scene/wall_geometry.hpp"
#include "walls/random_surface.hpp"

using namespace iwb::dem;

TEST_CASE("sawtooth wall: inside the box, heights 0..R_max, normals up", "[dem]") {
  const RoughnessProfile saw{ProfileKind::kSawtooth, 4e-3, 1e-3};
  const auto tris = profile_surface(saw, 24e-3, 8e-3, 0.0, false, 2e-3);
  CHECK(tris.size() == 6 * 2 * 2 * 4);  // pitches x faces x triangles x strips in y
  double zmax = -1;
  for (const auto& t : tris) {
    for (const auto* v : {&t.a, &t.b, &t.c}) {
      CHECK(v->x() >= 0.0);
      CHECK(v->x() <= 24e-3 + 1e-15);
      CHECK(v->y() >= 0.0);
      CHECK(v->y() <= 8e-3 + 1e-15);
      zmax = std::max(zmax, v->z());
    }
    CHECK((t.b - t.a).cross(t.c - t.a).z() > 0.0);
    CHECK((t.b - t.a).norm() <= std::hypot(2e-3, 2e-3, 1e-3) + 1e-12);
  }
  CHECK(zmax == Approx(1e-3));
}

TEST_CASE("top plate faces down and a flat wall is cut into strips", "[dem]") {
  const RoughnessProfile saw{ProfileKind::kSawtooth, 4e-3, 2e-3};
  for (const auto& t : profile_surface(saw, 24e-3, 8e-3, 0.02, true, 2e-3)) {
    CHECK((t.b - t.a).cross(t.c - t.a).z() < 0.0);
    for (const auto* v : {&t.a, &t.b, &t.c}) CHECK(v->z() <= 0.02 + 1e-15);
  }
  const auto flat = profile_surface(RoughnessProfile{}, 25e-3, 8e-3, 0.0, false, 2e-3);
  CHECK(flat.size() == 13 * 2 * 4);  // ceil(25/2) strips in x
  for (const auto& t : flat) CHECK(t.a.z() == 0.0);
}

TEST_CASE("STL text has one facet per triangle with unit normals", "[dem]") {
  const auto tris = profile_surface(RoughnessProfile{ProfileKind::kSinusoid, 4e-3, 1e-3}, 8e-3,
                                    4e-3, 0, false, 2e-3);
  const std::string stl = to_stl(tris, "w");
  std::size_t facets = 0;
  for (auto p = stl.find("facet normal"); p != std::string::npos;
       p = stl.find("facet normal", p + 1))
    ++facets;
  CHECK(facets == tris.size());
  CHECK(stl.rfind("endsolid w") != std::string::npos);
}

TEST_CASE(
    "an areal random wall's mesh covers the box once, faces the grains and passes through the "
    "map's nodes",
    "[dem]") {
  const double L = 12e-3, W = 4e-3;
  const auto map = std::make_shared<const walls::HeightMap>(
      walls::random_surface({0.3e-3, 1e-3, 0.8, 3}, L, W, 0.5e-3));
  const RoughnessProfile wall{ProfileKind::kRandom, 0.0, map->max(), map};
  for (bool down : {false, true}) {
    const auto tris = profile_surface(wall, L, W, 5e-3, down, 2e-3);
    CHECK(tris.size() == 2u * std::size_t(map->nx() * map->ny()));
    double projected = 0.0;
    for (const auto& t : tris) {
      const Eigen::Vector3d n = (t.b - t.a).cross(t.c - t.a);
      CHECK((down ? -n.z() : n.z()) > 0.0);  // towards the granular layer
      projected += 0.5 * std::abs(n.z());
      for (const auto* v : {&t.a, &t.b, &t.c})
        CHECK(v->z() == Approx(5e-3 + (down ? -1 : 1) * map->at(v->x(), v->y())).margin(1e-12));
    }
    CHECK(projected == Approx(L * W).epsilon(1e-12));
  }
}

// Issue 60: a measured map at 0.1 d50 ended LIGGGHTS with "mesh neighbor list overflow" (a grain's
// mesh neighbours beyond `neigh_modify one`); the engine's limit is now sized from the densest
// part of the mesh. On a flat wall cut into cells of side e, a 3 x 3 block of bins of side r holds
// 9 (r / e)^2 cells of 2 triangles each, and halving e quadruples it.
TEST_CASE("the densest 3 x 3 bins of a wall mesh hold 18 (reach / edge)^2 triangles when flat",
          "[dem]") {
  const double reach = 2e-3;
  for (double edge : {0.5e-3, 0.25e-3}) {
    const auto flat = profile_surface(RoughnessProfile{}, 24e-3, 24e-3, 0.0, false, edge);
    CHECK(densest_triangles(flat, reach) == int(std::lround(18.0 * std::pow(reach / edge, 2))));
  }
}
