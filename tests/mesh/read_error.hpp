#pragma once
// The message a mesh file's bytes get from the readers, for tests that
// assert it exactly.

#include <string>

#include "mesh/input_error.hpp"
#include "mesh/io/mesh_file.hpp"

namespace umbra::test {

// "FILE:LINE:COL: reason" (or "FILE: reason"), or "no error".
inline std::string read_error_of(const std::string& bytes, const std::string& path) {
  try {
    parse_polygon_soup(bytes, path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace umbra::test
