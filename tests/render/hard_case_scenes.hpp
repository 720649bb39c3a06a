#pragma once
// Building blocks for the hard-case and property tests: a floor, boxes as OBJ
// text, and mesh files written to a temporary folder.

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <unistd.h>

#include <glm/vec3.hpp>

namespace umbra::test {

// The floor of the scenes: the square z = -1 of the cube [-1, 1]^3, two triangles.
inline std::string floor_text() { return "triangle -1 -1 -1  1 -1 -1  1 1 -1\ntriangle -1 -1 -1  1 1 -1  -1 1 -1\n"; }

// The box [lo, hi] as OBJ, faces counter-clockwise seen from outside; its
// vertex numbers start after `first` earlier vertices.
inline std::string box_obj(const glm::dvec3& lo, const glm::dvec3& hi, int first = 0) {
  std::ostringstream obj;
  obj.precision(17);
  for (const double z : {lo.z, hi.z})
    obj << "v " << lo.x << " " << lo.y << " " << z << "\nv " << hi.x << " " << lo.y << " " << z << "\nv " << hi.x << " " << hi.y
        << " " << z << "\nv " << lo.x << " " << hi.y << " " << z << "\n";
  static const int faces[12][3] = {{1, 4, 3}, {1, 3, 2}, {5, 6, 7}, {5, 7, 8}, {1, 2, 6}, {1, 6, 5},
                                   {2, 3, 7}, {2, 7, 6}, {3, 4, 8}, {3, 8, 7}, {4, 1, 5}, {4, 5, 8}};
  for (const auto& f : faces) obj << "f " << f[0] + first << " " << f[1] + first << " " << f[2] + first << "\n";
  return obj.str();
}

// The box [lo, hi]^2 x [z0, z1].
inline std::string box_obj(double lo, double hi, double z0, double z1, int first = 0) {
  return box_obj(glm::dvec3(lo, lo, z0), glm::dvec3(hi, hi, z1), first);
}

// The same box with its top made of four triangles round a centre vertex
// raised by `bump` (which may be negative).
inline std::string fan_top_box_obj(double lo, double hi, double z0, double z1, double bump) {
  std::ostringstream obj;
  obj.precision(17);
  for (const double z : {z0, z1})
    obj << "v " << lo << " " << lo << " " << z << "\nv " << hi << " " << lo << " " << z << "\nv " << hi << " " << hi
        << " " << z << "\nv " << lo << " " << hi << " " << z << "\n";
  obj << "v " << 0.5 * (lo + hi) << " " << 0.5 * (lo + hi) << " " << z1 + bump << "\n";
  obj << "f 1 4 3\nf 1 3 2\nf 5 6 9\nf 6 7 9\nf 7 8 9\nf 8 5 9\nf 1 2 6\nf 1 6 5\nf 2 3 7\nf 2 7 6\nf 3 4 8\n"
         "f 3 8 7\nf 4 1 5\nf 4 5 8\n";
  return obj.str();
}

// The whole of a text file.
inline std::string read_file(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// This process's temporary folder for the mesh files its tests write (CTest
// runs tests in parallel processes), removed when the process exits.
inline const std::filesystem::path& process_mesh_folder() {
  struct Folder {
    std::filesystem::path path =
        std::filesystem::temp_directory_path() / ("umbra-test-meshes-" + std::to_string(::getpid()));
    Folder() { std::filesystem::create_directories(path); }
    ~Folder() {
      std::error_code ignored;
      std::filesystem::remove_all(path, ignored);
    }
  };
  static const Folder folder;
  return folder.path;
}

// Writes `text` to a file named `name` in the process's folder; returns its path.
inline std::string write_mesh(const std::string& name, const std::string& text) {
  const std::filesystem::path path = process_mesh_folder() / name;
  std::ofstream(path) << text;
  return path.string();
}

}  // namespace umbra::test
