#include "reference/ray_cast_render.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <thread>

#include <glm/geometric.hpp>

#include "image/edge_pixels.hpp"
#include "image/pixel_mean.hpp"
#include "scene/camera.hpp"
#include "scene/terminator.hpp"
#include "reference/hit_surface.hpp"
#include "reference/ray_caster.hpp"
#include "reference/texture_sampling.hpp"

namespace umbra {
namespace {

// The colour the surface's material is multiplied by at `p`: its corners'
// colours, and its texture map at its corners' texture coordinates, blended
// across the triangle; white where the file gives neither.
glm::dvec3 surface_colour(const Scene& scene, const Surface& s, const glm::dvec3& p) {
  if (!s.mesh) return glm::dvec3(1.0);
  const TextureImage* texture = s.mesh->triangle_uvs.empty() ? nullptr : scene.materials[size_t(s.material)].texture.get();
  if (s.mesh->triangle_colors.empty() && !texture) return glm::dvec3(1.0);
  const CornerBlend blend(s, p);
  glm::dvec3 colour(1.0);
  if (!s.mesh->triangle_colors.empty()) colour = blend(s.mesh->triangle_colors[s.triangle]);
  if (texture) colour *= sample_bilinear(*texture, blend(s.mesh->triangle_uvs[s.triangle]));
  return colour;
}

// Per light, per mesh, which triangles are on its terminator (empty for a
// flat mesh; terminator.hpp).
using Terminators = std::vector<std::vector<std::vector<uint8_t>>>;

Terminators terminators_of(const Scene& scene) {
  Terminators all(scene.lights.size(), std::vector<std::vector<uint8_t>>(scene.meshes.size()));
  for (size_t i = 0; i < scene.lights.size(); ++i)
    for (size_t k = 0; k < scene.meshes.size(); ++k)
      if (!scene.meshes[k].triangle_normals.empty())
        all[i][k] = terminator_triangles(scene.meshes[k], triangle_light_sides(scene.meshes[k], scene.lights[i].position));
  return all;
}

// For a hit on `mesh`'s face that turns from the light, whether anything
// more than the mesh's own surface, where the ray to the light leaves it,
// stands between it and the light: the GL's count past one volume.
bool shadowed_past_own_surface(const Scene& scene, const RayCaster& caster, const RayHit& hit, const Mesh* mesh,
                               const glm::dvec3& light) {
  const double distance = glm::length(light - hit.point);
  const std::optional<RayHit> leaving = caster.nearest_hit(hit.point, (light - hit.point) / distance, hit.object);
  if (!leaving || leaving->t >= distance) return false;
  if (surface_of(scene, leaving->object).mesh != mesh) return true;
  return caster.shadow_ray_blocked(leaving->point, leaving->object, light);
}

// The shader's shade() for one sample, in double precision (shaders.hpp),
// unclamped as the GL's float frame keeps it, with its coverage: (colour, 1),
// or for a shadow catcher (lit, unlit, 0, -1); with `masks`, each light's
// mask at (x, y) too. `eye` is where the sample's ray starts (the eye, for
// a perspective camera).
glm::dvec4 shade(const Scene& scene, const RayCaster& caster, const glm::dvec3& ambient_sum, const Terminators& terminators,
                 const RayHit& hit, const glm::dvec3& eye, std::vector<Image>* masks, int x, int y) {
  const Surface surface = surface_of(scene, hit.object);
  const Material& m = scene.materials[size_t(surface.material)];
  const glm::dvec3 tint = surface_colour(scene, surface, hit.point);
  glm::dvec3 n = hit.normal;
  if (glm::dot(n, eye - hit.point) < 0.0) n = -n;
  const std::optional<glm::dvec3> smooth = shading_normal(surface, hit.point);
  const glm::dvec3 s = !smooth ? n : glm::dot(*smooth, n) < 0.0 ? -*smooth : *smooth;
  // The ambient pass: the lights' ambient, the hemisphere and the headlight.
  const FillLight& fill = scene.fill;
  const glm::dvec3 ambient = ambient_sum + glm::mix(fill.ground, fill.sky, 0.5 + 0.5 * glm::dot(s, fill.up));
  const glm::dvec3 head = fill.headlight * std::max(glm::dot(s, glm::normalize(eye - hit.point)), 0.0);
  glm::dvec3 colour = (ambient * m.ambient + head * m.diffuse) * tint;
  const auto mean = [](const glm::dvec3& rgb) { return (rgb.r + rgb.g + rgb.b) / 3.0; };
  glm::dvec2 caught(mean(ambient + head));  // a shadow catcher's lit and unlit light
  for (size_t i = 0; i < scene.lights.size(); ++i) {
    const Light& light = scene.lights[i];
    const glm::dvec3 l = glm::normalize(light.position - hit.point);
    const bool faces = seen_side_faces_light(hit, eye, light.position);
    const bool lit = faces && !caster.shadow_ray_blocked(hit.point, hit.object, light.position);
    if (masks) (*masks)[i].at(x, y) = lit ? kMaskLit : kMaskUnlit;
    // A smooth face on the terminator that turns from the light takes the
    // light its normals give it, unless more than its own surface shades it.
    const bool lit_by_normals = smooth && !faces && terminators[i][size_t(surface.mesh - scene.meshes.data())][surface.triangle] &&
                                !shadowed_past_own_surface(scene, caster, hit, surface.mesh, light.position);
    // A face lit at a grazing angle may round to n . l just below 0: none.
    const double n_dot_l = std::max(glm::dot(n, l), 0.0);
    if (m.shadow_catcher && faces) caught += glm::dvec2(lit ? 1.0 : 0.0, 1.0) * (mean(light.color) * n_dot_l);
    if (!lit && !lit_by_normals) continue;
    const double s_dot_l = smooth ? std::max(glm::dot(s, l), 0.0) : n_dot_l;
    const glm::dvec3 v = glm::normalize(eye - hit.point);
    const glm::dvec3 r = 2.0 * (smooth ? glm::dot(s, l) : n_dot_l) * s - l;  // reflect(-l, s)
    const double highlight = m.shininess > 0.0 ? std::pow(std::max(glm::dot(r, v), 0.0), m.shininess) : 1.0;
    colour += light.color * (m.diffuse * tint * s_dot_l + m.specular * highlight);
  }
  return m.shadow_catcher ? glm::dvec4(caught, 0.0, -1.0) : glm::dvec4(colour, 1.0);
}

// Samples of one view of a scene: an eye ray's colour and coverage, and a
// pixel's mean over a grid of them, as the GL's frame puts its samples.
class FrameSampler {
 public:
  FrameSampler(const Scene& scene, const RayCaster& caster, int width, int height)
      : scene_(scene), caster_(caster), rays_(scene.camera, width, height), terminators_(terminators_of(scene)),
        nothing_(background_sample(scene.background.color, scene.background.transparent)) {
    for (const Light& light : scene.lights) ambient_sum_ += light.ambient;
  }

  // The pixel (x, y)'s samples x samples points at the centres of its
  // sub-pixels, as the GL's frame drawn that many times larger puts them,
  // averaged; with `masks`, each light's mask at the pixel's centre too.
  glm::dvec4 pixel_mean(int x, int y, int samples, std::vector<Image>* masks) const {
    const glm::dvec4 centre = masks || samples % 2 ? sample(x + 0.5, y + 0.5, masks, x, y) : glm::dvec4(0.0);
    glm::dvec4 sum = samples % 2 ? centre : glm::dvec4(0.0);  // an odd grid's middle sample is the centre
    for (int j = 0; j < samples; ++j)
      for (int i = 0; i < samples; ++i)
        if (samples % 2 == 0 || i != samples / 2 || j != samples / 2)
          sum += sample(x + (i + 0.5) / samples, y + (j + 0.5) / samples, nullptr, x, y);
    return sum / double(samples * samples);
  }

 private:
  // A sample at (px, py) in pixels (the pixel's centre at x + 1/2): its
  // colour and coverage, the background where it sees nothing, as the GL
  // clears its frame (pixel_mean.hpp).
  glm::dvec4 sample(double px, double py, std::vector<Image>* masks, int x, int y) const {
    const Ray ray = rays_.ray(px - 0.5, py - 0.5);
    const auto hit = caster_.nearest_hit(ray);
    return hit ? resolved_sample(shade(scene_, caster_, ambient_sum_, terminators_, *hit, ray.origin, masks, x, y), scene_.background.color,
                                 scene_.background.transparent)
               : nothing_;
  }

  const Scene& scene_;
  const RayCaster& caster_;
  PixelRays rays_;
  glm::dvec3 ambient_sum_{0.0};
  Terminators terminators_;
  glm::dvec4 nothing_;
};

// Calls job(k) for k in [0, count), shared among the machine's cores.
template <typename Job>
void on_every_core(size_t count, const Job& job) {
  const size_t threads = std::max(1u, std::thread::hardware_concurrency());
  const auto share = [&](size_t first) {
    for (size_t k = first; k < count; k += threads) job(k);
  };
  std::vector<std::thread> workers;
  for (size_t t = 1; t < threads; ++t) workers.emplace_back(share, t);
  share(0);
  for (std::thread& w : workers) w.join();
}

// Draws again each pixel of `image` that edge_pixels finds, from `sampler`'s
// samples x samples rays; returns how many.
size_t redraw_edge_pixels(const Scene& scene, const FrameSampler& sampler, Image& image, int samples) {
  const std::vector<uint8_t> edge = edge_pixels(image);
  std::vector<size_t> redrawn;
  for (size_t k = 0; k < edge.size(); ++k)
    if (edge[k]) redrawn.push_back(k);
  // Each worker takes a run of pixels, so that neighbours share its cache.
  constexpr size_t kRun = 64;
  on_every_core((redrawn.size() + kRun - 1) / kRun, [&](size_t run) {
    for (size_t k = run * kRun; k < std::min(redrawn.size(), (run + 1) * kRun); ++k) {
      const int x = int(redrawn[k] % size_t(image.width)), y = int(redrawn[k] / size_t(image.width));
      put_pixel_mean(image, x, y, sampler.pixel_mean(x, y, samples, nullptr), scene.background.color, scene.tone);
    }
  });
  return redrawn.size();
}

}  // namespace

RayCastFrame ray_cast_frame(const Scene& scene, int width, int height, int samples, AntialiasedPixels where) {
  RayCastFrame frame{Image(width, height, scene.background.transparent ? 4 : 3),
                     std::vector<Image>(scene.lights.size(), Image(width, height, 1, kMaskNoSurface))};
  const RayCaster caster(scene);
  const FrameSampler sampler(scene, caster, width, height);
  const int first_samples = where == AntialiasedPixels::kAll ? samples : 1;
  on_every_core(size_t(height), [&](size_t row) {
    const int y = int(row);
    for (int x = 0; x < width; ++x)
      put_pixel_mean(frame.image, x, y, sampler.pixel_mean(x, y, first_samples, &frame.masks), scene.background.color, scene.tone);
  });
  if (first_samples != samples) redraw_edge_pixels(scene, sampler, frame.image, samples);
  return frame;
}

size_t ray_cast_edge_pixels(const Scene& scene, const RayCaster& caster, Image& image, int samples) {
  return redraw_edge_pixels(scene, FrameSampler(scene, caster, image.width, image.height), image, samples);
}

}  // namespace umbra
