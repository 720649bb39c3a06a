#pragma once
// The mesh `umbra check --repair` works on: CGAL's Surface_mesh over the
// kernel with exact predicates (CGAL stays in mesh/check).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

namespace umbra::repair {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point>;

}  // namespace umbra::repair
