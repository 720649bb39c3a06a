// Vertex colours as files give them (PLY red/green/blue, OBJ "v x y z r g b",
// glTF COLOR_0): read per point, kept per triangle corner through the check
// (two points at one place may differ), and drawn blended across each
// triangle by the GL and the ray-cast reference alike.
#include <gtest/gtest.h>

#include <string>

#include "hard_case_scenes.hpp"
#include "image_agreement.hpp"
#include "mesh/check/mesh_check.hpp"
#include "mesh/io/mesh_file.hpp"
#include "scene/staged_scene.hpp"
#include "tests/mesh/interchange_writers.hpp"
#include "tests/mesh/mesh_builders.hpp"

namespace umbra {
namespace {

// The unit cube's 8 corners, each its own colour: (x, y, z) as (r, g, b),
// with blue at least 0.2 so that no corner is black.
glm::vec3 corner_colour(const glm::dvec3& p) { return {float(p.x), float(p.y), float(std::max(p.z, 0.2))}; }

std::string coloured_ply(const PolygonSoup& cube) {
  std::string text = "ply\nformat ascii 1.0\nelement vertex " + std::to_string(cube.points.size()) +
                     "\nproperty float x\nproperty float y\nproperty float z\n"
                     "property uchar red\nproperty uchar green\nproperty uchar blue\nelement face " +
                     std::to_string(cube.polygon_count()) + "\nproperty list uchar int vertex_indices\nend_header\n";
  for (const glm::dvec3& p : cube.points) {
    const glm::vec3 c = corner_colour(p);
    text += std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + " " + std::to_string(int(c.r * 255 + 0.5f)) +
            " " + std::to_string(int(c.g * 255 + 0.5f)) + " " + std::to_string(int(c.b * 255 + 0.5f)) + "\n";
  }
  for (size_t f = 0; f < cube.polygon_count(); ++f)
    text += "3 " + std::to_string(cube.polygon(f)[0]) + " " + std::to_string(cube.polygon(f)[1]) + " " + std::to_string(cube.polygon(f)[2]) + "\n";
  return text;
}

std::string coloured_obj(const PolygonSoup& cube) {
  std::string text;
  for (const glm::dvec3& p : cube.points) {
    const glm::vec3 c = corner_colour(p);
    text += "v " + std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + " " + std::to_string(c.r) + " " +
            std::to_string(c.g) + " " + std::to_string(c.b) + "\n";
  }
  for (size_t f = 0; f < cube.polygon_count(); ++f)
    text += "f " + std::to_string(cube.polygon(f)[0] + 1) + " " + std::to_string(cube.polygon(f)[1] + 1) + " " +
            std::to_string(cube.polygon(f)[2] + 1) + "\n";
  return text;
}

// COLOR_0 as normalised unsigned bytes, RGBA: positions, then colours, then indices.
std::string coloured_gltf(const PolygonSoup& cube) {
  std::string buffer;
  for (const glm::dvec3& p : cube.points) test::append_le(buffer, float(p.x)), test::append_le(buffer, float(p.y)), test::append_le(buffer, float(p.z));
  for (const glm::dvec3& p : cube.points) {
    const glm::vec3 c = corner_colour(p);
    for (const float channel : {c.r, c.g, c.b, 1.0f}) buffer += char(uint8_t(channel * 255 + 0.5f));
  }
  for (const uint32_t c : cube.corners) test::append_le(buffer, c);
  const size_t n = cube.points.size();
  const std::string views = R"([{"buffer": 0, "byteOffset": 0, "byteLength": )" + std::to_string(12 * n) +
                            R"(}, {"buffer": 0, "byteOffset": )" + std::to_string(12 * n) + R"(, "byteLength": )" + std::to_string(4 * n) +
                            R"(}, {"buffer": 0, "byteOffset": )" + std::to_string(16 * n) + R"(, "byteLength": )" +
                            std::to_string(4 * cube.corners.size()) + "}]";
  const std::string json =
      R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}], )"
      R"("meshes": [{"primitives": [{"attributes": {"POSITION": 0, "COLOR_0": 1}, "indices": 2}]}], "buffers": [{"byteLength": )" +
      std::to_string(buffer.size()) + R"(, "uri": "data:application/octet-stream;base64,)" + test::base64(buffer) + R"("}], "bufferViews": )" +
      views + R"(, "accessors": [{"bufferView": 0, "componentType": 5126, "count": )" + std::to_string(n) +
      R"(, "type": "VEC3"}, {"bufferView": 1, "componentType": 5121, "normalized": true, "count": )" + std::to_string(n) +
      R"(, "type": "VEC4"}, {"bufferView": 2, "componentType": 5125, "count": )" + std::to_string(cube.corners.size()) +
      R"(, "type": "SCALAR"}]})";
  return json;
}

TEST(VertexColours, EachFormatReadsAColourPerPoint) {
  const PolygonSoup cube = test::unit_cube();
  for (const auto& [name, text] : {std::pair{"cube.ply", coloured_ply(cube)}, std::pair{"cube.obj", coloured_obj(cube)},
                                   std::pair{"cube.gltf", coloured_gltf(cube)}}) {
    const PolygonSoup soup = parse_polygon_soup(text, name);
    ASSERT_EQ(soup.point_colors.size(), cube.points.size()) << name;
    for (size_t i = 0; i < cube.points.size(); ++i)
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(soup.point_colors[i][c], corner_colour(cube.points[i])[c], 0.5 / 255 + 1e-6) << name << " point " << i;
  }
  // One more number after x y z is OBJ's w, not a colour; none at all, no colours.
  EXPECT_TRUE(parse_polygon_soup("v 0 0 0 1\nv 1 0 0 1\nv 0 1 0 1\nf 1 2 3\n", "w.obj").point_colors.empty());
  EXPECT_TRUE(parse_polygon_soup(test::obj_text(cube), "plain.obj").point_colors.empty());
  // Three fields that are not all numbers are an error at their place, not black.
  try {
    parse_polygon_soup("v 0 0 0 1 0 x\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "bad.obj");
    ADD_FAILURE() << "a colour that is no number was read";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "bad.obj:1:13: expected a number for the vertex colour blue, got \"x\"");
  }
}

// Two triangles meet at an edge whose two points are written twice, in two
// colours: merged into one vertex for the topology, each triangle keeps its own.
TEST(VertexColours, TheCheckKeepsEachCornersColourWherePointsMerge) {
  const PolygonSoup soup = parse_polygon_soup(
      "v 0 0 0 1 0 0\nv 1 0 0 1 0 0\nv 0 1 0 1 0 0\nv 1 0 0 0 0 1\nv 0 1 0 0 0 1\nv 1 1 0 0 0 1\nf 1 2 3\nf 4 6 5\n", "two.obj");
  const MeshAnalysis a = analyse_mesh(soup, CheckOptions{0.0});
  ASSERT_EQ(a.positions.size(), 4u);  // the shared edge's points merged
  ASSERT_EQ(a.triangle_colors.size(), 2u);
  for (const glm::vec3& c : a.triangle_colors[0]) EXPECT_EQ(c, glm::vec3(1, 0, 0));
  for (const glm::vec3& c : a.triangle_colors[1]) EXPECT_EQ(c, glm::vec3(0, 0, 1));
}

// Staged, each coloured cube shows its colours, and the GL image and the
// ray-cast image agree pixel for pixel away from edges.
TEST(VertexColours, GlAndRayCastDrawTheSameColoursAwayFromEdges) {
  const PolygonSoup cube = test::unit_cube();
  for (const auto& [name, text] : {std::pair{"cube.ply", coloured_ply(cube)}, std::pair{"cube.obj", coloured_obj(cube)},
                                   std::pair{"cube.gltf", coloured_gltf(cube)}}) {
    const Scene scene = parse_scene_or_mesh_file(test::write_mesh(name, text));
    ASSERT_FALSE(scene.meshes[0].triangle_colors.empty()) << name;
    const test::RenderedImages pictures = test::render_gl_and_ray_cast(scene, 64);
    EXPECT_EQ(test::differing_channels_away_from_edges(scene, pictures), 0) << name;
    for (const Image* image : {&pictures.gl, &pictures.cpu}) {
      int coloured = 0;  // pixels far from grey: the floor and an uncoloured cube are grey
      for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) coloured += std::abs(int(image->at(x, y, 0)) - int(image->at(x, y, 2))) > 40;
      EXPECT_GT(coloured, 64) << name;
    }
  }
}

}  // namespace
}  // namespace umbra
