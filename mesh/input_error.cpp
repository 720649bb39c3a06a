#include "mesh/input_error.hpp"

namespace umbra {

std::string FileLoc::str() const {
  std::string s = file;
  if (line > 0) s += ":" + std::to_string(line);
  if (line > 0 && column > 0) s += ":" + std::to_string(column);
  return s;
}

}  // namespace umbra
