#include "scene/up_axis.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

namespace umbra {

bool is_up_axis(const std::string& up) {
  return std::any_of(std::begin(kUpTurns), std::end(kUpTurns), [&](const UpTurn& t) { return up == t.up; });
}

const UpTurn& up_turn(const std::string& up) {
  for (const UpTurn& t : kUpTurns)
    if (up == t.up) return t;
  throw std::invalid_argument("not an up axis: " + up);
}

glm::dmat3 up_rotation(const std::string& up) {
  const UpTurn& t = up_turn(up);
  glm::dmat3 r(glm::rotate(glm::dmat4(1.0), glm::radians(t.degrees), t.axis));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r[i][j] = std::round(r[i][j]);
  return r;
}

std::string axis_name(const glm::dvec3& direction) {
  int axis = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(direction[k]) > std::abs(direction[axis])) axis = k;
  return std::string(direction[axis] < 0 ? "-" : "+") + "xyz"[axis];
}

}  // namespace umbra
