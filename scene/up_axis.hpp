#pragma once
// A mesh file's six possible up axes, and the turn that stands each up as
// the stage's +z: one table, which staging, the pose choice and --up read.

#include <string>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

namespace umbra {

// The turn that takes a file's axis `up` to +z, as the scene's `rotate`
// clause writes it (about `axis`, counter-clockwise, in degrees). The front
// of a +y-up model (+z) turns to -y, where the camera is.
struct UpTurn {
  const char* up;
  glm::dvec3 axis;
  double degrees;
};
inline constexpr UpTurn kUpTurns[] = {
    {"+z", {1, 0, 0}, 0}, {"-z", {1, 0, 0}, 180}, {"+y", {1, 0, 0}, 90},
    {"-y", {1, 0, 0}, -90}, {"+x", {0, 1, 0}, -90}, {"-x", {0, 1, 0}, 90},
};

// "+x", "-x", "+y", "-y", "+z" or "-z": the axis of the file that points up.
bool is_up_axis(const std::string& up);
// Its turn; std::invalid_argument for anything else.
const UpTurn& up_turn(const std::string& up);
// The turn as a matrix, rounded to whole numbers (every entry is -1, 0 or 1).
glm::dmat3 up_rotation(const std::string& up);
// The name of the file's axis `direction` (a signed unit axis), "+x" ... "-z".
std::string axis_name(const glm::dvec3& direction);

}  // namespace umbra
