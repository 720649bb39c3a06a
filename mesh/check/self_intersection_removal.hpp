#pragma once
// Removing where a closed triangle mesh crosses itself, for `umbra check
// --repair`: parts that overlap (a model built of shells pushed into one
// another, as many are) become the one surface that bounds their union.
// CGAL 5.5's experimental autorefinement (Polygon Mesh Processing's
// `autorefine_and_remove_self_intersections`) splits the faces along every
// crossing and drops the patches that lie inside.

#include <array>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "mesh/check/repair_mesh_type.hpp"

namespace umbra {

// The face property that names, for each face the removal split, the
// triangle it was split from (its corners' points), so that the repair can
// carry the file's attributes into the pieces; absent when nothing was split.
constexpr const char* kSplitFromProperty = "f:split_from";
using SplitFrom = std::array<repair::Point, 3>;

struct SelfIntersectionRemoval {
  bool removed = false;
  // Why not, when not removed: "CGAL's autorefinement left some", "the
  // surface it gave encloses 1.2e-05 where the parts enclose 8.7e+06 to
  // 8.7e+06"...
  std::string why_not;
};

// Replaces `mesh` (closed, consistently oriented, each closed component
// facing out where that is known) with its autorefined surface, when that
// surface is closed, crosses nowhere and is sound: it must enclose no less
// than the largest of the parts and no more than all of them together,
// which the union of overlapping parts does. Otherwise leaves `mesh` as it
// is and says why: the autorefinement is experimental, and on a shell that
// crosses only itself it can keep the wrong side.
// `crossing`: the pairs of its faces that cross, as the repair's search
// found them (find_self_intersections).
using FacePair = std::pair<repair::SurfaceMesh::Face_index, repair::SurfaceMesh::Face_index>;
SelfIntersectionRemoval remove_self_intersections(repair::SurfaceMesh& mesh, const std::vector<FacePair>& crossing);

}  // namespace umbra
