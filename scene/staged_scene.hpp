#pragma once
// A mesh file shown on its own, without a scene written for it: umbra stages
// it as a product shot (f3d and Blender stage a model much the same way).
// The model stands on a ground plane in its own up axis, lit by one point
// light above and to one side, seen from a raised three-quarter view that
// frames it and its shadow; the ground reaches past the frame's edges. The
// stage is written as scene text that the user can save and edit, and that
// reads back as the same scene.

#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "scene/mesh_loader.hpp"
#include "scene/scene.hpp"

namespace umbra {

// Whether `path` is a mesh file (by its content; see mesh_format.hpp) rather
// than a scene. False for a file that cannot be read: the scene parser then
// says why.
bool is_mesh_file(const std::string& path);

// Why `path` is plainly neither a scene nor a mesh file: "neither a scene
// nor a mesh file (OBJ, ..., or 3MF): a JPEG image". "" for a .scene file, a
// mesh file, or other text, which the scene parser reads (and says, line by
// line, what is wrong with), and for a file that cannot be read (the parser
// says why).
std::string neither_scene_nor_mesh(const std::string& path);

// "+x", "-x", "+y", "-y", "+z" or "-z": the axis of the file that points up.
bool is_up_axis(const std::string& up);

// The floor, light and camera for a model whose box, fitted and turned so that
// its up axis is +z, is [lo, hi]; the camera frames `points` (points of the
// model) and their shadows on the floor, in a picture `aspect` (width over
// height) wide: by the narrower of its two fields of view.
struct Stage {
  glm::dvec3 light{0.0};
  double floor_z = 0.0;  // a thousandth below the model, written to a millionth
  glm::dvec3 floor_centre{0.0};
  double floor_half_size = 0.0;
  Camera camera;
};
Stage stage_for(const glm::dvec3& lo, const glm::dvec3& hi, const std::vector<glm::dvec3>& points, double aspect = 1.0);

// Points of `mesh` that show its extent to a camera: the corners of up to
// `most` of its triangles, spread over them, and the corners that reach
// furthest along each axis.
std::vector<glm::dvec3> framing_points(const Mesh& mesh, size_t most = 4096);

// The name the staged scene goes by in messages: "MESH (staged)", in the mesh's folder.
std::string staged_scene_name(const std::string& mesh_path);

// How a mesh file on its own is staged: stood on its `up` axis ("" for its
// format's own), framed for a picture `frame_aspect` (width over height) wide.
struct StagingOptions {
  std::string up;
  double frame_aspect = 1.0;
};

// parse_scene_file for a scene, or the staged scene for a mesh file.
// `staged` (when given) receives the staged scene's text, or "" for a scene
// file. A mesh file with no faces is an InputError: there is nothing to show.
// `maps` says where texture maps may be read from.
Scene parse_scene_or_mesh_file(const std::string& path, const MeshLoadProgress& progress = {}, std::string* staged = nullptr,
                               const StagingOptions& staging = {}, const TextureMaps& maps = {});

}  // namespace umbra
