#include "render/caster_entries.hpp"

#include <string>
#include <utility>

#include "mesh/predicates/orientation.hpp"
#include "silhouette/sphere_volume.hpp"
#include "silhouette/triangle_volume.hpp"

namespace umbra {

CasterEntry sphere_entry(const Sphere& s, const Light& light, int segments) {
  CasterEntry e{"sphere", s.where, "", sphere_volume(s.center, s.radius, light.position, segments)};
  e.volume_phrase = "tangent-circle " + std::to_string(segments) + "-gon";
  return e;
}

CasterEntry triangle_entry(const Triangle& t, const Light& light) {
  CasterEntry e{"triangle", t.where, "", {}};
  if (collinear(t.a, t.b, t.c)) {
    e.volume_phrase = "none: degenerate (collinear vertices)";
  } else if (auto volume = triangle_volume(t.a, t.b, t.c, light.position)) {
    e.volume = std::move(*volume);
    e.volume_phrase = "three side quads";
  } else {
    e.volume_phrase = "none: its plane contains the light, so it is seen edge-on";
  }
  return e;
}

// A mesh's entry. Its volume goes to light_plan.mesh_volumes[slot], whose
// index buffer is kept from the previous frame when there is one; with
// --method triangles, every triangle's own volume instead.
CasterEntry mesh_entry(const Scene& scene, size_t index, const MeshCaster& caster, const Light& light, LightPlan& light_plan,
                       size_t& slot, MeshCasterScratch& scratch, bool per_triangle_asked) {
  const Mesh& mesh = scene.meshes[index];
  CasterEntry e{"mesh", mesh.where, "", {}};
  const std::string triangles = std::to_string(mesh.triangles.size()) + " triangles";
  if (per_triangle_asked) {
    e.volume = per_triangle_volume(mesh.positions, mesh.triangles, light.position);
    e.volume_phrase = "per-triangle volumes, the slow reference (--method triangles; " + triangles + ")";
    return e;
  }
  if (slot == light_plan.mesh_volumes.size()) light_plan.mesh_volumes.emplace_back();
  MeshVolumePlan& volume = light_plan.mesh_volumes[slot];
  volume.mesh = index;
  e.mesh_volume = int(slot++);
  mesh_caster_volume_indices(caster, light.position, scratch, volume.volume, light_plan.capped());
  e.volume_phrase = caster.phrase() + " (" + triangles + ")";
  return e;
}

// Every sphere's and triangle's volume in lp.all_volumes, in file order: one
// draw call (the meshes' volumes are drawn from their own buffers).
void gather_volumes(LightPlan& lp) {
  for (const CasterEntry& e : lp.casters)
    if (e.mesh_volume < 0) append_volume(lp.all_volumes, e.volume, lp.capped());
}

CasterEntry culled_entry(const char* kind, const FileLoc& where) {
  return {kind, where, "none: its shadow volume cannot reach the view", {}};
}

// Empties a light's sphere and triangle volumes (not its mesh volumes).
void clear_volumes(LightPlan& lp) {
  lp.all_volumes.vertices.clear();
  lp.all_volumes.triangles.clear();
  lp.all_volumes.side_quads = lp.all_volumes.light_cap_triangles = lp.all_volumes.dark_cap_triangles = 0;
  lp.side_quads = lp.light_cap_triangles = lp.dark_cap_triangles = 0;
}

}  // namespace umbra
