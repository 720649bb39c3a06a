// Makes the meshes that bench/open_mesh_benchmark.sh renders, as OBJ files
// in OUT_DIR, each fitted into the box [-0.7, 0.7]^2 x [-0.8, 0.1] over the
// scenes' floor:
//   closed.obj       a bumpy torus of about 300,000 triangles: a closed 2-manifold
//   holes.obj        the same with 3 small holes (faces removed)
//   reversed.obj     the same with a patch of 588 faces wound the other way
//   fin.obj          the same with one non-manifold fin (a third face on one edge)
//   two.obj          two interpenetrating tori of half the triangles each
//   duplicates.obj   the same as closed.obj with a patch of 366 faces repeated
//   parts.obj        576 open tubes (no end caps), about 110,000 triangles
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

struct Mesh {
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<uint32_t, 3>> triangles;
};

constexpr double kTau = 6.283185307179586;

// n x m quads round a torus (radii 0.55 and 0.22 with bumps), centred at `c`,
// its axis turned by `tilt` radians about x.
Mesh bumpy_torus(int n, int m, std::array<double, 3> c, double tilt) {
  Mesh mesh;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      const double u = kTau * i / n, v = kTau * j / m;
      const double r = 0.22 * (1.0 + 0.12 * std::sin(7 * u) * std::sin(5 * v));
      const double x = (0.55 + r * std::cos(v)) * std::cos(u), y = (0.55 + r * std::cos(v)) * std::sin(u), z = r * std::sin(v);
      mesh.points.push_back({c[0] + x, c[1] + y * std::cos(tilt) - z * std::sin(tilt), c[2] + y * std::sin(tilt) + z * std::cos(tilt)});
    }
  const auto at = [&](int i, int j) { return uint32_t((i % n) * m + (j % m)); };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return mesh;
}

void append(Mesh& to, const Mesh& from) {
  const uint32_t offset = uint32_t(to.points.size());
  to.points.insert(to.points.end(), from.points.begin(), from.points.end());
  for (auto t : from.triangles) to.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
}

// An open tube (no caps) of `segments` x `rings` quads along a tilted axis.
Mesh tube(std::array<double, 3> base, double radius, double length, double tilt_x, double tilt_y, int segments, int rings) {
  Mesh mesh;
  for (int k = 0; k <= rings; ++k)
    for (int j = 0; j < segments; ++j) {
      const double a = kTau * j / segments, h = length * k / rings;
      double x = radius * std::cos(a), y = radius * std::sin(a), z = h;
      const double y1 = y * std::cos(tilt_x) - z * std::sin(tilt_x), z1 = y * std::sin(tilt_x) + z * std::cos(tilt_x);
      const double x2 = x * std::cos(tilt_y) + z1 * std::sin(tilt_y), z2 = -x * std::sin(tilt_y) + z1 * std::cos(tilt_y);
      mesh.points.push_back({base[0] + x2, base[1] + y1, base[2] + z2});
    }
  const auto at = [&](int k, int j) { return uint32_t(k * segments + (j % segments)); };
  for (int k = 0; k < rings; ++k)
    for (int j = 0; j < segments; ++j) {
      mesh.triangles.push_back({at(k, j), at(k, j + 1), at(k + 1, j + 1)});
      mesh.triangles.push_back({at(k, j), at(k + 1, j + 1), at(k + 1, j)});
    }
  return mesh;
}

void write(const std::string& path, const Mesh& mesh) {
  std::ofstream out(path);
  char line[128];
  for (const auto& p : mesh.points) {
    std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", p[0], p[1], p[2]);
    out << line;
  }
  for (const auto& t : mesh.triangles) out << "f " << t[0] + 1 << " " << t[1] + 1 << " " << t[2] + 1 << "\n";
  if (!out) throw std::runtime_error("cannot write " + path);
  std::cout << path << ": " << mesh.triangles.size() << " triangles\n";
}

// The faces of `mesh` whose first vertex lies within `radius` of point index `centre`.
std::vector<size_t> patch(const Mesh& mesh, uint32_t centre, double radius) {
  std::vector<size_t> faces;
  const auto& c = mesh.points[centre];
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& p = mesh.points[mesh.triangles[t][0]];
    const double dx = p[0] - c[0], dy = p[1] - c[1], dz = p[2] - c[2];
    if (dx * dx + dy * dy + dz * dz < radius * radius) faces.push_back(t);
  }
  return faces;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: make_mesh_variants OUT_DIR\n";
    return 2;
  }
  const std::string dir = argv[1];
  try {
    const int n = 500, m = 300;  // 300,000 triangles
    const Mesh closed = bumpy_torus(n, m, {0.0, 0.0, -0.45}, 0.5);
    write(dir + "/closed.obj", closed);

    Mesh holes = closed;
    std::vector<uint8_t> drop(closed.triangles.size(), 0);
    for (const uint32_t centre : {uint32_t(0), uint32_t(n * m / 3 + 40), uint32_t(2 * n * m / 3 + 170)})
      for (size_t t : patch(closed, centre, 0.006)) drop[t] = 1;
    holes.triangles.clear();
    for (size_t t = 0; t < closed.triangles.size(); ++t)
      if (!drop[t]) holes.triangles.push_back(closed.triangles[t]);
    write(dir + "/holes.obj", holes);

    Mesh reversed = closed;
    for (size_t t : patch(closed, uint32_t(n * m / 2 + 100), 0.05)) std::swap(reversed.triangles[t][1], reversed.triangles[t][2]);
    write(dir + "/reversed.obj", reversed);

    Mesh fin = closed;
    const auto edge = closed.triangles[0];
    fin.points.push_back({closed.points[edge[0]][0], closed.points[edge[0]][1], closed.points[edge[0]][2] + 0.05});
    fin.triangles.push_back({edge[0], edge[1], uint32_t(fin.points.size() - 1)});
    write(dir + "/fin.obj", fin);

    Mesh two = bumpy_torus(n / 2, m, {-0.15, 0.0, -0.45}, 0.5);
    append(two, bumpy_torus(n / 2, m, {0.2, 0.1, -0.4}, 1.2));
    write(dir + "/two.obj", two);

    Mesh duplicates = closed;
    for (size_t t : patch(closed, uint32_t(n * m / 4 + 7), 0.05)) duplicates.triangles.push_back(closed.triangles[t]);
    write(dir + "/duplicates.obj", duplicates);

    Mesh parts;
    for (int i = 0; i < 24; ++i)
      for (int j = 0; j < 24; ++j) {
        const double x = -0.69 + 1.38 * (i + 0.5) / 24, y = -0.69 + 1.38 * (j + 0.5) / 24;
        append(parts, tube({x, y, -0.8 + 0.1 * ((i * 7 + j * 3) % 5)}, 0.022, 0.35 + 0.05 * ((i + j) % 4),
                           0.3 * std::sin(i * 1.3), 0.3 * std::cos(j * 0.7), 24, 4));
      }
    write(dir + "/parts.obj", parts);
    return 0;
  } catch (const std::exception& e) {
    std::cerr << e.what() << "\n";
    return 1;
  }
}
