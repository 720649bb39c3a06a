// Makes the large mesh that bench/check_benchmark.sh times: a mesh read with
// umbra's readers, each triangle split into four at its edge midpoints LEVELS
// times (the surface and its topology stay the same), written as binary STL,
// as OBJ and as glTF binary (.glb).
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>

#include "mesh/input_error.hpp"
#include "mesh/io/mesh_file.hpp"
#include "mesh/check/point_merging.hpp"
#include "mesh/check/polygon_triangulation.hpp"

namespace {

using Triangle = std::array<uint32_t, 3>;

void subdivide(std::vector<glm::dvec3>& points, std::vector<Triangle>& triangles) {
  std::map<std::pair<uint32_t, uint32_t>, uint32_t> midpoint;
  const auto middle = [&](uint32_t a, uint32_t b) {
    const auto key = std::minmax(a, b);
    const auto [it, added] = midpoint.try_emplace(key, uint32_t(points.size()));
    if (added) points.push_back(0.5 * (points[a] + points[b]));
    return it->second;
  };
  std::vector<Triangle> finer;
  finer.reserve(triangles.size() * 4);
  for (const Triangle& t : triangles) {
    const uint32_t ab = middle(t[0], t[1]), bc = middle(t[1], t[2]), ca = middle(t[2], t[0]);
    finer.push_back({t[0], ab, ca});
    finer.push_back({ab, t[1], bc});
    finer.push_back({ca, bc, t[2]});
    finer.push_back({ab, bc, ca});
  }
  triangles = std::move(finer);
}

void write_stl(const std::string& path, const std::vector<glm::dvec3>& points, const std::vector<Triangle>& triangles) {
  std::ofstream out(path, std::ios::binary);
  const std::string header(80, ' ');
  out.write(header.data(), 80);
  const uint32_t count = uint32_t(triangles.size());
  out.write(reinterpret_cast<const char*>(&count), 4);
  for (const Triangle& t : triangles) {
    float record[12] = {0, 0, 0};
    for (int k = 0; k < 3; ++k)
      for (int i = 0; i < 3; ++i) record[3 + 3 * k + i] = float(points[t[size_t(k)]][i]);
    out.write(reinterpret_cast<const char*>(record), sizeof record);
    out.write("\0\0", 2);
  }
}

void write_obj(const std::string& path, const std::vector<glm::dvec3>& points, const std::vector<Triangle>& triangles) {
  std::ofstream out(path);
  char line[128];
  for (const glm::dvec3& p : points) {
    // Written as float, as the STL holds them, so both files describe the same mesh.
    std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", double(float(p.x)), double(float(p.y)), double(float(p.z)));
    out << line;
  }
  for (const Triangle& t : triangles) out << "f " << t[0] + 1 << " " << t[1] + 1 << " " << t[2] + 1 << "\n";
}

// One glTF 2.0 primitive: float positions, uint32 indices, in one GLB buffer.
void write_glb(const std::string& path, const std::vector<glm::dvec3>& points, const std::vector<Triangle>& triangles) {
  std::string buffer;
  for (const glm::dvec3& p : points)
    for (int i = 0; i < 3; ++i) {
      const float v = float(p[i]);
      buffer.append(reinterpret_cast<const char*>(&v), 4);
    }
  const size_t point_bytes = buffer.size();
  buffer.append(reinterpret_cast<const char*>(triangles.data()), triangles.size() * sizeof(Triangle));
  std::string json = R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
                     R"("meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}],"buffers":[{"byteLength":)" +
                     std::to_string(buffer.size()) + R"(}],"bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":)" +
                     std::to_string(point_bytes) + R"(},{"buffer":0,"byteOffset":)" + std::to_string(point_bytes) +
                     R"(,"byteLength":)" + std::to_string(buffer.size() - point_bytes) +
                     R"(}],"accessors":[{"bufferView":0,"componentType":5126,"count":)" + std::to_string(points.size()) +
                     R"(,"type":"VEC3"},{"bufferView":1,"componentType":5125,"count":)" + std::to_string(3 * triangles.size()) +
                     R"(,"type":"SCALAR"}]})";
  while (json.size() % 4) json += ' ';
  const auto u32 = [](uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
  std::ofstream out(path, std::ios::binary);
  out << "glTF" << u32(2) << u32(uint32_t(12 + 8 + json.size() + 8 + buffer.size())) << u32(uint32_t(json.size())) << "JSON"
      << json << u32(uint32_t(buffer.size())) << std::string("BIN\0", 4) << buffer;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 6) {
    std::cerr << "usage: make_subdivided_mesh IN OUT.stl OUT.obj OUT.glb LEVELS\n";
    return 2;
  }
  try {
    const umbra::PolygonSoup soup = umbra::read_polygon_soup(argv[1]);
    const umbra::MergedPoints merged = umbra::merge_coincident_points(soup.points);
    std::vector<glm::dvec3> points = merged.positions;
    std::vector<Triangle> triangles;
    for (size_t f = 0; f < soup.polygon_count(); ++f) {
      std::vector<uint32_t> corners;
      for (uint32_t k = 0; k < soup.corner_count(f); ++k) corners.push_back(merged.vertex_of_point[soup.polygon(f)[k]]);
      umbra::triangulate_polygon(points, corners.data(), uint32_t(corners.size()), triangles);
    }
    for (int level = std::atoi(argv[5]); level > 0; --level) subdivide(points, triangles);
    write_stl(argv[2], points, triangles);
    write_obj(argv[3], points, triangles);
    write_glb(argv[4], points, triangles);
    std::cout << triangles.size() << " triangles, " << points.size() << " vertices\n";
    return 0;
  } catch (const umbra::InputError& e) {
    std::cerr << e.what() << "\n";
    return 1;
  }
}
