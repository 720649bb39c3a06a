// 3MF written with lib3mf, for `umbra check --repair OUT.3mf`: the parts
// the 3MF reader found (PolygonSoup::parts) come back as objects in their
// own coordinates, each placed by a build item with its transform, so that a
// slicer's user gets the print file's objects back, repaired.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

#include "mesh/input_error.hpp"
#include "mesh/io/lib3mf_support.hpp"
#include "mesh/io/mesh_writers.hpp"

namespace umbra {
namespace {

using namespace NMR;
using lib3mf::Held;

bool is_finite(const glm::dmat4& m) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(m[c][r])) return false;
  return true;
}

// The triangles of one part, to be written as one object.
struct Part {
  std::string name, part_number;
  glm::dmat4 placement{1.0};
  std::vector<size_t> triangles;
};

class ThreeMfWriter {
 public:
  ThreeMfWriter(const TriangleFile& mesh, const std::string& path) : mesh_(mesh), path_(path) {}

  void write(const std::string& write_to) {
    check(lib3mf_createmodel(&model_.object), nullptr);
    if (const auto unit = std::find(lib3mf::kUnits.begin(), lib3mf::kUnits.end(), mesh_.length_unit); unit != lib3mf::kUnits.end())
      check(lib3mf_model_setunit(model_.object, DWORD(unit - lib3mf::kUnits.begin())), model_.object);
    add_materials();
    for (const Part& part : parts())
      if (!part.triangles.empty()) add_part(part);
    Held writer;
    check(lib3mf_model_querywriter(model_.object, "3mf", &writer.object), model_.object);
    check(lib3mf_writer_writetofileutf8(writer.object, write_to.c_str()), writer.object);
  }

 private:
  // lib3mf's result, or its last error as an InputError located at the output.
  void check(LIB3MFRESULT result, PLib3MFBase* source) const {
    if (result == LIB3MF_OK) return;
    const std::string said = lib3mf::last_error(source);
    throw InputError({path_, 0, 0}, "cannot write the repaired mesh: lib3mf: " + (said.empty() ? "error " + std::to_string(result) : said));
  }

  // The file's parts with their triangles, then one for triangles of none.
  std::vector<Part> parts() const {
    std::vector<Part> parts;
    for (const SoupPart& p : mesh_.parts) parts.push_back({p.name, p.part_number, p.placement, {}});
    parts.push_back({std::filesystem::path(path_).stem().string(), "", glm::dmat4(1.0), {}});
    for (size_t t = 0; t < mesh_.triangles.size(); ++t) {
      const int part = t < mesh_.triangle_parts.size() ? mesh_.triangle_parts[t] : -1;
      parts[part >= 0 && size_t(part) < mesh_.parts.size() ? size_t(part) : parts.size() - 1].triangles.push_back(t);
    }
    return parts;
  }

  void add_materials() {
    if (mesh_.materials.empty()) return;
    check(lib3mf_model_addbasematerialgroup(model_.object, &materials_.object), model_.object);
    check(lib3mf_basematerial_getresourceid(materials_.object, &material_group_), materials_.object);
    for (size_t m = 0; m < mesh_.materials.size(); ++m) {
      const glm::dvec3 rgb = glm::clamp(mesh_.materials[m].diffuse, 0.0, 1.0) * 255.0;
      const BYTE r = BYTE(std::lround(rgb.r)), g = BYTE(std::lround(rgb.g)), b = BYTE(std::lround(rgb.b));
      DWORD index = 0;
      check(lib3mf_basematerial_addmaterialutf8(materials_.object, material_name(mesh_, m).c_str(), r, g, b, &index), materials_.object);
      // Opaque: lib3mf writes the colour it adds with an alpha of 0.
      check(lib3mf_basematerial_setdisplaycolorrgba(materials_.object, index, r, g, b, 255), materials_.object);
    }
  }

  void add_part(const Part& part) {
    // Its points in its own coordinates; a placement that cannot be undone
    // leaves them where they are, placed by none.
    const glm::dmat4 undo = glm::inverse(part.placement);
    const bool undone = is_finite(undo);
    const glm::dmat4 placement = undone ? part.placement : glm::dmat4(1.0);
    // The reader turned a mirroring placement's triangles round: turned back.
    const bool mirrored = glm::determinant(glm::dmat3(placement)) < 0.0;
    std::vector<uint32_t> number(mesh_.points.size(), UINT32_MAX);
    std::vector<MODELMESHVERTEX> vertices;
    std::vector<MODELMESHTRIANGLE> triangles;
    for (const size_t t : part.triangles) {
      MODELMESHTRIANGLE triangle;
      for (size_t k = 0; k < 3; ++k) {
        const uint32_t p = mesh_.triangles[t][k];
        if (number[p] == UINT32_MAX) {
          number[p] = uint32_t(vertices.size());
          const glm::dvec3 own = undone ? glm::dvec3(undo * glm::dvec4(mesh_.points[p], 1.0)) : mesh_.points[p];
          vertices.push_back({{float(own.x), float(own.y), float(own.z)}});
        }
        triangle.m_nIndices[k] = number[p];
      }
      if (mirrored) std::swap(triangle.m_nIndices[1], triangle.m_nIndices[2]);
      triangles.push_back(triangle);
    }
    Held object;
    check(lib3mf_model_addmeshobject(model_.object, &object.object), model_.object);
    if (!part.name.empty()) check(lib3mf_object_setnameutf8(object.object, part.name.c_str()), object.object);
    check(lib3mf_meshobject_setgeometry(object.object, vertices.data(), DWORD(vertices.size()), triangles.data(), DWORD(triangles.size())),
          object.object);
    if (!mesh_.triangle_materials.empty()) {
      // 3MF gives an object with coloured triangles a default, which its
      // uncoloured ones take: its first triangle's colour.
      const auto first = std::find_if(part.triangles.begin(), part.triangles.end(), [&](size_t t) { return mesh_.triangle_materials[t] >= 0; });
      if (first != part.triangles.end()) {
        Held default_material, properties;
        check(lib3mf_object_createdefaultpropertyhandler(object.object, &default_material.object), object.object);
        check(lib3mf_defaultpropertyhandler_setbasematerial(default_material.object, material_group_, DWORD(mesh_.triangle_materials[*first])),
              default_material.object);
        check(lib3mf_meshobject_createpropertyhandler(object.object, &properties.object), object.object);
        for (size_t k = 0; k < part.triangles.size(); ++k)
          if (const int m = mesh_.triangle_materials[part.triangles[k]]; m >= 0)
            check(lib3mf_propertyhandler_setbasematerial(properties.object, DWORD(k), material_group_, DWORD(m)), properties.object);
      }
    }
    MODELTRANSFORM transform = lib3mf::to_3mf(placement);
    Held item;
    check(lib3mf_model_addbuilditem(model_.object, object.object, &transform, &item.object), model_.object);
    if (!part.part_number.empty()) check(lib3mf_builditem_setpartnumberutf8(item.object, part.part_number.c_str()), item.object);
  }

  const TriangleFile& mesh_;
  const std::string& path_;
  Held model_, materials_;  // the model outlives the material group it holds
  DWORD material_group_ = 0;
};

}  // namespace

WrittenMesh write_3mf_file(const TriangleFile& mesh, const std::string& path, const std::string& write_to) {
  ThreeMfWriter(mesh, path).write(write_to);
  WrittenMesh written{{}, unkept(mesh, true, false, false, false)};
  if (std::any_of(mesh.materials.begin(), mesh.materials.end(), [](const SoupMaterial& m) { return bool(m.texture); }))
    written.dropped.push_back("texture maps");
  return written;
}

}  // namespace umbra
