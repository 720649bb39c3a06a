// Properties every scene must have: the shadow does not depend on the order a
// triangle's vertices are written in, nor on where the whole scene (lights and
// camera included) stands in space; and every volume is closed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include <glm/gtc/matrix_transform.hpp>

#include "hard_case_scenes.hpp"
#include "mask_comparison.hpp"
#include "scene/scene_parser.hpp"
#include "volume_soundness.hpp"

namespace umbra {
namespace {

std::vector<std::string> bundled_scene_paths() {
  std::vector<std::string> paths;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(UMBRA_SOURCE_DIR) + "/scenes"))
    if (entry.path().extension() == ".scene") paths.push_back(entry.path().string());
  std::sort(paths.begin(), paths.end());
  return paths;
}

Image mask_of(const Scene& scene, int size) {
  RenderSettings settings;
  settings.width = settings.height = size;
  const RenderPlan plan = make_render_plan(scene, settings);
  HeadlessContext context(size, size);
  ShadowRenderer renderer(scene, plan);
  return renderer.render_mask(0);
}

// The finite and infinite points of a volume, sorted: its geometry whatever
// the numbering.
std::vector<std::array<double, 4>> sorted_points(const ShadowVolume& v) {
  std::vector<std::array<double, 4>> points;
  for (const glm::dvec4& p : v.vertices) points.push_back({p.x, p.y, p.z, p.w});
  std::sort(points.begin(), points.end());
  return points;
}

TEST(Property, VertexOrderChangesNeitherVolumeNorMask) {
  for (const std::string& path : bundled_scene_paths()) {
    SCOPED_TRACE(path);
    const Scene scene = parse_scene_file(path);
    if (scene.triangles.empty()) continue;
    const RenderPlan plan = make_render_plan(scene, RenderSettings{});
    const Image mask = mask_of(scene, 96);
    // Every cyclic rotation and both windings.
    for (int order = 1; order < 6; ++order) {
      Scene reordered = scene;
      for (Triangle& t : reordered.triangles) {
        for (int r = 0; r < order % 3; ++r) t = {t.b, t.c, t.a, t.material, t.where};
        if (order >= 3) std::swap(t.b, t.c);
      }
      const RenderPlan other = make_render_plan(reordered, RenderSettings{});
      for (size_t i = 0; i < plan.lights[0].casters.size(); ++i) {
        const ShadowVolume& a = plan.lights[0].casters[i].volume;
        const ShadowVolume& b = other.lights[0].casters[i].volume;
        EXPECT_EQ(sorted_points(a), sorted_points(b)) << "caster " << i << ", order " << order;
        EXPECT_EQ(a.triangles.size(), b.triangles.size());
      }
      EXPECT_EQ(mask_of(reordered, 96).pixels, mask.pixels) << "order " << order;
    }
  }
}

TEST(Property, MeshFaceOrderAndWindingChangeNothing) {
  // mesh_icosphere.scene with its OBJ written again with every face's corners
  // rotated, and with every face reversed (an inward mesh: loading turns it
  // outward), or with the faces listed backwards.
  const std::string dir = std::string(UMBRA_SOURCE_DIR) + "/scenes/";
  std::ifstream scene_file(dir + "mesh_icosphere.scene"), obj_file(dir + "meshes/icosphere.obj");
  const std::string scene_text((std::istreambuf_iterator<char>(scene_file)), std::istreambuf_iterator<char>());
  std::vector<std::string> vertices, faces;
  for (std::string line; std::getline(obj_file, line);) {
    if (line.rfind("v ", 0) == 0) vertices.push_back(line);
    if (line.rfind("f ", 0) == 0) faces.push_back(line);
  }
  ASSERT_EQ(faces.size(), 320u);
  const Image mask = mask_of(parse_scene_file(dir + "mesh_icosphere.scene"), 96);
  for (const char* variant : {"rotated", "reversed", "backwards"}) {
    std::ostringstream obj;
    for (const std::string& v : vertices) obj << v << "\n";
    std::vector<std::string> written = faces;
    if (std::string(variant) == "backwards") std::reverse(written.begin(), written.end());
    for (const std::string& f : written) {
      std::istringstream corners(f.substr(2));
      std::string a, b, c;
      corners >> a >> b >> c;
      if (std::string(variant) == "rotated") obj << "f " << b << " " << c << " " << a << "\n";
      else if (std::string(variant) == "reversed") obj << "f " << a << " " << c << " " << b << "\n";
      else obj << f << "\n";
    }
    std::string text = scene_text;
    const std::string mesh_path = test::write_mesh(std::string(variant) + ".obj", obj.str());
    text.replace(text.find("meshes/icosphere.obj"), std::strlen("meshes/icosphere.obj"), "\"" + mesh_path + "\"");
    EXPECT_EQ(mask_of(parse_scene_text(text, "variant.scene"), 96).pixels, mask.pixels) << variant;
  }
}

// Every point of the scene, its lights and its camera moved by x -> R x + t.
Scene moved(Scene scene, const glm::dmat4& motion) {
  const auto point = [&](glm::dvec3& p) { p = glm::dvec3(motion * glm::dvec4(p, 1.0)); };
  const auto direction = [&](glm::dvec3& d) { d = glm::dvec3(motion * glm::dvec4(d, 0.0)); };
  point(scene.camera.eye);
  point(scene.camera.target);
  direction(scene.camera.up);
  for (Light& l : scene.lights) point(l.position);
  for (Sphere& s : scene.spheres) point(s.center);
  for (Triangle& t : scene.triangles) {
    point(t.a);
    point(t.b);
    point(t.c);
  }
  for (Mesh& mesh : scene.meshes) {
    std::vector<glm::dvec3> points = mesh.positions;
    for (glm::dvec3& p : points) point(p);
    mesh.positions = std::move(points);
    mesh.bounds_min = mesh.bounds_max = mesh.positions[0];
    for (const glm::dvec3& p : mesh.positions) {
      mesh.bounds_min = glm::min(mesh.bounds_min, p);
      mesh.bounds_max = glm::max(mesh.bounds_max, p);
    }
  }
  return scene;
}

TEST(Property, RigidMotionOfEverythingKeepsTheMask) {
  // The reference answer is the same image before and after, so the moved
  // scene's GL mask must match the original scene's exact shadow rays.
  const glm::dmat4 motion = glm::rotate(glm::translate(glm::dmat4(1.0), {0.7, -1.9, 0.4}), glm::radians(73.0),
                                        glm::normalize(glm::dvec3(1.0, 2.0, -0.5)));
  for (const std::string& path : bundled_scene_paths()) {
    SCOPED_TRACE(path);
    Scene scene = parse_scene_file(path);
    scene.camera_from = FileLoc{path, 0, 0};  // the default view, now as an explicit camera that moves too
    const Scene other = moved(scene, motion);
    RenderSettings settings;
    settings.width = settings.height = 96;
    const RenderPlan plan = make_render_plan(scene, settings);
    const Image mask = mask_of(other, 96);
    const test::MaskComparison r = test::compare_with_reference(scene, plan, mask, 0);
    EXPECT_EQ(r.unexplained, 0) << r.first_unexplained << " (" << r.differing << " of " << r.surface_pixels << " differ)";
    EXPECT_TRUE(test::within_boundary_bound(r)) << r.excused_boundary << " excused of " << r.boundary_pixels;
    test::expect_sound_volumes(other);
  }
}

TEST(Property, EveryVolumeIsClosedForEveryBundledSceneAndLightAngle) {
  for (const std::string& path : bundled_scene_paths())
    for (double angle = 0.0; angle < 360.0; angle += 45.0) {
      SCOPED_TRACE(path + " at " + std::to_string(angle) + " deg");
      Scene scene = parse_scene_file(path);
      rotate_lights_about_z(scene, angle);
      test::expect_sound_volumes(scene);
    }
}

}  // namespace
}  // namespace umbra
