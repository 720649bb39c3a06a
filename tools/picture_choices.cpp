#include "tools/picture_choices.hpp"

#include "render/render_method.hpp"

namespace umbra {

void add_picture_choices(CommandOptions& options, PictureChoices& c) {
  add_size_option(options, c.settings.width, c.settings.height,
                  "image size in pixels (default: a scene's size statement, else " + std::to_string(c.settings.width) + "x" +
                      std::to_string(c.settings.height) + ")",
                  &c.size_given);
  add_light_angle_option(options, c.light_angle_deg,
                         "rotate every light about the z axis by DEG degrees (for a MESH, before the camera frames its shadow)");
  add_segments_option(options, c.settings.sphere_segments);
  add_method_option(options, c.settings.method, "how shadows are made (default auto):\n{methods}\n");
  add_map_size_option(options, c.settings.shadow_map_size);
  add_gl_option(options, c.gl);
  add_antialias_option(options, c.antialias,
                       "N x N samples per pixel, averaged ({range}), where the picture has an edge: the GL draws one sample a "
                       "pixel, and each pixel that differs from a neighbour is drawn again from N x N exact rays. Default " +
                           std::to_string(kStagedAntialias) +
                           " for a MESH on its own, 1 for a SCENE, whose pictures stay as they were; masks are one sample at each "
                           "pixel's centre");
  options.flag("--antialias-all", c.antialias_all,
               "take the N x N samples at every pixel, the GL's frame drawn N times larger, as it always is for {inexact methods},"
               " --show-volumes, a scene with a sphere, or more triangles than the picture has pixels");
  options.flag("--show-volumes", c.show_volumes, "draw the shadow volumes translucently over the image");
  add_staging_options(options, c.staging, c.staging_given);
}

void settle_picture_choices(PictureChoices& c) {
  c.gl = gl_with_environment(c.gl);
  require_consistent_staging(c.staging);
  note_staging_flags(c.staging, c.staging_given);
  c.staging.view.light_turn_deg = c.light_angle_deg;
  c.staging.antialias = c.antialias;
  c.staging.antialias_all = c.antialias_all;
}

PictureChoices parse_picture_choices(const std::vector<std::string>& words) {
  PictureChoices choices;
  CommandOptions options;
  add_picture_choices(options, choices);
  options.parse(words);
  settle_picture_choices(choices);
  return choices;
}

int default_antialias(const std::string& path) { return is_mesh_file(path) ? kStagedAntialias : 1; }

AntialiasedPixels antialiased_pixels(bool all, bool show_volumes, const RenderSettings& settings, const Scene* scene,
                                     size_t views) {
  const bool gl = settings.method != RenderMethod::kRaycast;
  size_t triangles = 0;
  if (scene) {
    triangles = scene->triangles.size();
    for (const Mesh& m : scene->meshes) triangles += m.triangles.size();
  }
  const bool spheres = scene && !scene->spheres.empty();
  const bool finer_than_pixels = triangles > views * size_t(settings.width) * size_t(settings.height);
  return all || show_volumes || !draws_exact_shadows(settings.method) || (gl && (spheres || finer_than_pixels))
             ? AntialiasedPixels::kAll
             : AntialiasedPixels::kEdges;
}

void set_picture_samples(RenderSettings& settings, const std::optional<int>& asked, bool all, bool show_volumes,
                         const Scene& scene, size_t views) {
  settings.antialias = asked.value_or(scene.antialias.value_or(1));
  settings.antialiased = antialiased_pixels(all || (!asked && scene.antialias_all), show_volumes, settings, &scene, views);
}

void set_picture_size(RenderSettings& settings, bool size_given, const Scene& scene) {
  if (!size_given && scene.size) settings.width = scene.size->first, settings.height = scene.size->second;
}

}  // namespace umbra
