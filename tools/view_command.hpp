#pragma once

#include <string>
#include <vector>

namespace umbra {


// `umbra view`: the interactive program in a window. Exit 0 when the
// window is closed (or after --frames), 1 when the first scene is bad or no
// window can be opened, 2 on a usage error.
int run_view_command(const std::vector<std::string>& args);

}  // namespace umbra
