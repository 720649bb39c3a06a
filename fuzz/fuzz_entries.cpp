#include "fuzz/fuzz_entries.hpp"
#include "fuzz/format_byte.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <string_view>

#include "mesh/check/mesh_check.hpp"
#include "mesh/io/mesh_file.hpp"
#include "mesh/io/mesh_format.hpp"
#include "mesh/io/mesh_readers.hpp"
#include "scene/mesh_placement.hpp"
#include "scene/scene_checks.hpp"
#include "scene/staged_scene.hpp"
#include "tools/view_set.hpp"
#include "scene/scene_parser.hpp"
#include "render/render_plan.hpp"
#include "silhouette/mesh_caster.hpp"
#include "silhouette/mesh_volume.hpp"
#include "silhouette/volume_topology.hpp"

namespace umbra::fuzz {

void scene_input(const uint8_t* data, size_t size) {
  try {
    const Scene scene =
        parse_scene_text(std::string(reinterpret_cast<const char*>(data), size), "/nonexistent/fuzz.scene");
    require_lights_off_casters(scene);
    RenderSettings settings;
    settings.sphere_segments = 8;
    (void)make_render_plan(scene, settings);
  } catch (const InputError&) {
  }
}

namespace {

// The file read under `name`, the check's analysis, and the mesh's shadow
// volume from a few fixed lights.
void read_and_cast(std::string_view bytes, const std::string& name) {
  try {
    const PolygonSoup soup = parse_polygon_soup(bytes, name);
    CheckOptions options;
    options.self_intersection_seconds = 0.5;
    const MeshAnalysis analysis = analyse_mesh(soup, options);
    const MeshCaster caster = prepare_mesh_caster(analysis.positions, analysis.triangles);
    for (const glm::dvec3 light : {glm::dvec3(0.3, 0.2, 5.0), glm::dvec3(-7.0, 0.5, -0.25), glm::dvec3(0.01, -0.02, 0.03)}) {
      const ShadowVolume volume = mesh_caster_volume(caster, light);
      for (const glm::dvec4& v : volume.vertices) {
        const bool finite = std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
        if (!finite || !(v.w == 1.0 || (v.w == 0.0 && (v.x != 0.0 || v.y != 0.0 || v.z != 0.0))))
          throw std::logic_error("a shadow volume vertex is not finite, or (0, 0, 0, 0)");
      }
      if (!volume.triangles.empty() && !has_no_boundary(volume))
        throw std::logic_error("a mesh's shadow volume has a boundary");
    }
  } catch (const InputError&) {
  }
}

}  // namespace

void mesh_input(const uint8_t* data, size_t size) {
  if (size == 0) return;
  const std::string_view bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
  const std::string name = mesh_format_name_of_byte(data[0]);
  // Content a library reads (a STEP header: Open CASCADE's; glTF 1.0:
  // Assimp's) is library_input's.
  const std::string id = mesh_reader_of(bytes, name);
  if (const MeshFormat* format = mesh_format_by_id(id); format && !format->fuzzed) return;
  if (id == "gltf" && gltf_needs_assimp(bytes)) return;
  read_and_cast(bytes, name);
}

void library_input(const uint8_t* data, size_t size) {
  if (size == 0) return;
  read_and_cast({reinterpret_cast<const char*>(data) + 1, size - 1}, mesh_format_name_of_byte(data[0], Readers::kEvery));
}

void cameras_input(const uint8_t* data, size_t size) {
  static const Scene staged = [] {
    PolygonSoup soup;
    soup.path = "tetrahedron";
    soup.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    soup.polygon_starts = {0, 3, 6, 9, 12};
    soup.corners = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    return stage_polygon_soup(std::make_shared<const PolygonSoup>(std::move(soup)));
  }();
  try {
    const TransformsFile file = read_transforms(std::string(reinterpret_cast<const char*>(data), size), "fuzz.json");
    for (const Shot& shot : shots_of(file, staged, placement_of(staged.meshes.at(0))))
      for (const auto& [x, y] : {std::pair{0.0, 0.0}, {file.width - 1.0, file.height - 1.0}}) {
        const Ray ray = shot.camera.pixel_ray(file.width, file.height, x, y);
        const double length = glm::length(ray.direction);
        if (!std::isfinite(ray.origin.x + ray.origin.y + ray.origin.z) || !(std::abs(length - 1.0) < 1e-9))
          throw std::logic_error("an accepted camera's pixel ray is not finite and unit");
      }
  } catch (const InputError&) {
  }
}

}  // namespace umbra::fuzz
