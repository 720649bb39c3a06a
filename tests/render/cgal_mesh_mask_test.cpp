// Real meshes from Debian's CGAL data as scene meshes: a closed genus-2
// surface, the same kind of surface with three holes, a file of 26 closed
// pieces, and open scans and models. Each is fitted over a floor; every light's mask must match exact
// shadow rays, with the method the check chose.
#include <gtest/gtest.h>

#include <filesystem>

#include "mask_comparison.hpp"
#include "mesh/check/mesh_check.hpp"
#include "mesh/io/mesh_file.hpp"
#include "scene/scene_parser.hpp"
#include "render/render_plan.hpp"
#include "silhouette/mesh_caster.hpp"
#include "silhouette/mesh_volume.hpp"
#include "silhouette/volume_topology.hpp"

namespace umbra {
namespace {

// A scene with the mesh scaled into the box [-0.45, 0.45]^2 x [-0.75, 0.15]
// over the floor z = -1, lit from two sides.
Scene scene_with(const std::string& mesh_name, double rotate_x_deg) {
  const std::string path = std::string(UMBRA_CGAL_DATA) + "/meshes/" + mesh_name;
  const MeshReport report = check_mesh(read_polygon_soup(path), CheckOptions{0.0});
  const glm::dvec3 size = report.bbox_max - report.bbox_min;
  const double scale = 0.9 / std::max({size.x, size.y, size.z});
  const glm::dvec3 centre = 0.5 * (report.bbox_min + report.bbox_max) * scale;
  std::ostringstream text;
  text << "light 0.5 0.8 1.8\nlight -0.9 -0.3 1.5 color 0.6 0.6 0.6\n"
       << "triangle -1 -1 -1  1 -1 -1  1 1 -1\ntriangle -1 -1 -1  1 1 -1  -1 1 -1\n"
       << "mesh \"" << path << "\" scale " << scale << " rotate 1 0 0 " << rotate_x_deg << " translate " << -centre.x << " "
       << -centre.y << " " << -0.3 - centre.z << "\n";
  return parse_scene_text(text.str(), "cgal.scene");
}

struct CgalMeshCase {
  const char* file;
  bool closed;  // every component a closed 2-manifold: cast from the silhouette
};

void PrintTo(const CgalMeshCase& c, std::ostream* out) { *out << c.file; }

class CgalMeshScene : public testing::TestWithParam<CgalMeshCase> {};

TEST_P(CgalMeshScene, MaskMatchesExactShadowRays) {
  const Scene scene = scene_with(GetParam().file, 0.0);
  ASSERT_EQ(scene.meshes.size(), 1u);
  EXPECT_EQ(scene.meshes[0].components.all_cast_from_silhouette(), GetParam().closed);
  test::expect_masks_match_reference(scene, 160, 120, 64);
}

TEST_P(CgalMeshScene, MaskMatchesExactShadowRaysTurnedAndWithTheLightRotated) {
  test::expect_masks_match_reference(scene_with(GetParam().file, 70.0), 120, 120, 64, 100.0);
}

INSTANTIATE_TEST_SUITE_P(Meshes, CgalMeshScene,
                         testing::Values(CgalMeshCase{"double-torus-example.off", true},
                                         CgalMeshCase{"double-torus-3-holes.off", false},
                                         CgalMeshCase{"bones.off", true},
                                         // Real open meshes: 106 holes and 65 non-manifold vertices; a
                                         // scan with one hole; one hole and 1643 self-intersecting face pairs.
                                         CgalMeshCase{"elephant-with-holes.off", false},
                                         CgalMeshCase{"nefertiti.off", false},
                                         CgalMeshCase{"mannequin-devil.off", false}),
                         [](const testing::TestParamInfo<CgalMeshCase>& info) {
                           std::string name = info.param.file;
                           name = name.substr(0, name.find('.'));
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });

TEST(CgalMeshVolumes, SilhouetteVolumesHaveNoBoundaryForManyLights) {
  for (const char* file : {"double-torus-example.off", "bones.off"}) {
    const Scene scene = scene_with(file, 30.0);
    const std::vector<MeshCaster> casters = prepare_mesh_casters(scene);
    ASSERT_FALSE(casters[0].silhouette.triangles.empty()) << file;
    for (int i = 0; i < 24; ++i) {
      const double angle = 0.2618 * i;
      const glm::dvec3 light(1.5 * std::cos(angle), 1.5 * std::sin(angle), 0.3 + 0.1 * i);
      EXPECT_TRUE(has_no_boundary(mesh_caster_volume(casters[0], light))) << file << ", light " << i;
    }
  }
}

}  // namespace
}  // namespace umbra
