#pragma once

#include <string>
#include <vector>

namespace umbra {


// `umbra render`: returns the process exit status (0 written, 1 bad input or
// failure, 2 usage error). Messages go to stderr, the plan to stdout.
int run_render_command(const std::vector<std::string>& args);

}  // namespace umbra
