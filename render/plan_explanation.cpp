#include "render/render_plan.hpp"

#include <cmath>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <string>

namespace umbra {
namespace {

std::ostream& operator<<(std::ostream& out, const glm::dvec3& v) {
  return out << "(" << v.x << ", " << v.y << ", " << v.z << ")";
}

// "1.58 times ..." for --explain: how far a light's volumes are extruded.
std::string reach_phrase(double reach) {
  if (std::isinf(reach)) return "to infinity: along every axis the light lies within the casters' box";
  std::ostringstream out;
  out << std::setprecision(3) << reach << " times their casters' distance from the light, past every surface and the near plane";
  return out.str();
}

}  // namespace

std::string image_phrase(const RenderSettings& settings) {
  const int n = settings.antialias;
  const std::string grid = std::to_string(n) + " x " + std::to_string(n);
  return std::to_string(settings.width) + "x" + std::to_string(settings.height) + ", " +
         (n == 1 ? "one sample per pixel, at its centre (--antialias)"
          : settings.antialiased == AntialiasedPixels::kAll
              ? grid + " samples per pixel, averaged (--antialias)"
              : "one sample per pixel, and " + grid + " exact rays averaged at each that differs from a neighbour (--antialias)");
}

void print_render_plan(std::ostream& out, const Scene& scene, const RenderPlan& plan) {
  const Camera& c = plan.camera;
  out << "render plan for " << scene.path << "\n";
  out << "  image: " << image_phrase(plan.settings) << "\n";
  out << "  camera: eye " << c.eye << " target " << c.target << " up " << c.up;
  if (c.orthographic()) out << " orthographic " << c.ortho_height;
  else out << " fovy " << c.fovy_deg << " deg";
  out << (plan.camera_is_spec_default ? " (the default view)" : " (from the scene file)") << "\n";
  if (c.orthographic())
    out << "  projection: orthographic, " << c.ortho_height << " high, from the eye's plane to far " << plan.far_plane
        << " (past the surfaces' bounds); shadow volumes stop at a finite reach, drawn with depth clamping\n";
  else
    out << "  projection: perspective, near " << plan.near_plane << " (from the surfaces' bounds as the eye sees them), "
        << "far plane at infinity (epsilon 2^-22)\n";
  out << "  shading: ambient + diffuse" << (plan.specular_used ? " + specular" : " (no material has a specular term: skipped)")
      << "\n";
  out << "  method: " << method_name(plan.settings.method) << "; " << method_technique(plan.settings.method) << "\n";
  for (size_t i = 0; i < plan.lights.size(); ++i) {
    const Light& light = scene.lights[i];
    const LightPlan& lp = plan.lights[i];
    out << "  light " << i + 1 << " at " << light.position << " (line " << light.where.line << "): " << lp.side_quads
        << " side quads, " << lp.light_cap_triangles << " light-cap and " << lp.dark_cap_triangles << " dark-cap triangles\n";
    if (!plan.light_adds_direct[i]) out << "    no colour: ambient only, so a frame draws neither its shadows nor its direct light\n";
    else out << "    shadows: " << lp.count_reason << "\n";
    if (!lp.casters.empty() && counts_volumes(plan.settings.method))
      out << "    volumes reach " << reach_phrase(lp.volume_reach) << "\n";
    if (lp.culled_casters > 0)
      out << "    " << lp.culled_casters << " of " << lp.casters.size() << " casters left out: their volumes cannot reach the view\n";
    for (const CasterEntry& e : lp.casters) {
      out << "    " << e.kind << " (line " << e.where.line << "): " << e.volume_phrase;
      if (e.mesh_volume >= 0) {
        const MeshVolumeIndices& v = lp.mesh_volumes[size_t(e.mesh_volume)].volume;
        out << ", " << v.side_quads << " quads";
        if (lp.capped()) out << " + " << v.light_cap_triangles + v.dark_cap_triangles << " cap triangles";
        out << " (static vertices, indices per frame)";
      } else if (!e.volume.triangles.empty()) {
        out << ", " << e.volume.side_quads << " quads";
        if (lp.capped()) out << " + " << e.volume.light_cap_triangles + e.volume.dark_cap_triangles << " cap triangles";
      }
      out << "\n";
    }
  }
}

}  // namespace umbra
