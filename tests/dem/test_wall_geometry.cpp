// Wall meshes: inside the periodic box, the profile's heights, normals into the granular layer,
// no triangle longer than the strip size.
#include <catch2/catch.hpp>

#include "dem/wall_geometry.hpp"

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
  const auto tris = profile_surface(RoughnessProfile{ProfileKind::kSinusoid, 4e-3, 1e-3}, 8e-3, 4e-3, 0, false, 2e-3);
  const std::string stl = to_stl(tris, "w");
  std::size_t facets = 0;
  for (auto p = stl.find("facet normal"); p != std::string::npos; p = stl.find("facet normal", p + 1)) ++facets;
  CHECK(facets == tris.size());
  CHECK(stl.rfind("endsolid w") != std::string::npos);
}
