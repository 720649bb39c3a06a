#pragma once
// The validated scene (scene-format.md) as plain values. Nothing above scene/
// sees scene text: the parser produces this, the renderer consumes it. A mesh
// here holds what rendering needs, not the check's report, so nothing that
// renders depends on mesh/check/.

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/common.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "image/tone_curve.hpp"
#include "mesh/input_error.hpp"
#include "mesh/shared_positions.hpp"
#include "mesh/texture_image.hpp"
#include "mesh/topology/back_faces.hpp"
#include "mesh/topology/silhouette_components.hpp"
#include "mesh/topology/edge_table.hpp"
#include "scene/camera.hpp"

namespace umbra {

struct Light {
  glm::dvec3 position{0.0};             // homogeneous (x, y, z, 1): finite distance
  glm::dvec3 color{1.0};                // diffuse and specular intensity
  glm::dvec3 ambient{0.15};             // ambient intensity this light adds
  FileLoc where;
};

struct Material {
  std::string name;
  glm::dvec3 ambient{1.0};
  glm::dvec3 diffuse{0.8};
  glm::dvec3 specular{0.0};
  double shininess = 32.0;
  // A mesh file's diffuse texture map (OBJ's map_Kd, glTF's
  // baseColorTexture): it multiplies the ambient and diffuse terms of the
  // faces with texture coordinates (Mesh::triangle_uvs), sampled bilinearly
  // as the GL samples it, without mipmaps. Colours are used as written, as
  // every other colour is (no colour management). None for scene materials.
  std::shared_ptr<const TextureImage> texture;
  // Not drawn: its surfaces show what is behind them (the background),
  // darkened by the share of light that shadows take from them, so that a
  // model and its shadow can be laid over any picture (a shadow catcher).
  bool shadow_catcher = false;
};

struct Sphere {
  glm::dvec3 center{0.0};
  double radius = 0.0;
  int material = 0;  // index into Scene::materials
  FileLoc where;
};

struct Triangle {
  glm::dvec3 a{0.0}, b{0.0}, c{0.0};  // in file order: the order changes nothing
  int material = 0;
  FileLoc where;
};

// A `mesh` statement with its file loaded: the triangles in scene coordinates
// (fit, then scale, then rotate, then translate), merged, consistently oriented where
// the mesh allows, with their edges and which components are closed
// 2-manifolds (those cast their shadow from a silhouette, the rest by edge
// multiplicity).
struct Mesh {
  std::string path;  // as resolved against the scene file's folder
  int material = 0;  // the statement's (or the default), for faces the file gives no material
  bool material_given = false;  // the statement names one: it overrides the file's own
  bool plain = false;  // `plain`: its material alone, not the file's materials, maps or vertex colours
  // Per triangle, an index into Scene::materials, where the file gives its
  // faces materials (OBJ's usemtl, glTF, 3MF); empty when every face takes `material`.
  std::vector<int> triangle_materials;
  // Per triangle, its corners' colours where the file gives vertex colours
  // (PLY, OBJ "v x y z r g b", glTF COLOR_0); they multiply the material's
  // ambient and diffuse terms, blended across the triangle. Empty: none.
  std::vector<std::array<glm::vec3, 3>> triangle_colors;
  // Per triangle, its corners' texture coordinates (v down the image), where
  // some of the file's materials has a texture map. Empty: none.
  std::vector<std::array<glm::vec2, 3>> triangle_uvs;
  // `smooth DEG`: shaded smooth, in the file's normals where it gives them
  // (OBJ vn, PLY nx ny nz, glTF NORMAL), else in normals averaged over the
  // faces round each point that meet at no more than DEG degrees
  // (crease_normals.hpp). Unset: flat faces. Shadows are the faces' either way.
  std::optional<double> smooth_deg;
  // Not in the scene's text: smooth only a mesh of fewer triangles than
  // this, else flat (smooth_deg unset once loaded). A staged mesh finer than
  // its picture's pixels has no facet to show, so none to hide, and is
  // spared the normals' time and memory.
  size_t smooth_triangle_limit = SIZE_MAX;
  // Per triangle, its corners' unit normals for shading, in scene
  // coordinates; (0, 0, 0) at a corner drawn flat. Empty: every face flat.
  std::vector<std::array<glm::vec3, 3>> triangle_normals;
  bool fit = false;  // centred and scaled so that its box's longest side spans the cube, before the rest
  double scale = 1.0;
  glm::dvec3 rotation_axis{0.0, 0.0, 1.0};
  double rotation_deg = 0.0;
  glm::dvec3 translation{0.0};
  FileLoc where;

  SharedPositions positions;  // the one copy of the points, which the mesh's caster shares
  std::vector<std::array<uint32_t, 3>> triangles;
  glm::dvec3 bounds_min{0.0}, bounds_max{0.0};  // of the triangles' corners, in scene coordinates
  glm::dvec3 file_bounds_min{0.0}, file_bounds_max{0.0};  // likewise in the file's own, where `fit` measured them
  EdgeTable edges;               // of `triangles`
  SilhouetteComponents components;   // of `triangles`: which cast from their silhouette
  // What loading changed, as the check reports it: "2 duplicate faces
  // dropped, 588 faces flipped to agree"; "" when nothing.
  std::string loading_changes;
  // Whether, seen from outside the mesh's box, its back faces may be culled.
  BackFaces back_faces = BackFaces::kDrawn;

  int material_of(size_t triangle) const { return triangle_materials.empty() ? material : triangle_materials[triangle]; }
};

// The default view: looking down -z at the origin, +y up, with the front face
// of the cube [-1,1]^3 (z = 1) filling 99% of the window's height.
Camera spec_camera();

// What a picture shows where no surface is: a colour, or nothing at all
// (alpha 0, in a PNG with an alpha channel).
struct Background {
  glm::dvec3 color{0.0};
  bool transparent = false;
};

// Light that reaches every surface the camera sees without a shadow, beside
// the lights, which cast exact ones: a studio's fill, for a picture whose
// shaded sides keep their shape (a staged mesh has it; a spec scene none).
// - The headlight is a light at the eye. It lights only what the eye sees,
//   so every point it could shadow is hidden: it casts no shadow in view.
//   Diffuse only, by the seen side's n . v.
// - The hemisphere (sky and ground) replaces a constant ambient term with
//   one that depends on a face's turn: sky where the seen side faces `up`,
//   ground where it faces down, blended by (1 + n . up) / 2 between
//   (a hemisphere light; Akenine-Moller, Haines and Hoffman, "Real-Time
//   Rendering", 4th ed., 2018, 10.3). It multiplies the ambient colour.
struct FillLight {
  glm::dvec3 headlight{0.0};
  glm::dvec3 sky{0.0}, ground{0.0};
  glm::dvec3 up{0.0, 0.0, 1.0};  // unit
};

struct Warning {
  FileLoc where;
  std::string message;
};

// The largest side of a frame drawn, supersampling included: llvmpipe's and
// most GPUs' limit. A picture's size (the scene's `size`, --size) is at most that.
constexpr int kLargestPictureSide = 16384;

struct Scene {
  std::string path;
  std::vector<Light> lights;
  std::vector<Material> materials;  // [0] is the default material
  std::vector<Sphere> spheres;
  std::vector<Triangle> triangles;
  std::vector<Mesh> meshes;
  Camera camera = spec_camera();
  std::optional<FileLoc> camera_from;  // where the camera statement was; none: the default view
  Background background;
  FillLight fill;
  ToneCurve tone = ToneCurve::kClip;  // how light becomes a channel's value (tone_curve.hpp)
  std::optional<int> antialias;  // samples per side it is drawn with, unless told (none: 1)
  bool antialias_all = false;    // `antialias N all`: at every pixel, not only at edges
  std::optional<std::pair<int, int>> size;  // `size W H`: the picture's width and height, unless told
  std::vector<Warning> warnings;
};

// The box round every surface (spheres, triangles, meshes); empty (lo > hi)
// when the scene has none.
struct SceneBounds {
  glm::dvec3 lo{1.0}, hi{-1.0};
  bool empty() const { return lo.x > hi.x; }
  // Grows the box to hold `box` too.
  void grow(const SceneBounds& box) {
    if (box.empty()) return;
    if (empty()) *this = box;
    else lo = glm::min(lo, box.lo), hi = glm::max(hi, box.hi);
  }
};
SceneBounds surface_bounds(const Scene& scene);
// One surface's box: what surface_bounds grows by.
SceneBounds surface_bounds(const Sphere& sphere);
SceneBounds surface_bounds(const Triangle& triangle);
SceneBounds surface_bounds(const Mesh& mesh);  // empty for a mesh with no triangles

// A lower bound on the distance from `point` to every surface: exact for
// spheres and triangles; for a mesh, the distance to its box when the point
// lies outside the box, else to its nearest triangle. 0 for a point on a
// surface; infinity when the scene has none.
double nearest_surface_distance(const Scene& scene, const glm::dvec3& point);

// The light motion of the viewer and --light-angle: every light rotated about the z axis.
void rotate_lights_about_z(Scene& scene, double degrees);
// `p` turned about the z axis by `degrees`, as rotate_lights_about_z turns a light.
glm::dvec3 rotated_about_z(const glm::dvec3& p, double degrees);

}  // namespace umbra
