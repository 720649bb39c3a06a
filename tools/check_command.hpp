#pragma once

#include <string>
#include <vector>

namespace umbra {


// `umbra check`: 0 when every mesh is a closed, consistently oriented
// 2-manifold without self-intersections, 1 when one is not (or its repair
// failed), 2 when one could not be read or on a usage error.
int run_check_command(const std::vector<std::string>& args);

}  // namespace umbra
