#pragma once
// Writers of glTF, GLB and 3MF files for tests: a triangle soup as one glTF
// primitive or one 3MF object, with the placement and materials a test asks
// for. Written by hand (a stored zip, glTF JSON with a base64 buffer) so that
// each file is exactly what the test says.

#include <cstdint>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "mesh/io/polygon_soup.hpp"

namespace umbra::test {

inline std::string base64(const std::string& bytes) {
  static const char* kDigits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < bytes.size(); i += 3) {
    uint32_t v = uint32_t(uint8_t(bytes[i])) << 16;
    if (i + 1 < bytes.size()) v |= uint32_t(uint8_t(bytes[i + 1])) << 8;
    if (i + 2 < bytes.size()) v |= uint8_t(bytes[i + 2]);
    out += kDigits[(v >> 18) & 63];
    out += kDigits[(v >> 12) & 63];
    out += i + 1 < bytes.size() ? kDigits[(v >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? kDigits[v & 63] : '=';
  }
  return out;
}

template <typename T>
void append_le(std::string& out, T value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof value);  // little endian on the machines we build for
}

// `soup` (triangles) as ASCII STL, its coordinates to six decimals.
inline std::string stl_text(const PolygonSoup& soup) {
  std::string text = "solid s\n";
  for (size_t p = 0; p < soup.polygon_count(); ++p) {
    text += "facet normal 0 0 0\nouter loop\n";
    for (uint32_t c = 0; c < 3; ++c) {
      const glm::dvec3& q = soup.points[soup.polygon(p)[c]];
      text += "vertex " + std::to_string(q.x) + " " + std::to_string(q.y) + " " + std::to_string(q.z) + "\n";
    }
    text += "endloop\nendfacet\n";
  }
  return text + "endsolid s\n";
}

// A triangle soup's points as float VEC3 and its corners as uint32 indices:
// the one buffer of the glTF files below.
inline std::string gltf_buffer(const PolygonSoup& soup) {
  std::string bytes;
  for (const glm::dvec3& p : soup.points) append_le(bytes, float(p.x)), append_le(bytes, float(p.y)), append_le(bytes, float(p.z));
  for (uint32_t c : soup.corners) append_le(bytes, c);
  return bytes;
}

struct GltfOptions {
  std::string node = R"("mesh": 0)";  // the JSON members of node 0, the scene's root
  std::string extra_nodes;            // more nodes, each as ",{...}"
  std::string scene_nodes = "[0]";    // the scene's roots
  std::string more;                   // more top-level members, each as `, "name": ...` (textures, images, samplers)
  std::string material = R"({"name": "red", "pbrMetallicRoughness": {"baseColorFactor": [1, 0, 0, 1], "metallicFactor": 0}})";
  std::string buffer_uri;             // "" embeds the buffer as base64
  int mode = 4;                       // TRIANGLES
};

// glTF JSON for `soup` (triangles only), whose buffer is `buffer` (as
// gltf_buffer makes it, or broken on purpose); without a uri in a GLB.
inline std::string gltf_json(const PolygonSoup& soup, const std::string& buffer, const GltfOptions& o, bool in_glb = false) {
  const size_t point_bytes = soup.points.size() * 12;
  std::string uri;
  if (!in_glb) uri = R"(, "uri": ")" + (o.buffer_uri.empty() ? "data:application/octet-stream;base64," + base64(buffer) : o.buffer_uri) + "\"";
  return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": )" + o.scene_nodes + R"(}], "nodes": [{)" + o.node + "}" + o.extra_nodes +
         R"(], "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 0, "mode": )" +
         std::to_string(o.mode) + R"(}]}], "materials": [)" + o.material + R"(], "buffers": [{"byteLength": )" +
         std::to_string(buffer.size()) + uri + R"(}], "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": )" +
         std::to_string(point_bytes) + R"(}, {"buffer": 0, "byteOffset": )" + std::to_string(point_bytes) +
         R"(, "byteLength": )" + std::to_string(buffer.size() - point_bytes) +
         R"(}], "accessors": [{"bufferView": 0, "componentType": 5126, "count": )" + std::to_string(soup.points.size()) +
         R"(, "type": "VEC3"}, {"bufferView": 1, "componentType": 5125, "count": )" + std::to_string(soup.corners.size()) +
         R"(, "type": "SCALAR"}])" + o.more + "}";
}

inline std::string glb(const std::string& json, const std::string& buffer) {
  std::string j = json, b = buffer;
  while (j.size() % 4) j += ' ';
  while (b.size() % 4) b += '\0';
  std::string out = "glTF";
  append_le(out, uint32_t(2));
  append_le(out, uint32_t(12 + 8 + j.size() + 8 + b.size()));
  append_le(out, uint32_t(j.size()));
  out += "JSON" + j;
  append_le(out, uint32_t(b.size()));
  out += std::string("BIN\0", 4) + b;
  return out;
}

inline uint32_t crc32(const std::string& bytes) {
  uint32_t crc = 0xffffffffu;
  for (char ch : bytes) {
    crc ^= uint8_t(ch);
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
  }
  return ~crc;
}

// A zip archive whose entries are stored (not compressed).
inline std::string stored_zip(const std::vector<std::pair<std::string, std::string>>& entries) {
  std::string out, directory;
  for (const auto& [name, data] : entries) {
    const uint32_t offset = uint32_t(out.size()), crc = crc32(data), size = uint32_t(data.size());
    const auto header = [&](std::string& to, bool central) {
      append_le(to, central ? uint32_t(0x02014b50) : uint32_t(0x04034b50));
      if (central) append_le(to, uint16_t(20));
      for (uint16_t v : {uint16_t(20), uint16_t(0), uint16_t(0), uint16_t(0), uint16_t(0)}) append_le(to, v);
      append_le(to, crc), append_le(to, size), append_le(to, size);
      append_le(to, uint16_t(name.size())), append_le(to, uint16_t(0));
      if (central) {
        for (uint16_t v : {uint16_t(0), uint16_t(0), uint16_t(0)}) append_le(to, v);
        append_le(to, uint32_t(0)), append_le(to, offset);
      }
      to += name;
    };
    header(out, false);
    out += data;
    header(directory, true);
  }
  const uint32_t directory_offset = uint32_t(out.size());
  out += directory;
  append_le(out, uint32_t(0x06054b50));
  for (uint16_t v : {uint16_t(0), uint16_t(0), uint16_t(entries.size()), uint16_t(entries.size())}) append_le(out, v);
  append_le(out, uint32_t(directory.size())), append_le(out, directory_offset), append_le(out, uint16_t(0));
  return out;
}

// A 3MF object element for `soup` (triangles only), with base material
// `pindex` of group 1 on every triangle when it is >= 0.
inline std::string threemf_object(int id, const PolygonSoup& soup, int pindex = -1) {
  std::string s = "<object id=\"" + std::to_string(id) + "\" type=\"model\"" +
                  (pindex >= 0 ? " pid=\"1\" pindex=\"" + std::to_string(pindex) + "\"" : "") + "><mesh><vertices>";
  for (const glm::dvec3& p : soup.points)
    s += "<vertex x=\"" + std::to_string(p.x) + "\" y=\"" + std::to_string(p.y) + "\" z=\"" + std::to_string(p.z) + "\"/>";
  s += "</vertices><triangles>";
  for (size_t f = 0; f < soup.polygon_count(); ++f)
    s += "<triangle v1=\"" + std::to_string(soup.polygon(f)[0]) + "\" v2=\"" + std::to_string(soup.polygon(f)[1]) + "\" v3=\"" +
         std::to_string(soup.polygon(f)[2]) + "\"/>";
  return s + "</triangles></mesh></object>";
}

// A 3MF package: `resources` and `build` are the model's XML elements' contents.
inline std::string threemf(const std::string& resources, const std::string& build, const std::string& unit = "millimeter") {
  const std::string model =
      R"(<?xml version="1.0" encoding="UTF-8"?><model unit=")" + unit + R"(" xml:lang="en-US" )"
      R"(xmlns="http://schemas.microsoft.com/3dmanufacturing/core/2015/02"><resources>)" +
      resources + "</resources><build>" + build + "</build></model>";
  const std::string types =
      R"(<?xml version="1.0" encoding="UTF-8"?><Types xmlns="http://schemas.openxmlformats.org/package/2006/content-types">)"
      R"(<Default Extension="rels" ContentType="application/vnd.openxmlformats-package.relationships+xml"/>)"
      R"(<Default Extension="model" ContentType="application/vnd.ms-package.3dmanufacturing-3dmodel+xml"/></Types>)";
  const std::string rels =
      R"(<?xml version="1.0" encoding="UTF-8"?><Relationships xmlns="http://schemas.openxmlformats.org/package/2006/relationships">)"
      R"(<Relationship Target="/3D/3dmodel.model" Id="rel0" Type="http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel"/>)"
      R"(</Relationships>)";
  return stored_zip({{"[Content_Types].xml", types}, {"_rels/.rels", rels}, {"3D/3dmodel.model", model}});
}

}  // namespace umbra::test
