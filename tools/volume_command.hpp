#pragma once

#include <string>
#include <vector>

namespace umbra {


// `umbra volume`: writes one light's shadow volumes as an OBJ file with the
// vertices at infinity brought to a finite distance. Exit 0 written, 1 bad
// scene or unwritable output, 2 usage error.
int run_volume_command(const std::vector<std::string>& args);

}  // namespace umbra
