// 3MF (3D Manufacturing Format), read with lib3mf: every item of the build,
// each placed by its transform; an item that is a components object brings
// its components, each with its own transform. Base-material colours become
// the faces' materials.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <regex>
#include <set>
#include <string>

#include <glm/mat4x4.hpp>

#include <Model/COM/NMR_DLLInterfaces.h>
#include <zip.h>

#include "mesh/input_error.hpp"
#include "mesh/io/lib3mf_support.hpp"
#include "mesh/io/mesh_readers.hpp"

namespace umbra {
namespace {

using namespace NMR;
using lib3mf::Held;

// A lib3mf text (an object's name, a build item's part number), whole; ""
// when it has none.
template <typename Object>
std::string text_of(Object* object, LIB3MFRESULT (*get)(Object*, LPSTR, ULONG, ULONG*)) {
  ULONG needed = 0;
  if (get(object, nullptr, 0, &needed) != LIB3MF_OK || needed == 0) return "";
  std::string text(needed + 1, '\0');  // room for the terminating zero, which `needed` does not count
  if (get(object, text.data(), ULONG(text.size()), &needed) != LIB3MF_OK) return "";
  text.resize(std::strlen(text.c_str()));
  return text;
}

class ThreeMfReader {
 public:
  ThreeMfReader(PLib3MFModel* model, PolygonSoup& soup) : model_(model), soup_(soup) {}

  void read() {
    Held items;
    check(lib3mf_model_getbuilditems(model_, &items.object), model_);
    BOOL more = false;
    while (check(lib3mf_builditemiterator_movenext(items.object, &more), items.object), more) {
      Held item, object;
      check(lib3mf_builditemiterator_getcurrent(items.object, &item.object), items.object);
      check(lib3mf_builditem_getobjectresource(item.object, &object.object), item.object);
      MODELTRANSFORM transform;
      check(lib3mf_builditem_getobjecttransform(item.object, &transform), item.object);
      part_number_ = text_of(item.object, lib3mf_builditem_getpartnumberutf8);
      add_object(object.object, lib3mf::to_glm(transform));
    }
  }

 private:
  [[noreturn]] void fail(const std::string& message) const { throw InputError({soup_.path, 0, 0}, message); }

  // lib3mf's result, or its last error as an InputError.
  bool check(LIB3MFRESULT result, PLib3MFBase* source) const {
    if (result == LIB3MF_OK) return true;
    const std::string said = lib3mf::last_error(source);
    fail("lib3mf: " + (said.empty() ? "error " + std::to_string(result) : said));
  }

  DWORD resource_id(PLib3MFModelObjectResource* object) const {
    DWORD id = 0;
    check(lib3mf_resource_getresourceid(object, &id), object);
    return id;
  }

  void add_object(PLib3MFModelObjectResource* object, const glm::dmat4& transform) {
    const DWORD id = resource_id(object);
    if (!on_path_.insert(id).second) fail("object " + std::to_string(id) + " contains itself: its components form a cycle");
    BOOL is_mesh = false, is_components = false;
    check(lib3mf_object_ismeshobject(object, &is_mesh), object);
    check(lib3mf_object_iscomponentsobject(object, &is_components), object);
    if (is_mesh) add_mesh(object, id, transform);
    if (is_components) {
      DWORD count = 0;
      check(lib3mf_componentsobject_getcomponentcount(object, &count), object);
      for (DWORD c = 0; c < count; ++c) {
        Held component, part;
        check(lib3mf_componentsobject_getcomponent(object, c, &component.object), object);
        check(lib3mf_component_getobjectresource(component.object, &part.object),
              component.object);
        MODELTRANSFORM local;
        check(lib3mf_component_gettransform(component.object, &local), component.object);
        add_object(part.object, transform * lib3mf::to_glm(local));
      }
    }
    on_path_.erase(id);
  }

  // The soup's material for base material `index` of group `group`, added when first used.
  int material(DWORD group, DWORD index) {
    const auto key = std::make_pair(group, index);
    if (const auto it = materials_.find(key); it != materials_.end()) return it->second;
    Held base;
    if (lib3mf_model_getbasematerialbyid(model_, group, &base.object) != LIB3MF_OK)
      return materials_[key] = -1;
    BYTE r = 0, g = 0, b = 0, a = 0;
    if (lib3mf_basematerial_getdisplaycolor(base.object, index, &r, &g, &b, &a) != LIB3MF_OK) return materials_[key] = -1;
    SoupMaterial m;
    char name[256] = {};
    ULONG needed = 0;
    if (lib3mf_basematerial_getnameutf8(base.object, index, name, sizeof name, &needed) == LIB3MF_OK) m.name = name;
    m.diffuse = glm::dvec3(r, g, b) / 255.0;
    soup_.materials.push_back(m);
    return materials_[key] = int(soup_.materials.size() - 1);
  }

  void add_mesh(PLib3MFModelMeshObject* mesh, DWORD id, const glm::dmat4& transform) {
    DWORD vertex_count = 0, triangle_count = 0;
    check(lib3mf_meshobject_getvertexcount(mesh, &vertex_count), mesh);
    check(lib3mf_meshobject_gettrianglecount(mesh, &triangle_count), mesh);
    std::vector<MODELMESHVERTEX> vertices(vertex_count);
    std::vector<MODELMESHTRIANGLE> triangles(triangle_count);
    if (vertex_count) check(lib3mf_meshobject_getvertices(mesh, vertices.data(), vertex_count, nullptr), mesh);
    if (triangle_count) check(lib3mf_meshobject_gettriangleindices(mesh, triangles.data(), triangle_count, nullptr), mesh);
    soup_.parts.push_back({text_of(mesh, lib3mf_object_getnameutf8), part_number_, transform});
    const uint32_t first = uint32_t(soup_.points.size());
    for (DWORD v = 0; v < vertex_count; ++v) {
      const float* xyz = vertices[v].m_fPosition;
      const glm::dvec3 p(transform * glm::dvec4(xyz[0], xyz[1], xyz[2], 1.0));
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        fail("object " + std::to_string(id) + " vertex " + std::to_string(v) + " has a coordinate that is not a finite number");
      soup_.points.push_back(p);
    }
    // Each triangle's base material, when it has one.
    Held properties;
    check(lib3mf_meshobject_createpropertyhandler(mesh, &properties.object), mesh);
    const bool mirrored = glm::determinant(glm::dmat3(transform)) < 0.0;
    for (DWORD t = 0; t < triangle_count; ++t) {
      DWORD a = triangles[t].m_nIndices[0], b = triangles[t].m_nIndices[1], c = triangles[t].m_nIndices[2];
      if (a >= vertex_count || b >= vertex_count || c >= vertex_count)
        fail("object " + std::to_string(id) + " triangle " + std::to_string(t) + " refers to a vertex it does not have");
      if (mirrored) std::swap(b, c);  // a mirroring transform turns the winding round
      soup_.corners.insert(soup_.corners.end(), {first + a, first + b, first + c});
      soup_.end_polygon(0);
      eModelPropertyType type = MODELPROPERTYTYPE_NONE;
      DWORD group = 0, index = 0;
      const bool based = lib3mf_propertyhandler_getpropertytype(properties.object, t, &type) == LIB3MF_OK &&
                         type == MODELPROPERTYTYPE_BASEMATERIALS &&
                         lib3mf_propertyhandler_getbasematerial(properties.object, t, &group, &index) == LIB3MF_OK;
      soup_.polygon_materials.push_back(based ? material(group, index) : -1);
      soup_.polygon_parts.push_back(int(soup_.parts.size() - 1));
    }
  }

  PLib3MFModel* model_;
  PolygonSoup& soup_;
  std::set<DWORD> on_path_;  // the objects from the build item to the one being read
  std::string part_number_;  // the build item's being read
  std::map<std::pair<DWORD, DWORD>, int> materials_;
};

// A zip archive ends with its central directory's last record ("PK\5\6",
// within the last 22 + 65535 bytes, the longest comment).
bool has_end_of_central_directory(std::string_view bytes) {
  const size_t tail = std::min<size_t>(bytes.size(), 22 + 65535);
  return bytes.substr(bytes.size() - tail).find("PK\x05\x06") != std::string_view::npos;
}

// The model part of a 3MF package (its 3D/3dmodel.model, as every producer
// names it), read with libzip; "" when there is none.
std::string model_part(std::string_view bytes) {
  zip_error_t error;
  zip_error_init(&error);
  zip_source_t* source = zip_source_buffer_create(bytes.data(), bytes.size(), 0, &error);
  zip_t* archive = source ? zip_open_from_source(source, ZIP_RDONLY, &error) : nullptr;
  std::string xml;
  if (!archive) {
    if (source) zip_source_free(source);
  } else {
    zip_stat_t stat;
    zip_file_t* part = zip_stat(archive, "3D/3dmodel.model", 0, &stat) == 0 ? zip_fopen(archive, "3D/3dmodel.model", 0) : nullptr;
    if (part) {
      xml.resize(stat.size);
      if (zip_fread(part, xml.data(), stat.size) != zip_int64_t(stat.size)) xml.clear();
      zip_fclose(part);
    }
    zip_close(archive);
  }
  zip_error_fini(&error);
  return xml;
}

// The first object of `xml` with neither a mesh nor components, as
// "object 3 (\"Box\")", or "": lib3mf refuses one without naming it.
std::string object_without_content(const std::string& xml) {
  static const std::regex object(R"re(<(?:\w+:)?object\b([^>]*?)(/>|>([\s\S]*?)</(?:\w+:)?object>))re");
  static const std::regex id(R"re(\bid\s*=\s*"([^"]*)")re"), name(R"re(\bname\s*=\s*"([^"]*)")re");
  for (std::sregex_iterator it(xml.begin(), xml.end(), object), end; it != end; ++it) {
    const std::string body = (*it)[3];
    if (body.find("mesh") != std::string::npos || body.find("components") != std::string::npos) continue;
    const std::string attributes = (*it)[1];
    std::smatch m;
    std::string named = "object " + (std::regex_search(attributes, m, id) ? m[1].str() : std::string("?"));
    if (std::regex_search(attributes, m, name)) named += " (\"" + m[1].str() + "\")";
    return named;
  }
  return "";
}

}  // namespace

PolygonSoup read_3mf(std::string_view bytes, const std::string& path) {
  // Said here rather than by libzip through lib3mf, more plainly (and without
  // lib3mf 1.8.1 leaking its zip source when libzip refuses an archive).
  if (bytes.substr(0, 4) != std::string_view("PK\x03\x04", 4))
    throw InputError({path, 0, 0}, "not a valid 3MF file: it is not a zip archive, which a 3MF file is");
  if (!has_end_of_central_directory(bytes))
    throw InputError({path, 0, 0}, "not a valid 3MF file: the zip archive is cut short (it has no end of central directory)");
  Held model, reader;
  if (lib3mf_createmodel(&model.object) != LIB3MF_OK)
    throw InputError({path, 0, 0}, "lib3mf could not start");
  if (lib3mf_model_queryreader(model.object, "3mf", &reader.object) != LIB3MF_OK)
    throw InputError({path, 0, 0}, "lib3mf has no 3MF reader");
  // lib3mf reads from a buffer it does not write to, whatever its signature says.
  std::vector<BYTE> copy(bytes.begin(), bytes.end());
  if (lib3mf_reader_readfrombuffer(reader.object, copy.data(), copy.size()) != LIB3MF_OK) {
    std::string said = lib3mf::last_error(reader.object);
    if (said.empty()) said = "lib3mf could not read it";
    if (said.find("no supported content type") != std::string::npos)
      if (const std::string empty = object_without_content(model_part(bytes)); !empty.empty())
        throw InputError({path, 0, 0}, "not a valid 3MF file: " + empty + " has neither a mesh nor components (lib3mf: " + said + ")");
    throw InputError({path, 0, 0}, "not a valid 3MF file: " + said);
  }
  PolygonSoup soup;
  soup.path = path;
  soup.format = "3MF";
  // lib3mf warns once per element: each kind of warning is said once, counted.
  DWORD warnings = 0;
  lib3mf_reader_getwarningcount(reader.object, &warnings);
  std::vector<std::pair<std::string, size_t>> kinds;
  for (DWORD w = 0; w < warnings; ++w) {
    char text[512] = {};
    DWORD code = 0;
    ULONG needed = 0;
    if (lib3mf_reader_getwarningutf8(reader.object, w, &code, text, sizeof text, &needed) != LIB3MF_OK) continue;
    const auto same = std::find_if(kinds.begin(), kinds.end(), [&](const auto& kind) { return kind.first == text; });
    if (same != kinds.end()) ++same->second;
    else kinds.emplace_back(text, 1);
  }
  for (const auto& [text, count] : kinds)
    soup.warn(0, "lib3mf: " + text + (count > 1 ? " (" + std::to_string(count) + " times)" : ""));
  if (DWORD unit = 0; lib3mf_model_getunit(model.object, &unit) == LIB3MF_OK && unit < lib3mf::kUnits.size())
    soup.length_unit = lib3mf::kUnits[unit];
  ThreeMfReader(model.object, soup).read();
  return soup;
}

}  // namespace umbra
