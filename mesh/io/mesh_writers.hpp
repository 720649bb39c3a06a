#pragma once
// Writing a triangle mesh, with what a format can keep of the file's look
// (materials, texture coordinates, vertex colours, shading normals), for
// `umbra check --repair`. The formats' table (mesh_format.hpp) names the
// writer of each format it writes.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "mesh/io/polygon_soup.hpp"

namespace umbra {

// A triangle mesh and its look, as a writer takes it. Every attribute is
// optional (empty: none).
struct TriangleFile {
  std::vector<glm::dvec3> points;
  std::vector<std::array<uint32_t, 3>> triangles;
  std::vector<SoupMaterial> materials;
  std::vector<int> triangle_materials;    // per triangle, an index into `materials`, -1 for none
  std::vector<glm::vec3> point_colors;    // per point, each channel in [0, 1]
  std::vector<glm::vec2> corner_uvs;      // per corner (3 t + k), v running down the image as in PolygonSoup
  std::vector<glm::vec3> corner_normals;  // per corner; (0, 0, 0): none, and its face is drawn flat
  std::vector<SoupPart> parts;            // the file's parts, as PolygonSoup holds them
  std::vector<int> triangle_parts;        // per triangle, an index into `parts`, -1 for none
  std::string length_unit;                // as PolygonSoup names it; "" for none
};

// A file that the mesh names and that goes beside it: an OBJ's material
// library, a texture map that the source held inside itself.
struct CompanionFile {
  std::string path;   // its final path
  std::string what;   // "the material library", for messages
  std::string bytes;  // its whole content
};

struct WrittenMesh {
  std::vector<CompanionFile> companions;  // for the caller to write, each whole, beside the mesh
  std::vector<std::string> dropped;       // what the format could not keep, a phrase each: "texture coordinates"
};

// Writes `mesh` to `write_to` (a temporary name that ends as `path` does)
// in the format that `path` names, and returns the companion files that
// `path` refers to by name. Throws InputError, located at `path`, when it
// cannot be written.
using MeshWriter = WrittenMesh (*)(const TriangleFile& mesh, const std::string& path, const std::string& write_to);

// OBJ with its material library (PATH's stem and .mtl): materials, texture
// coordinates and shading normals per corner, and colours as "v x y z r g b",
// the extension most readers take. A texture map in the output's folder is
// named by its path from there; one elsewhere is copied beside the output as
// STEM.NAME, and one its source held inside itself (glTF's, a data URI) is
// written there as STEM.N.png, so that the output reads its maps from its own
// folder, as umbra reads a model's.
WrittenMesh write_obj_file(const TriangleFile& mesh, const std::string& path, const std::string& write_to);
// 3MF (lib3mf): each part an object of its own, named as it was, in its
// own coordinates, placed by a build item with its transform and part
// number, so that a 3MF's objects, build items and transforms come back
// (an object that two build items or components placed comes back twice,
// and components become build items of their own); materials as base
// materials, their names and display colours. Triangles of no part are one
// object, placed where they are.
WrittenMesh write_3mf_file(const TriangleFile& mesh, const std::string& path, const std::string& write_to);
// Binary PLY, points in double precision: vertex colours.
WrittenMesh write_ply_file(const TriangleFile& mesh, const std::string& path, const std::string& write_to);
// OFF, points in shortest round-trip decimal: geometry only.
WrittenMesh write_off_file(const TriangleFile& mesh, const std::string& path, const std::string& write_to);
// Binary STL, points rounded to float as the format stores them: geometry only.
WrittenMesh write_stl_file(const TriangleFile& mesh, const std::string& path, const std::string& write_to);

// For the writers: what a format without them leaves out of `mesh`, a
// phrase each ("texture coordinates").
std::vector<std::string> unkept(const TriangleFile& mesh, bool materials, bool uvs, bool colours, bool normals);
// A material's name, or "material_M" for one without.
std::string material_name(const TriangleFile& mesh, size_t m);

}  // namespace umbra
