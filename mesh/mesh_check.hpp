#pragma once
// `umbra check`'s analysis: is a mesh a closed, consistently oriented
// 2-manifold without self-intersections, and if not, exactly why and where.

#include "mesh/mesh_report.hpp"
#include "mesh/polygon_soup.hpp"

namespace umbra {

struct CheckOptions {
  // The search for self-intersections stops after this long and says so;
  // 0 skips it.
  double self_intersection_seconds = 60.0;
};

MeshReport check_mesh(const PolygonSoup& soup, const CheckOptions& options = {});

}  // namespace umbra
