#include "mesh/input_error.hpp"

namespace umbra {

std::string FileLoc::str() const {
  std::string s = file;
  if (line > 0) s += ":" + std::to_string(line);
  if (line > 0 && column > 0) s += ":" + std::to_string(column);
  return s;
}

const char* input_problem_name(InputProblem problem) {
  switch (problem) {
    case InputProblem::kMalformed: return "malformed";
    case InputProblem::kUnreadable: return "unreadable";
    case InputProblem::kUnsupportedFormat: return "unsupported-format";
    case InputProblem::kEmpty: return "empty";
    case InputProblem::kNoFaces: return "no-faces";
  }
  return "malformed";
}

}  // namespace umbra
