#pragma once
// A mesh file exactly as written: points and polygons in file order, nothing
// merged, dropped or reoriented, so that a check sees every defect the file
// has (a half-edge structure would refuse some of them on loading).

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "mesh/texture_image.hpp"

namespace umbra {

// Something a reader accepted although the format forbids it (an exporter's
// quirk): read anyway, and said once. `line` is 0 for the file as a whole.
struct ReadWarning {
  int line = 0;
  std::string message;
};

// A surface colour that a file gives its faces (OBJ's mtl Kd/Ks/Ns, glTF's
// baseColorFactor, 3MF's base materials), in the scene's Phong terms.
struct SoupMaterial {
  std::string name;
  glm::dvec3 diffuse{0.8};
  glm::dvec3 specular{0.0};
  double shininess = 32.0;
  // Its diffuse texture map, which multiplies `diffuse` where faces have
  // texture coordinates (PolygonSoup::corner_uvs); none when the file gives
  // none or it could not be read (a warning says so).
  std::shared_ptr<const TextureImage> texture;
};

// A part of the file that a writer can give back as it was: a 3MF build
// item's object (or a component of it), with the transform that placed its
// points where the soup holds them.
struct SoupPart {
  std::string name;            // the object's name; "" for none
  std::string part_number;     // its build item's part number; "" for none
  glm::dmat4 placement{1.0};   // from the object's own coordinates to the soup's
};

// How finely a CAD exchange file's surfaces are cut into triangles (Open
// CASCADE's BRepMesh_IncrementalMesh): the farthest a triangle may stray
// from its surface, as a fraction of the shape's bounding box diagonal, and
// the largest angle between neighbouring triangles' normals, in radians.
// The defaults are f3d's.
struct CadTessellation {
  double relative_deflection = 1e-3;
  double angle = 0.5;
};

// How a reader reads. Whether it reads its materials' texture maps, and
// from where: a picture needs them (decoded, they can take far more memory
// than the mesh); a check does not. A model from anywhere names its maps by
// any path it likes, and a map is decoded into the picture: so a map is
// read only from inside `root`, whatever path names it, unless `anywhere`.
// And how CAD files are tessellated.
struct ReadOptions {
  bool read = true;       // read texture maps
  std::string root;       // the folder the user named; "" for the model file's own folder
  bool anywhere = false;  // --any-texture-path: maps from any folder the user can read
  CadTessellation cad;
  static ReadOptions skip() { return {false, "", false, {}}; }  // no texture maps
};

struct PolygonSoup {
  std::string path;
  std::string format;                 // "OBJ", "OFF", "PLY (binary little endian)", "STL (ascii)", ...
  std::vector<glm::dvec3> points;     // in file order
  std::vector<int> point_lines;       // line of each point; empty or 0 in binary files
  std::vector<uint32_t> corners;      // point indices of every polygon, polygon after polygon
  std::vector<uint32_t> polygon_starts{0};  // polygon p is corners[starts[p], starts[p+1])
  std::vector<int> polygon_lines;     // line of each polygon; empty or 0 in binary files
  std::vector<ReadWarning> warnings;  // quirks read past, in file order
  std::vector<SoupMaterial> materials;   // the file's own, if it has any
  std::vector<int> polygon_materials;    // index into `materials` per polygon, -1 for none; empty: none at all
  // Per point, its colour as the file gives it (PLY red/green/blue, OBJ
  // "v x y z r g b", glTF COLOR_0), each channel in [0, 1]; empty when the
  // file gives none. Colours belong to the file's points, not to merged
  // vertices: two points at one place may differ.
  std::vector<glm::vec3> point_colors;
  // Per corner (parallel to `corners`), its texture coordinates, with v
  // running down the image (glTF's convention; OBJ's v is turned over on
  // reading); empty unless some material has a texture map.
  std::vector<glm::vec2> corner_uvs;
  // Per corner (parallel to `corners`), the normal the file gives it for
  // smooth shading (OBJ's vn, PLY's nx ny nz, glTF's NORMAL), as written,
  // not always of unit length; (0, 0, 0) for a corner without one. Empty
  // when the file gives none, or the soup is read for a check, which has no
  // use for them.
  std::vector<glm::vec3> corner_normals;
  // The file's parts (3MF's), and per polygon an index into them; both
  // empty for a file read as one part.
  std::vector<SoupPart> parts;
  std::vector<int> polygon_parts;
  // The unit of length the file names (3MF's "millimeter", "inch", ...);
  // "" where it names none.
  std::string length_unit;

  size_t polygon_count() const { return polygon_starts.size() - 1; }
  uint32_t corner_count(size_t p) const { return polygon_starts[p + 1] - polygon_starts[p]; }
  const uint32_t* polygon(size_t p) const { return corners.data() + polygon_starts[p]; }
  int point_line(size_t i) const { return i < point_lines.size() ? point_lines[i] : 0; }
  int polygon_line(size_t p) const { return p < polygon_lines.size() ? polygon_lines[p] : 0; }
  int polygon_material(size_t p) const { return p < polygon_materials.size() ? polygon_materials[p] : -1; }

  // corner_normals from a normal per point (PLY's, glTF's): none when there
  // are none, or not one for every point.
  void set_corner_normals_of_points(const std::vector<glm::vec3>& point_normals) {
    if (point_normals.empty() || point_normals.size() != points.size()) return;
    corner_normals.resize(corners.size());
    for (size_t c = 0; c < corners.size(); ++c)
      corner_normals[c] = corners[c] < point_normals.size() ? point_normals[corners[c]] : glm::vec3(0.0f);
  }
  void warn(int line, std::string message) { warnings.push_back({line, std::move(message)}); }
  void add_point(const glm::dvec3& p, int line) {
    points.push_back(p);
    point_lines.push_back(line);
  }
  // Closes the polygon made of the corners added since the last one.
  void end_polygon(int line) {
    polygon_starts.push_back(uint32_t(corners.size()));
    polygon_lines.push_back(line);
  }
};

}  // namespace umbra
