#pragma once
// A scene in motion, frame by frame: a turntable (the model turning about
// the z axis under a studio that holds still) or a light orbiting the
// model. Each frame is a Shot: where the camera stands and where the lights
// are, in the scene's coordinates. The surfaces never move, so a frame
// costs only its view and its lights' volumes.

#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "scene/camera.hpp"

namespace umbra {

struct Scene;

// What turns, a full turn over the frames: nothing; the model, about the z
// axis (a turntable: it turns counter-clockwise seen from above, and the
// camera, lights and floor hold still); or every light, about the z axis
// as --light-angle turns them (the camera and the model hold still).
enum class Turning { kNone, kModel, kLight };
// "model" or "light"; none for another word.
const char* turning_name(Turning turning);
bool parse_turning(const std::string& word, Turning& turning);

// Where one picture is taken from and lit from: the camera, and each
// light's position, in the scene's order.
struct Shot {
  Camera camera;
  std::vector<glm::dvec3> lights;
  bool operator==(const Shot&) const = default;
};
// The scene's own shot.
Shot shot_of(const Scene& scene);
// `scene` with its camera and lights where `shot` puts them (as many lights
// as the scene has: a shot made of it).
void place_shot(Scene& scene, const Shot& shot);

// The degrees frame `index` of `frames` turns by: 360 index / frames.
double frame_turn_deg(int index, int frames);

// `frames` shots of `scene`, frame 0 its own: the model turning (in the
// scene's coordinates, the camera and lights turning the other way about
// the z axis, so that the studio holds still about the model), or the
// lights orbiting, by frame_turn_deg each.
std::vector<Shot> motion_shots(const Scene& scene, Turning turning, int frames);

}  // namespace umbra
