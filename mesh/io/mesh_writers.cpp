#include "mesh/io/mesh_writers.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <unordered_map>

#include <glm/geometric.hpp>
#include <stb_image_write.h>  // Debian's libstb: its implementation is in libstb.so

#include "mesh/input_error.hpp"
#include "mesh/io/texture_file.hpp"

namespace umbra {
namespace {

// MTL's "-clamp on " before a map's name, where the map takes coordinates
// outside [0, 1] to its edge along both axes (glTF's clamp-to-edge
// sampler); MTL has no other wrap than repeat.
std::string clamp_option(const TextureImage& map) {
  const bool clamped = map.wrap_u == TextureImage::Wrap::kClampToEdge && map.wrap_v == TextureImage::Wrap::kClampToEdge;
  return clamped ? "-clamp on " : "";
}


// The shortest decimal that reads back as the same double.
void put_number(std::string& out, double x) {
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, x == 0.0 ? 0.0 : x).ptr;
  out.append(buffer, end);
}

void put_numbers(std::string& out, std::initializer_list<double> xs) {
  for (const double x : xs) {
    out += ' ';
    put_number(out, x);
  }
}

// Writes `bytes` to `write_to` whole, or throws located at `path`.
void write_bytes(const std::string& bytes, const std::string& path, const std::string& write_to) {
  std::ofstream out(write_to, std::ios::binary | std::ios::trunc);
  if (out) out.write(bytes.data(), std::streamsize(bytes.size()));
  if (out) out.close();
  if (!out) throw InputError({path, 0, 0}, std::string("cannot write the repaired mesh: ") + std::strerror(errno));
}

// Each distinct value of a per-corner attribute, numbered from 1 in order of
// first use, as an OBJ's `vt` and `vn` lines are.
template <size_t kSize>
struct NumberedValues {
  std::map<std::array<double, kSize>, uint32_t> index;
  uint32_t number(const std::array<double, kSize>& value, std::string& lines, const char* keyword) {
    const auto [at, added] = index.try_emplace(value, uint32_t(index.size() + 1));
    if (added) {
      lines += keyword;
      for (const double x : value) {
        lines += ' ';
        put_number(lines, x);
      }
      lines += '\n';
    }
    return at->second;
  }
};

// A texture map held inside its source, as PNG bytes.
std::string png_bytes(const TextureImage& image) {
  std::string bytes;
  stbi_write_png_to_func([](void* context, void* data, int size) { static_cast<std::string*>(context)->append(static_cast<const char*>(data), size_t(size)); },
                         &bytes, image.width, image.height, 4, image.rgba.data(), image.width * 4);
  return bytes;
}

// The material library of `mesh`, and the maps it writes beside `path`.
std::string material_library(const TriangleFile& mesh, const std::filesystem::path& path, std::vector<CompanionFile>& companions) {
  std::string text = "# materials of " + path.filename().string() + ", written by umbra check --repair\n";
  std::error_code ec;
  const std::filesystem::path folder = std::filesystem::absolute(path, ec).parent_path();
  std::map<std::string, std::string> copied;  // the maps copied beside the output, by name, and their sources
  for (size_t m = 0; m < mesh.materials.size(); ++m) {
    const SoupMaterial& material = mesh.materials[m];
    text += "\nnewmtl " + material_name(mesh, m) + "\nKd";
    put_numbers(text, {material.diffuse.r, material.diffuse.g, material.diffuse.b});
    text += "\nKs";
    put_numbers(text, {material.specular.r, material.specular.g, material.specular.b});
    text += "\nNs";
    put_numbers(text, {material.shininess});
    text += '\n';
    if (!material.texture) continue;
    const std::string what = "material \"" + material_name(mesh, m) + "\"'s texture map";
    const std::string& source = material.texture->file;
    const std::filesystem::path relative = std::filesystem::absolute(source, ec).lexically_normal().lexically_relative(folder);
    if (!source.empty() && !relative.empty() && *relative.begin() != "..") {
      text += "map_Kd " + clamp_option(*material.texture) + relative.generic_string() + "\n";  // in the output's folder already
      continue;
    }
    // Copied beside the output, which then reads it from its own folder as
    // umbra reads any model's maps (texture_file.hpp), and travels whole.
    // One copy of a file that several materials name; two files of one name
    // from different folders each their own (the second with the material's number).
    std::string name = path.stem().string() + "." +
                       (source.empty() ? std::to_string(m) + ".png" : std::filesystem::path(source).filename().string());
    const auto [copy, added] = copied.try_emplace(name, source);
    const bool copied_already = !added && !source.empty() && copy->second == source;
    if (!added && !copied_already) {
      name = path.stem().string() + "." + std::to_string(m) + "." + std::filesystem::path(source).filename().string();
      copied.emplace(name, source);
    }
    text += "map_Kd " + clamp_option(*material.texture) + name + "\n";
    if (copied_already) continue;
    std::vector<unsigned char> bytes;
    std::string error;
    if (!source.empty() && !read_regular_file(source, kMostTextureFileBytes, bytes, error))
      throw InputError({path.string(), 0, 0}, "cannot copy " + what + " " + source + ": " + error);
    companions.push_back({(path.parent_path() / name).string(), what,
                          source.empty() ? png_bytes(*material.texture) : std::string(bytes.begin(), bytes.end())});
  }
  return text;
}

// Whether corner c of the mesh has a shading normal.
bool has_normal(const TriangleFile& mesh, size_t c) {
  return !mesh.corner_normals.empty() && mesh.corner_normals[c] != glm::vec3(0.0f);
}

}  // namespace

WrittenMesh write_obj_file(const TriangleFile& mesh, const std::string& path, const std::string& write_to) {
  WrittenMesh written;
  const std::filesystem::path output(path);
  std::string text = "# written by umbra check --repair\n";
  if (!mesh.materials.empty()) {
    const std::filesystem::path library = output.parent_path() / (output.stem().string() + ".mtl");
    std::string library_text = material_library(mesh, output, written.companions);
    written.companions.push_back({library.string(), "the material library", std::move(library_text)});
    text += "mtllib " + library.filename().string() + "\n";
  }
  for (size_t p = 0; p < mesh.points.size(); ++p) {
    text += 'v';
    put_numbers(text, {mesh.points[p].x, mesh.points[p].y, mesh.points[p].z});
    if (!mesh.point_colors.empty()) put_numbers(text, {mesh.point_colors[p].r, mesh.point_colors[p].g, mesh.point_colors[p].b});
    text += '\n';
  }
  NumberedValues<2> uvs;
  NumberedValues<3> normals;
  std::string faces;
  int material = -1;
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const int wanted = mesh.triangle_materials.empty() ? -1 : mesh.triangle_materials[t];
    if (wanted != material && wanted >= 0) faces += "usemtl " + material_name(mesh, size_t(wanted)) + "\n";
    material = wanted;
    const bool smooth = has_normal(mesh, 3 * t) && has_normal(mesh, 3 * t + 1) && has_normal(mesh, 3 * t + 2);
    faces += 'f';
    for (size_t k = 0; k < 3; ++k) {
      const size_t c = 3 * t + k;
      faces += ' ' + std::to_string(mesh.triangles[t][k] + 1);
      // OBJ's v runs up the image, PolygonSoup's down; turned over in double,
      // where 1 - v is exact for a float v, so that reading turns it back.
      const glm::vec2 uv = mesh.corner_uvs.empty() ? glm::vec2(0.0f) : mesh.corner_uvs[c];
      if (!mesh.corner_uvs.empty()) faces += '/' + std::to_string(uvs.number({uv.x, 1.0 - double(uv.y)}, text, "vt"));
      const glm::vec3 n = smooth ? mesh.corner_normals[c] : glm::vec3(0.0f);
      if (smooth) faces += (mesh.corner_uvs.empty() ? "//" : "/") + std::to_string(normals.number({n.x, n.y, n.z}, text, "vn"));
    }
    faces += '\n';
  }
  write_bytes(text + faces, path, write_to);
  return written;
}

WrittenMesh write_ply_file(const TriangleFile& mesh, const std::string& path, const std::string& write_to) {
  const bool colours = !mesh.point_colors.empty();
  std::string bytes = "ply\nformat binary_little_endian 1.0\ncomment written by umbra check --repair\nelement vertex " +
                      std::to_string(mesh.points.size()) + "\nproperty double x\nproperty double y\nproperty double z\n";
  if (colours) bytes += "property uchar red\nproperty uchar green\nproperty uchar blue\n";
  bytes += "element face " + std::to_string(mesh.triangles.size()) + "\nproperty list uchar uint vertex_indices\nend_header\n";
  const auto put = [&bytes](const auto& value) { bytes.append(reinterpret_cast<const char*>(&value), sizeof value); };  // x86-64 and ARM64: little endian
  for (size_t p = 0; p < mesh.points.size(); ++p) {
    put(mesh.points[p]);
    if (colours)
      for (int channel = 0; channel < 3; ++channel)
        put(uint8_t(std::lround(std::clamp(mesh.point_colors[p][channel], 0.0f, 1.0f) * 255.0f)));
  }
  for (const auto& triangle : mesh.triangles) {
    put(uint8_t(3));
    put(triangle);
  }
  write_bytes(bytes, path, write_to);
  return {{}, unkept(mesh, false, false, true, false)};
}

WrittenMesh write_off_file(const TriangleFile& mesh, const std::string& path, const std::string& write_to) {
  std::string text = "OFF\n" + std::to_string(mesh.points.size()) + " " + std::to_string(mesh.triangles.size()) + " 0\n";
  for (const glm::dvec3& p : mesh.points) {
    put_numbers(text, {p.x, p.y, p.z});
    text += '\n';
  }
  for (const auto& t : mesh.triangles)
    text += "3 " + std::to_string(t[0]) + " " + std::to_string(t[1]) + " " + std::to_string(t[2]) + "\n";
  write_bytes(text, path, write_to);
  return {{}, unkept(mesh, false, false, false, false)};
}

WrittenMesh write_stl_file(const TriangleFile& mesh, const std::string& path, const std::string& write_to) {
  std::string bytes(80, ' ');
  bytes.replace(0, 30, "binary STL written by umbra   ");
  const auto put = [&bytes](const auto& value) { bytes.append(reinterpret_cast<const char*>(&value), sizeof value); };
  put(uint32_t(mesh.triangles.size()));
  for (const auto& t : mesh.triangles) {
    const glm::dvec3 a = mesh.points[t[0]], b = mesh.points[t[1]], c = mesh.points[t[2]];
    const glm::dvec3 n = glm::cross(b - a, c - a);
    const double length = glm::length(n);
    put(glm::vec3(length > 0.0 ? n / length : glm::dvec3(0.0)));
    for (const glm::dvec3& p : {a, b, c}) put(glm::vec3(p));
    put(uint16_t(0));
  }
  write_bytes(bytes, path, write_to);
  return {{}, unkept(mesh, false, false, false, false)};
}

std::vector<std::string> unkept(const TriangleFile& mesh, bool materials, bool uvs, bool colours, bool normals) {
  std::vector<std::string> dropped;
  if (!materials && !mesh.materials.empty()) dropped.push_back("materials");
  if (!uvs && !mesh.corner_uvs.empty()) dropped.push_back("texture coordinates");
  if (!colours && !mesh.point_colors.empty()) dropped.push_back("vertex colours");
  if (!normals && !mesh.corner_normals.empty()) dropped.push_back("shading normals");
  return dropped;
}

std::string material_name(const TriangleFile& mesh, size_t m) {
  const std::string& name = mesh.materials[m].name;
  return name.empty() ? "material_" + std::to_string(m) : name;
}

}  // namespace umbra
