// Meshes that are not closed 2-manifolds cast their exact shadow by edge
// multiplicity: open, non-manifold, non-orientable (mixed winding no flip
// can fix), self-intersecting, and closed and open parts in one file. Each
// mask must match exact shadow rays with the same tolerance as closed meshes.
#include <gtest/gtest.h>

#include "../mesh/mesh_builders.hpp"
#include "hard_case_scenes.hpp"
#include "mesh/check/mesh_check.hpp"
#include "mask_comparison.hpp"
#include "scene/scene_parser.hpp"
#include "render/render_plan.hpp"
#include "silhouette/mesh_caster.hpp"

namespace umbra {
namespace {

// The soup fitted into the box [-0.45, 0.45]^2 x [-0.75, 0.15] (turned about
// x first) over the scenes' floor, lit from two sides.
Scene scene_with(const std::string& name, const PolygonSoup& soup, double rotate_x_deg) {
  const std::string path = test::write_mesh(name + ".obj", test::obj_text(soup));
  glm::dvec3 lo(1e300), hi(-1e300);
  for (const glm::dvec3& p : soup.points) lo = glm::min(lo, p), hi = glm::max(hi, p);
  const double scale = 0.9 / std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
  std::ostringstream text;
  text << "light 0.5 0.8 1.8\nlight -0.9 -0.3 1.5 color 0.6 0.6 0.6\n" << test::floor_text() << "mesh \"" << path
       << "\" scale " << scale << " rotate 1 0 0 " << rotate_x_deg << " translate 0 0 -0.3\n";
  Scene scene = parse_scene_text(text.str(), name + ".scene");
  // Centre it over the floor whatever the turn did.
  Mesh& m = scene.meshes[0];
  const glm::dvec3 shift = glm::dvec3(0, 0, -0.3) - 0.5 * (m.bounds_min + m.bounds_max);
  std::vector<glm::dvec3> points = m.positions;
  for (glm::dvec3& p : points) p += shift;
  m.positions = std::move(points);
  m.bounds_min += shift, m.bounds_max += shift;
  return scene;
}

PolygonSoup two_crossing_bowls() {
  PolygonSoup turned = test::bowl(8, 24);
  for (glm::dvec3& p : turned.points) p = {p.x, -p.z - 0.4, p.y + 0.3};  // a quarter turn about x, moved into the first
  return test::combine(test::bowl(8, 24), turned);
}

PolygonSoup box_with_fins() {
  // Two fins on the box's top edge from (0, 0, 1) to (1, 0, 1): four faces on that edge.
  PolygonSoup soup = test::box_triangles(glm::dvec3(0.0), glm::dvec3(1.0));
  std::vector<glm::dvec3> points = soup.points;
  uint32_t edge_from = 0, edge_to = 0;
  for (uint32_t i = 0; i < points.size(); ++i) {
    if (points[i] == glm::dvec3(0, 0, 1)) edge_from = i;
    if (points[i] == glm::dvec3(1, 0, 1)) edge_to = i;
  }
  const uint32_t up = uint32_t(points.size()), out = up + 1;
  soup.add_point({0.5, -0.2, 1.6}, 0);
  soup.add_point({0.5, -0.8, 1.1}, 0);
  for (const uint32_t tip : {up, out}) {
    soup.corners.insert(soup.corners.end(), {edge_from, edge_to, tip});
    soup.end_polygon(0);
  }
  return soup;
}

struct OpenCase {
  const char* name;
  PolygonSoup (*soup)();
  const char* shape;  // SilhouetteComponents::phrase()
};

void PrintTo(const OpenCase& c, std::ostream* out) { *out << c.name; }

const OpenCase kCases[] = {
    {"bowl", [] { return test::bowl(10, 32); }, "open, 1 hole"},
    // No flip can orient a Moebius strip: its half twist leaves one edge whose faces disagree.
    {"moebius", [] { return test::moebius_strip(64); }, "open, 1 hole, 1 edge with mixed winding"},
    // The fins' free edges meet at the ends of the edge they share: one border loop.
    {"fins", box_with_fins, "open, 1 hole, 1 non-manifold edge"},
    {"crossing_bowls", two_crossing_bowls, "open, 2 holes"},
    {"bowl_and_box", [] { return test::combine(test::bowl(10, 32), test::box_triangles({-0.3, -0.3, -0.9}, {0.3, 0.3, -0.5})); },
     "open, 1 hole; 1 of 2 components closed"},
    // Closed, but its centre is pinched between its top fan and its bottom fan.
    {"horn_torus", [] { return test::horn_torus(24); }, "1 non-manifold vertex"},
};

class OpenMeshScene : public testing::TestWithParam<OpenCase> {};

TEST_P(OpenMeshScene, IsCastByEdgeMultiplicityAndSaysWhy) {
  const Scene scene = scene_with(GetParam().name, GetParam().soup(), 0.0);
  EXPECT_EQ(scene.meshes[0].components.phrase(), GetParam().shape);
  const MeshCaster caster = prepare_mesh_casters(scene)[0];
  EXPECT_FALSE(caster.open.empty());
}

TEST_P(OpenMeshScene, MaskMatchesExactShadowRays) {
  test::expect_masks_match_reference(scene_with(GetParam().name, GetParam().soup(), 0.0), 160, 120, 64);
}

TEST_P(OpenMeshScene, MaskMatchesExactShadowRaysTurnedAndWithTheLightRotated) {
  test::expect_masks_match_reference(scene_with(GetParam().name, GetParam().soup(), 110.0), 120, 120, 64, 100.0);
}

INSTANTIATE_TEST_SUITE_P(Meshes, OpenMeshScene, testing::ValuesIn(kCases),
                         [](const testing::TestParamInfo<OpenCase>& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace umbra

namespace umbra {
namespace {

// Two boxes that touch at a corner: the corner is a non-manifold vertex of
// the file, but each box has one fan of faces round it, so each is a closed
// 2-manifold on its own and casts from its silhouette, as the check says.
TEST(MeshCasterPhrase, ComponentsTouchingAtAVertexEachCastFromTheirSilhouette) {
  const PolygonSoup soup = test::combine(test::box_triangles({0, 0, 0}, {1, 1, 1}), test::box_triangles({1, 1, 1}, {2, 1.5, 2.5}));
  const Scene scene = scene_with("corner_boxes", soup, 30.0);
  const MeshReport report = check_mesh(soup, CheckOptions{});
  EXPECT_EQ(report.non_manifold_vertices, 1u);
  EXPECT_EQ(report.volume_kind(), VolumeKind::kSilhouette);
  const MeshCaster caster = prepare_mesh_casters(scene)[0];
  EXPECT_EQ(caster.phrase(), "1 non-manifold vertex; 2 of 2 components closed: silhouette volume");
  EXPECT_EQ(caster.silhouette.triangles.size(), 24u);
  EXPECT_TRUE(caster.open.empty());
  test::expect_masks_match_reference(scene, 160, 120, 64);
  test::expect_masks_match_reference(scene_with("corner_boxes_turned", soup, 110.0), 120, 120, 64, 100.0);
}

TEST(MeshCasterPhrase, SaysWhatLoadingChangedBeforeTheSilhouettePath) {
  // A box with one face wound the other way and one face repeated: loading
  // flips the one and drops the other, and the rest is a closed 2-manifold.
  PolygonSoup soup = test::reversed(test::box_triangles(glm::dvec3(0.0), glm::dvec3(1.0)), {3});
  soup.corners.insert(soup.corners.end(), soup.polygon(0), soup.polygon(0) + 3);
  soup.end_polygon(0);
  const Scene scene = scene_with("flipped_box", soup, 0.0);
  const MeshCaster caster = prepare_mesh_casters(scene)[0];
  EXPECT_EQ(caster.phrase(), "closed 2-manifold (1 duplicate face dropped, 1 face flipped to agree): silhouette volume");
  EXPECT_TRUE(caster.open.empty());
}

}  // namespace
}  // namespace umbra
