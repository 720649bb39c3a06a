#pragma once
// `umbra formats`: every mesh format umbra reads, from the formats' table
// (mesh_format.hpp): its extensions, how a file is told to be in it, what
// reads it, and whether this build does.

#include <string>
#include <vector>

namespace umbra {

// The table as `umbra formats` prints it.
std::string formats_table();
int run_formats_command(const std::vector<std::string>& argv);

}  // namespace umbra
