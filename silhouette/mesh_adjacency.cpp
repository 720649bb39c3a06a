#include "silhouette/mesh_adjacency.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include <glm/geometric.hpp>

namespace umbra {
namespace {

// A generous bound on the rounding of n . x - offset against the exact
// orient3d(a, b, c, x): n and offset carry a few roundings each of sizes
// |b-a||c-a| and |n||a|, the evaluation a few more of |n||x|. 64 units in the
// last place of those magnitudes covers them all several times over; inside
// the bound the exact predicate decides.
constexpr double kRelativeError = 64.0 * std::numeric_limits<double>::epsilon();

float rounded_up(double x) { return std::nextafter(float(x), std::numeric_limits<float>::infinity()); }

}  // namespace

MeshAdjacency build_mesh_adjacency(const HalfEdgeMesh& mesh) {
  MeshAdjacency adjacency;
  adjacency.positions.reserve(mesh.n_vertices());
  for (const auto v : mesh.vertices()) {
    const auto& p = mesh.point(v);
    adjacency.positions.emplace_back(p[0], p[1], p[2]);
  }
  adjacency.triangles.reserve(mesh.n_faces());
  adjacency.planes.reserve(mesh.n_faces());
  for (const auto f : mesh.faces()) {
    std::array<uint32_t, 3> tri{};
    int k = 0;
    for (const auto v : mesh.fv_range(f)) tri[size_t(k++)] = uint32_t(v.idx());
    adjacency.triangles.push_back(tri);
    const glm::dvec3& a = adjacency.positions[tri[0]];
    const glm::dvec3 ab = adjacency.positions[tri[1]] - a, ac = adjacency.positions[tri[2]] - a;
    const glm::dvec3 n = glm::cross(ab, ac);
    const double reach = std::max({glm::length(a), glm::length(adjacency.positions[tri[1]]),
                                   glm::length(adjacency.positions[tri[2]])});
    const double scale = kRelativeError * glm::length(ab) * glm::length(ac);
    adjacency.planes.push_back({n, glm::dot(n, a), rounded_up(scale), rounded_up(scale * reach)});
  }
  adjacency.edge_faces.reserve(mesh.n_edges());
  adjacency.edge_vertices.reserve(mesh.n_edges());
  for (const auto e : mesh.edges()) {
    const auto h = mesh.halfedge_handle(e, 0);
    const auto opposite = mesh.opposite_halfedge_handle(h);
    if (mesh.is_boundary(h) || mesh.is_boundary(opposite))
      throw std::invalid_argument("build_mesh_adjacency needs a closed mesh");
    adjacency.edge_faces.push_back({uint32_t(mesh.face_handle(h).idx()), uint32_t(mesh.face_handle(opposite).idx())});
    adjacency.edge_vertices.push_back({uint32_t(mesh.from_vertex_handle(h).idx()), uint32_t(mesh.to_vertex_handle(h).idx())});
  }
  return adjacency;
}

}  // namespace umbra
