// The triangles on a smooth mesh's terminator (scene/terminator.hpp), against
// their definition checked pair by pair: a triangle is on it where some
// triangle round one of its corners' points has the light on the other side
// (strictly in front against not) and is shaded alike there (normals within
// 10 degrees).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <glm/geometric.hpp>

#include "mesh/topology/crease_normals.hpp"
#include "scene/scene.hpp"
#include "scene/terminator.hpp"
#include "tests/mesh/mesh_builders.hpp"

namespace umbra {
namespace {

// The tests' torus of n x m quads, fanned into triangles, as a mesh.
Mesh torus(int n, int m) {
  const PolygonSoup soup = test::triangulated(test::quad_torus(n, m, 1.0, 0.35));
  Mesh mesh;
  mesh.positions = soup.points;
  for (size_t p = 0; p < soup.polygon_count(); ++p) mesh.triangles.push_back({soup.polygon(p)[0], soup.polygon(p)[1], soup.polygon(p)[2]});
  return mesh;
}

std::vector<uint8_t> by_definition(const Mesh& mesh, const std::vector<int8_t>& sides) {
  std::vector<uint8_t> on_terminator(mesh.triangles.size(), 0);
  for (size_t t = 0; t < mesh.triangles.size(); ++t)
    for (size_t c = 0; c < 3; ++c)
      for (size_t u = 0; u < mesh.triangles.size(); ++u)
        for (size_t d = 0; d < 3; ++d)
          if (mesh.triangles[u][d] == mesh.triangles[t][c] && (sides[t] > 0) != (sides[u] > 0) &&
              glm::dot(mesh.triangle_normals[t][c], mesh.triangle_normals[u][d]) >= 0.98480775f)
            on_terminator[t] = 1;
  return on_terminator;
}

TEST(Terminator, TheTrianglesOnItAreThoseOfItsDefinition) {
  Mesh mesh = torus(24, 12);  // 576 triangles: the definition's n^2 pairs stay cheap
  mesh.triangle_normals = crease_normals(mesh.positions, mesh.triangles, 40.0);
  for (const glm::dvec3 light : {glm::dvec3(0.5, 0.9, 1.8), glm::dvec3(-2.0, 0.3, 0.1), glm::dvec3(0.0, 0.0, 0.2)}) {
    SCOPED_TRACE("light " + std::to_string(light.x) + " " + std::to_string(light.y) + " " + std::to_string(light.z));
    const std::vector<int8_t> sides = triangle_light_sides(mesh, light);
    const auto expected = by_definition(mesh, sides);
    size_t on_it = 0;
    for (const uint8_t t : expected) on_it += t;
    EXPECT_GT(on_it, 20u) << "a light that leaves no terminator tests nothing";
    EXPECT_LT(on_it, mesh.triangles.size() / 2) << "nor does one that puts every triangle on it";
    EXPECT_EQ(terminator_triangles(mesh, sides), expected);
  }
}

}  // namespace
}  // namespace umbra
