#include "mesh/check/self_intersection_removal.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <sstream>
#include <vector>

#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/boost/graph/helpers.h>

namespace umbra {
namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using repair::Point;
using Mesh = repair::SurfaceMesh;

// Gives each piece of a split face the triangle it was split from.
struct SplitVisitor : PMP::Corefinement::Default_visitor<Mesh> {
  Mesh::Property_map<Mesh::Face_index, SplitFrom> split_from;
  SplitFrom splitting;
  void before_subface_creations(Mesh::Face_index f, Mesh&) { splitting = split_from[f]; }
  void after_subface_created(Mesh::Face_index f, Mesh&) { split_from[f] = splitting; }
};

// Each connected component of a closed `mesh`: the signed volume it
// encloses, summed about one of its points so that a model far from the
// origin loses no digits to it, and the diagonal of its bounding box.
struct Part {
  double volume = 0.0;
  CGAL::Bbox_3 box;
};
std::vector<Part> parts_of(Mesh& mesh, Mesh::Property_map<Mesh::Face_index, std::size_t> component) {
  std::vector<Part> parts(PMP::connected_components(mesh, component));
  const Point origin = mesh.point(*mesh.vertices().begin());
  for (const Mesh::Face_index f : mesh.faces()) {
    std::array<CGAL::Vector_3<repair::Kernel>, 3> corner;
    size_t k = 0;
    for (const auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
      corner[k++] = mesh.point(v) - origin;
      parts[component[f]].box += mesh.point(v).bbox();
    }
    parts[component[f]].volume += CGAL::scalar_product(corner[0], CGAL::cross_product(corner[1], corner[2])) / 6.0;
  }
  return parts;
}

// Why the parts of `mesh` are not the overlapping solids that the
// autorefinement is sound for, or "": each part that crosses another must
// cross no face of its own (where a shell crosses itself, which side is
// inside is unclear, and the autorefinement can keep the wrong one) and be a
// solid of some thickness facing out (a sliver or a flat pocket is where its
// constructions fail).
std::string unsound_parts(const std::vector<Part>& parts, Mesh::Property_map<Mesh::Face_index, std::size_t> component,
                          const std::vector<FacePair>& crossing) {
  for (const auto& [f, g] : crossing) {
    if (component[f] == component[g]) return "a closed component crosses itself, where which side is inside is unclear";
    for (const std::size_t c : {component[f], component[g]}) {
      const CGAL::Bbox_3& box = parts[c].box;
      const double diagonal = std::hypot(box.xmax() - box.xmin(), box.ymax() - box.ymin(), box.zmax() - box.zmin());
      // A cube encloses 0.19 of its diagonal cubed; a plate a thousandth as
      // thick as wide about 2e-4.
      if (parts[c].volume <= 1e-6 * diagonal * diagonal * diagonal)
        return parts[c].volume < 0.0 ? "a closed component that crosses another faces inward"
                                     : "a closed component that crosses another is too thin to be a solid";
    }
  }
  return "";
}

// The total signed volume of the parts, the largest part's and all parts'
// summed.
struct Enclosed {
  double total = 0.0, largest = 0.0, all = 0.0;
};
Enclosed enclosed_by(const std::vector<Part>& parts) {
  Enclosed enclosed;
  for (const Part& part : parts) {
    enclosed.total += part.volume;
    enclosed.largest = std::max(enclosed.largest, std::abs(part.volume));
    enclosed.all += std::abs(part.volume);
  }
  return enclosed;
}

// The parts of `mesh`, with a component map that lives while they are used.
struct Parts {
  explicit Parts(Mesh& mesh) : owner(mesh), component(mesh.add_property_map<Mesh::Face_index, std::size_t>("f:removal_component", 0).first),
                      parts(parts_of(mesh, component)) {}
  ~Parts() { owner.remove_property_map(component); }
  Parts(const Parts&) = delete;
  Parts& operator=(const Parts&) = delete;

  Mesh& owner;
  Mesh::Property_map<Mesh::Face_index, std::size_t> component;
  std::vector<Part> parts;
};

std::string said(double x) {
  std::ostringstream out;
  out << x;
  return out.str();
}

}  // namespace

SelfIntersectionRemoval remove_self_intersections(Mesh& mesh, const std::vector<FacePair>& crossing) {
  if (mesh.is_empty() || !CGAL::is_closed(mesh)) return {false, "the surface is not closed"};
  Enclosed before;
  {
    const Parts parts(mesh);
    if (const std::string why = unsound_parts(parts.parts, parts.component, crossing); !why.empty()) return {false, why};
    before = enclosed_by(parts.parts);
  }
  Mesh refined = mesh;
  SplitVisitor visitor;
  visitor.split_from = refined.add_property_map<Mesh::Face_index, SplitFrom>(kSplitFromProperty).first;
  for (const Mesh::Face_index f : refined.faces()) {
    size_t k = 0;
    for (const auto v : CGAL::vertices_around_face(refined.halfedge(f), refined)) visitor.split_from[f][k++] = refined.point(v);
  }
  try {
    if (!PMP::experimental::autorefine_and_remove_self_intersections(refined, CGAL::parameters::visitor(visitor)))
      return {false, "CGAL's autorefinement could not remove them all"};
  } catch (const std::exception& e) {
    return {false, std::string("CGAL's autorefinement failed (") + e.what() + ")"};
  }
  refined.collect_garbage();
  if (refined.is_empty() || !CGAL::is_closed(refined)) return {false, "the surface CGAL's autorefinement gave is not closed"};
  if (PMP::does_self_intersect(refined)) return {false, "the surface CGAL's autorefinement gave still crosses itself"};
  // The union of the parts encloses at least the largest and at most all of
  // them; the bounds widened by a relative 1e-9 for the sums' rounding.
  const double enclosed = enclosed_by(Parts(refined).parts).total;
  if (enclosed < before.largest * (1.0 - 1e-9) || enclosed > before.all * (1.0 + 1e-9))
    return {false, "the surface CGAL's autorefinement gave encloses " + said(enclosed) + ", where the union of the parts encloses " +
                       said(before.largest) + " to " + said(before.all)};
  mesh = std::move(refined);
  return {true, ""};
}

}  // namespace umbra
