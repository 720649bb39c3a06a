// umbra check --repair OUT.3mf: a print file repaired comes back with its
// objects, build items, transforms, part numbers, unit and colours, so that
// a slicer opens it as it opened the original.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <iterator>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "mesh/io/mesh_file.hpp"
#include "tests/mesh/interchange_writers.hpp"
#include "tests/mesh/mesh_builders.hpp"
#include "tests/tools/command_fixture.hpp"

namespace umbra {
namespace {

using test::CommandResult;
namespace fs = std::filesystem;

// A triangle where the soup puts it, its corners' coordinates turned so
// that its least corner comes first (its winding kept), and its material's
// name.
using PlacedTriangle = std::pair<std::array<double, 9>, std::string>;

std::vector<PlacedTriangle> placed_triangles(const PolygonSoup& soup) {
  std::vector<PlacedTriangle> triangles;
  for (size_t f = 0; f < soup.polygon_count(); ++f) {
    std::array<std::array<double, 3>, 3> p;
    for (size_t k = 0; k < 3; ++k) {
      const glm::dvec3& q = soup.points[soup.polygon(f)[k]];
      p[k] = {q.x, q.y, q.z};
    }
    std::rotate(p.begin(), std::min_element(p.begin(), p.end()), p.end());
    const int m = soup.polygon_material(f);
    triangles.push_back({{p[0][0], p[0][1], p[0][2], p[1][0], p[1][1], p[1][2], p[2][0], p[2][1], p[2][2]},
                         m >= 0 ? soup.materials[size_t(m)].name : ""});
  }
  std::sort(triangles.begin(), triangles.end());
  return triangles;
}

class ThreeMfRepair : public test::CommandTest {};

// An open box (its top missing), red with one blue face, placed twice by a
// components object (scaled by 2; mirrored in z and moved), which a build
// item with a part number places in an inch-based file: repaired, each
// placement is an object of its own, in the box's own coordinates, placed
// by a build item with the composed transform and the part number; the
// colours, the unit and every original triangle come back, where the file
// put them, and the holes are filled.
TEST_F(ThreeMfRepair, APrintFileComesBackWithItsPartsPlacementsAndColours) {
  const PolygonSoup open_box = test::without_faces(test::unit_cube(), {10, 11});
  std::string box = test::threemf_object(2, open_box, 0);
  box.insert(box.find(" type="), " name=\"Box\"");
  box.replace(box.find("v3=\"6\"/>") + 6, 0, " pid=\"1\" p1=\"1\"");  // one triangle blue
  const std::string resources = R"(<basematerials id="1"><base name="red" displaycolor="#FF0000"/><base name="blue" displaycolor="#0000FF"/>)"
                                R"(</basematerials>)" +
                                box +
                                R"(<object id="3" type="model"><components><component objectid="2" transform="2 0 0 0 2 0 0 0 2 0 0 0"/>)"
                                R"(<component objectid="2" transform="1 0 0 0 1 0 0 0 -1 3 0 0"/></components></object>)";
  const std::string input =
      write("tray.3mf", test::threemf(resources, R"(<item objectid="3" partnumber="P-7" transform="1 0 0 0 1 0 0 0 1 10 20 30"/>)", "inch"));
  const CommandResult r = run("check " + input + " --repair " + path("fixed.3mf"));
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("verdict            closed 2-manifold"), std::string::npos) << r.out;

  const PolygonSoup before = read_polygon_soup(input), after = read_polygon_soup(path("fixed.3mf"));
  ASSERT_EQ(before.parts.size(), 2u);
  EXPECT_EQ(before.parts[0].name, "Box");
  EXPECT_EQ(before.parts[0].part_number, "P-7");
  EXPECT_EQ(after.length_unit, "inch");
  ASSERT_EQ(after.parts.size(), 2u);
  for (size_t k = 0; k < 2; ++k) {
    EXPECT_EQ(after.parts[k].name, "Box");
    EXPECT_EQ(after.parts[k].part_number, "P-7");
    EXPECT_EQ(after.parts[k].placement, before.parts[k].placement) << k;
  }
  ASSERT_EQ(after.materials.size(), 2u);
  EXPECT_EQ(after.materials[0].name, "red");
  EXPECT_EQ(after.materials[0].diffuse, glm::dvec3(1, 0, 0));
  EXPECT_EQ(after.materials[1].name, "blue");
  EXPECT_EQ(after.materials[1].diffuse, glm::dvec3(0, 0, 1));
  // Every triangle the file had, where it was and in its colour; and two
  // per hole besides.
  const std::vector<PlacedTriangle> had = placed_triangles(before), has = placed_triangles(after);
  EXPECT_EQ(has.size(), had.size() + 4);
  std::vector<PlacedTriangle> kept;
  std::set_intersection(had.begin(), had.end(), has.begin(), has.end(), std::back_inserter(kept));
  EXPECT_EQ(kept.size(), had.size());
  // The file's build items, as a slicer reads them.
  EXPECT_EQ(run("check " + path("fixed.3mf")).status, 0);
}

// A real 3MF (assimp's test box, written by another tool): nothing to
// repair, and it comes back triangle for triangle, where it was, in its unit.
TEST_F(ThreeMfRepair, ARealFileComesBackAsItWas) {
  const std::string box = "/usr/share/assimp/models/3MF/box.3mf";
  if (!fs::exists(box)) GTEST_SKIP() << "needs Debian's assimp-testmodels (build.sh installs it)";
  const CommandResult r = run("check " + box + " --repair " + path("box.3mf"));
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("  nothing to change\n"), std::string::npos) << r.out;
  const PolygonSoup before = read_polygon_soup(box), after = read_polygon_soup(path("box.3mf"));
  EXPECT_EQ(placed_triangles(after), placed_triangles(before));
  EXPECT_EQ(after.length_unit, before.length_unit);
  ASSERT_EQ(after.parts.size(), before.parts.size());
  EXPECT_EQ(after.parts[0].placement, before.parts[0].placement);
}

}  // namespace
}  // namespace umbra
