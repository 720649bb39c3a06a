#pragma once
// Small meshes built in the tests, each with a report the tests know exactly.

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "mesh/io/polygon_soup.hpp"

namespace umbra::test {

using Face = std::vector<uint32_t>;

inline PolygonSoup make_soup(const std::vector<glm::dvec3>& points, const std::vector<Face>& faces) {
  PolygonSoup soup;
  soup.path = "test.off";
  soup.format = "test";
  for (size_t i = 0; i < points.size(); ++i) soup.add_point(points[i], int(i) + 1);
  for (size_t f = 0; f < faces.size(); ++f) {
    soup.corners.insert(soup.corners.end(), faces[f].begin(), faces[f].end());
    soup.end_polygon(int(points.size() + f) + 1);
  }
  return soup;
}

// `soup` with every polygon fanned into triangles: for what takes triangles only.
inline PolygonSoup triangulated(const PolygonSoup& soup) {
  PolygonSoup out = soup;
  out.corners.clear();
  out.polygon_starts = {0};
  out.polygon_lines.clear();
  for (size_t f = 0; f < soup.polygon_count(); ++f)
    for (uint32_t k = 1; k + 1 < soup.corner_count(f); ++k) {
      out.corners.insert(out.corners.end(), {soup.polygon(f)[0], soup.polygon(f)[k], soup.polygon(f)[k + 1]});
      out.end_polygon(soup.polygon_line(f));
    }
  return out;
}

// Appends `b` to `a` (indices shifted), as two components of one file.
inline PolygonSoup combine(const PolygonSoup& a, const PolygonSoup& b) {
  PolygonSoup soup = a;
  const uint32_t offset = uint32_t(a.points.size());
  for (size_t i = 0; i < b.points.size(); ++i) soup.add_point(b.points[i], b.point_line(i));
  for (size_t f = 0; f < b.polygon_count(); ++f) {
    for (uint32_t k = 0; k < b.corner_count(f); ++k) soup.corners.push_back(b.polygon(f)[k] + offset);
    soup.end_polygon(b.polygon_line(f));
  }
  return soup;
}

// Vertices 0..3 at the origin and the unit axes; faces point outward.
inline PolygonSoup tetrahedron(glm::dvec3 at = glm::dvec3(0.0), double size = 1.0) {
  return make_soup({at, at + glm::dvec3(size, 0, 0), at + glm::dvec3(0, size, 0), at + glm::dvec3(0, 0, size)},
                   {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}});
}

// The box [lo, hi] as 6 outward quads; vertex i has x = hi.x when i & 1,
// y = hi.y when i & 2, z = hi.z when i & 4.
inline PolygonSoup box_quads(glm::dvec3 lo, glm::dvec3 hi) {
  std::vector<glm::dvec3> points;
  for (int i = 0; i < 8; ++i) points.push_back({i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z});
  return make_soup(points, {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}});
}

// The same box as 12 outward triangles: quad q becomes triangles 2q and 2q+1.
inline PolygonSoup box_triangles(glm::dvec3 lo, glm::dvec3 hi) {
  const PolygonSoup quads = box_quads(lo, hi);
  std::vector<Face> faces;
  for (size_t q = 0; q < quads.polygon_count(); ++q) {
    const uint32_t* v = quads.polygon(q);
    faces.push_back({v[0], v[1], v[2]});
    faces.push_back({v[0], v[2], v[3]});
  }
  return make_soup(quads.points, faces);
}

inline PolygonSoup unit_cube() { return box_triangles(glm::dvec3(0.0), glm::dvec3(1.0)); }

// The volume its faces enclose, summed about `about` (triangles and convex polygons as fans).
inline double signed_volume(const PolygonSoup& soup, const glm::dvec3& about) {
  double volume = 0.0;
  for (size_t f = 0; f < soup.polygon_count(); ++f) {
    const uint32_t* v = soup.polygon(f);
    for (uint32_t k = 1; k + 1 < soup.corner_count(f); ++k) {
      const glm::dvec3 a = soup.points[v[0]] - about, b = soup.points[v[k]] - about, c = soup.points[v[k + 1]] - about;
      volume += a.x * (b.y * c.z - b.z * c.y) - a.y * (b.x * c.z - b.z * c.x) + a.z * (b.x * c.y - b.y * c.x);
    }
  }
  return volume / 6.0;
}

// The area of its faces (triangles and convex polygons as fans).
inline double area(const PolygonSoup& soup) {
  double sum = 0.0;
  for (size_t f = 0; f < soup.polygon_count(); ++f) {
    const uint32_t* v = soup.polygon(f);
    for (uint32_t k = 1; k + 1 < soup.corner_count(f); ++k)
      sum += 0.5 * glm::length(glm::cross(soup.points[v[k]] - soup.points[v[0]], soup.points[v[k + 1]] - soup.points[v[0]]));
  }
  return sum;
}

inline PolygonSoup reversed(PolygonSoup soup, std::vector<size_t> faces) {
  for (size_t f : faces) std::reverse(soup.corners.begin() + soup.polygon_starts[f], soup.corners.begin() + soup.polygon_starts[f + 1]);
  return soup;
}

inline PolygonSoup all_reversed(PolygonSoup soup) {
  for (size_t f = 0; f < soup.polygon_count(); ++f) soup = reversed(std::move(soup), {f});
  return soup;
}

// A hollow solid, correctly oriented: the box [0, 3]^3 facing out, and the
// cavity [1, 2]^3 whose shell faces into the cavity. Its volume is 27 - 1.
inline PolygonSoup hollow_cube() {
  return combine(box_triangles(glm::dvec3(0.0), glm::dvec3(3.0)), all_reversed(box_triangles(glm::dvec3(1.0), glm::dvec3(2.0))));
}

// The prism over `polygon` (in the xy plane, counter-clockwise where it is
// simple) from z0 to z1: each cap a fan of triangles from the polygon's first
// corner, each side a quad, outward where the polygon turns counter-clockwise.
// A self-crossing polygon gives a closed prism whose walls cross, with its
// clockwise lobes turned inside out.
inline PolygonSoup prism(const std::vector<glm::dvec2>& polygon, double z0, double z1) {
  const uint32_t n = uint32_t(polygon.size());
  std::vector<glm::dvec3> points;
  for (const double z : {z0, z1})
    for (const glm::dvec2& p : polygon) points.emplace_back(p.x, p.y, z);
  std::vector<Face> faces;
  for (uint32_t k = 1; k + 1 < n; ++k) {
    faces.push_back({0, k + 1, k});          // bottom, facing -z
    faces.push_back({n, n + k, n + k + 1});  // top, facing +z
  }
  for (uint32_t k = 0; k < n; ++k) faces.push_back({k, (k + 1) % n, n + (k + 1) % n, n + k});
  return make_soup(points, faces);
}

// An L-shaped prism and a box that pokes out of its inner wall into the
// notch: two closed, outward shells that cross, neither inside the other.
inline PolygonSoup box_through_l_prism() {
  return combine(prism({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, 0.0, 1.0),
                 box_triangles(glm::dvec3(1.2, 0.5, 0.2), glm::dvec3(1.8, 1.5, 0.8)));
}

// A prism over a bow tie with a large lobe (counter-clockwise) and a small
// one (clockwise, so inside out): one closed shell whose walls cross.
inline PolygonSoup bow_tie_prism() { return prism({{0, 0}, {4, 2}, {4, 1.4}, {0, 2}}, 0.0, 1.0); }

inline PolygonSoup without_faces(const PolygonSoup& soup, std::vector<size_t> drop) {
  std::vector<Face> faces;
  for (size_t f = 0; f < soup.polygon_count(); ++f)
    if (std::find(drop.begin(), drop.end(), f) == drop.end()) faces.emplace_back(soup.polygon(f), soup.polygon(f) + soup.corner_count(f));
  return make_soup(soup.points, faces);
}

// A torus of n x m quads (tube radius r around a circle of radius R in the xy plane), outward.
inline PolygonSoup quad_torus(int n, int m, double R = 2.0, double r = 0.5) {
  std::vector<glm::dvec3> points;
  std::vector<Face> faces;
  const double tau = 6.283185307179586;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      const double u = tau * i / n, v = tau * j / m;
      points.push_back({(R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v)});
    }
  const auto at = [&](int i, int j) { return uint32_t(((i + n) % n) * m + (j + m) % m); };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) faces.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
  return make_soup(points, faces);
}

// The octahedron with vertices at +-1 on each axis, outward.
inline PolygonSoup octahedron() {
  return make_soup({{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}},
                   {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}});
}

// A unit sphere of `rings` bands (an even number puts a ring on the equator)
// and `segments` meridians: triangles at the poles, quads between, outward.
inline PolygonSoup uv_sphere(int rings, int segments) {
  const double pi = 3.141592653589793;
  std::vector<glm::dvec3> points = {{0, 0, 1}, {0, 0, -1}};
  for (int i = 1; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const double polar = pi * i / rings, azimuth = 2 * pi * j / segments;
      points.push_back({std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth), std::cos(polar)});
    }
  const auto at = [&](int ring, int j) { return uint32_t(2 + (ring - 1) * segments + (j + segments) % segments); };
  std::vector<Face> faces;
  for (int j = 0; j < segments; ++j) {
    faces.push_back({0, at(1, j), at(1, j + 1)});
    for (int i = 1; i + 1 < rings; ++i) faces.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
    faces.push_back({1, at(rings - 1, j + 1), at(rings - 1, j)});
  }
  return make_soup(points, faces);
}

// A cylinder of radius 1 round the z axis from z = -1 to 1: `segments`
// sides, each cut into `stacks` quads, and each cap a fan of triangles from
// its first corner; outward.
inline PolygonSoup cylinder(int segments, int stacks) {
  const double tau = 6.283185307179586;
  std::vector<glm::dvec3> points;
  for (int i = 0; i <= stacks; ++i)
    for (int j = 0; j < segments; ++j)
      points.push_back({std::cos(tau * j / segments), std::sin(tau * j / segments), -1.0 + 2.0 * i / stacks});
  const auto at = [&](int i, int j) { return uint32_t(i * segments + (j + segments) % segments); };
  std::vector<Face> faces;
  for (int j = 1; j + 1 < segments; ++j) {
    faces.push_back({at(0, 0), at(0, j + 1), at(0, j)});                  // bottom, facing -z
    faces.push_back({at(stacks, 0), at(stacks, j), at(stacks, j + 1)});  // top, facing +z
  }
  for (int i = 0; i < stacks; ++i)
    for (int j = 0; j < segments; ++j) faces.push_back({at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j)});
  return make_soup(points, faces);
}

// A plate as CAD tools tessellate a printer's bed: 300 x 300 x 6, its top a
// flat face at z = 0 fanned from one corner, a shallow bevel round it
// (falling 0.3 over 2, 8.5 degrees) cut into `segments` quads a side, walls
// fanned from their lower corners, and a bottom; closed and outward.
inline PolygonSoup bevelled_plate(uint32_t segments) {
  std::vector<glm::dvec3> points;
  // A square ring of half-size h at height z, counter-clockwise seen from
  // above from (-h, -h), `segments` points a side; its first point's index.
  const auto ring = [&](double h, double z) {
    const uint32_t first = uint32_t(points.size());
    const glm::dvec2 corners[4] = {{-h, -h}, {h, -h}, {h, h}, {-h, h}};
    for (int side = 0; side < 4; ++side)
      for (uint32_t k = 0; k < segments; ++k) {
        const glm::dvec2 p = corners[side] + (corners[(side + 1) % 4] - corners[side]) * (double(k) / segments);
        points.emplace_back(p.x, p.y, z);
      }
    return first;
  };
  const uint32_t n = 4 * segments, top = ring(148.0, 0.0), edge = ring(150.0, -0.3), low = uint32_t(points.size());
  for (const glm::dvec2 c : {glm::dvec2(-150, -150), glm::dvec2(150, -150), glm::dvec2(150, 150), glm::dvec2(-150, 150)})
    points.emplace_back(c.x, c.y, -6.0);
  std::vector<Face> faces;
  for (uint32_t k = 1; k + 1 < n; ++k) faces.push_back({top, top + k, top + k + 1});
  for (uint32_t k = 0; k < n; ++k) faces.push_back({edge + k, edge + (k + 1) % n, top + (k + 1) % n, top + k});
  for (uint32_t side = 0; side < 4; ++side) {
    const uint32_t a = low + side, b = low + (side + 1) % 4;
    faces.push_back({a, b, edge + (side + 1) * segments % n});
    for (uint32_t k = segments; k > 0; --k) faces.push_back({a, edge + (side * segments + k) % n, edge + side * segments + k - 1});
  }
  faces.push_back({low, low + 3, low + 2});
  faces.push_back({low, low + 2, low + 1});
  return make_soup(points, faces);
}

// A Moebius strip of n quads: one border loop, not orientable.
inline PolygonSoup moebius_strip(int n) {
  std::vector<glm::dvec3> points;
  const double tau = 6.283185307179586;
  for (int i = 0; i < n; ++i) {
    const double u = tau * i / n;
    for (double s : {-0.3, 0.3}) {
      const double w = s * std::cos(u / 2);
      points.push_back({(1 + w) * std::cos(u), (1 + w) * std::sin(u), s * std::sin(u / 2)});
    }
  }
  std::vector<Face> faces;
  for (int i = 0; i < n; ++i) {
    const uint32_t a = uint32_t(2 * i), b = a + 1;
    // The last quad joins the strip's end to its start with a half twist.
    const uint32_t c = i + 1 < n ? a + 2 : 1, d = i + 1 < n ? a + 3 : 0;
    faces.push_back({a, c, d, b});
  }
  return make_soup(points, faces);
}

// The soup as OBJ text, points and polygons in order.
inline std::string obj_text(const PolygonSoup& soup) {
  std::ostringstream out;
  out.precision(17);
  for (const glm::dvec3& p : soup.points) out << "v " << p.x << " " << p.y << " " << p.z << "\n";
  for (size_t f = 0; f < soup.polygon_count(); ++f) {
    out << "f";
    for (uint32_t k = 0; k < soup.corner_count(f); ++k) out << " " << soup.polygon(f)[k] + 1;
    out << "\n";
  }
  return out.str();
}

// A horn torus: a ring of quads between two circles, each circle fanned to
// the one centre point, so that the centre is pinched between the top fan and
// the bottom fan of one component. Every edge has two faces, which agree.
inline PolygonSoup horn_torus(uint32_t n) {
  std::vector<glm::dvec3> points{glm::dvec3(0.0)};
  std::vector<Face> faces;
  for (uint32_t i = 0; i < n; ++i) {
    const double a = 2.0 * M_PI * i / n;
    points.push_back({std::cos(a), std::sin(a), 0.5});
    points.push_back({std::cos(a), std::sin(a), -0.5});
  }
  for (uint32_t i = 0; i < n; ++i) {
    const uint32_t top = 1 + 2 * i, bottom = top + 1, next_top = 1 + 2 * ((i + 1) % n), next_bottom = next_top + 1;
    faces.push_back({0, top, next_top});
    faces.push_back({next_top, top, bottom, next_bottom});
    faces.push_back({0, next_bottom, bottom});
  }
  return make_soup(points, faces);
}

// The lower half (z <= 0) of a unit sphere of `rings` x `segments` quads: a
// bowl, open at its rim.
inline PolygonSoup bowl(int rings, int segments) {
  std::vector<glm::dvec3> points{{0, 0, -1}};
  const double pi = 3.141592653589793;
  for (int i = 1; i <= rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const double polar = pi - 0.5 * pi * i / rings, azimuth = 2 * pi * j / segments;
      points.push_back({std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth), std::cos(polar)});
    }
  const auto at = [segments](int i, int j) { return uint32_t(1 + (i - 1) * segments + (j % segments)); };
  std::vector<Face> faces;
  for (int j = 0; j < segments; ++j) faces.push_back({0, at(1, j + 1), at(1, j)});
  for (int i = 1; i < rings; ++i)
    for (int j = 0; j < segments; ++j) faces.push_back({at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j)});
  return make_soup(points, faces);
}

}  // namespace umbra::test
