#include "scene/motion.hpp"

#include <stdexcept>

#include "scene/scene.hpp"

namespace umbra {

const char* turning_name(Turning turning) {
  switch (turning) {
    case Turning::kNone: return "none";
    case Turning::kModel: return "model";
    case Turning::kLight: return "light";
  }
  return "none";
}

bool parse_turning(const std::string& word, Turning& turning) {
  for (const Turning t : {Turning::kModel, Turning::kLight})
    if (word == turning_name(t)) return turning = t, true;
  return false;
}

Shot shot_of(const Scene& scene) {
  Shot shot{scene.camera, {}};
  for (const Light& light : scene.lights) shot.lights.push_back(light.position);
  return shot;
}

void place_shot(Scene& scene, const Shot& shot) {
  if (shot.lights.size() != scene.lights.size()) throw std::logic_error("a shot's lights are not the scene's");
  scene.camera = shot.camera;
  for (size_t i = 0; i < shot.lights.size(); ++i) scene.lights[i].position = shot.lights[i];
}

double frame_turn_deg(int index, int frames) { return 360.0 * index / frames; }

std::vector<Shot> motion_shots(const Scene& scene, Turning turning, int frames) {
  const Shot first = shot_of(scene);
  std::vector<Shot> shots;
  for (int i = 0; i < frames; ++i) {
    Shot shot = first;
    const double turn = frame_turn_deg(i, frames);
    if (turning == Turning::kModel) {
      // The model turning by `turn` under a still studio is, in the model's
      // own coordinates, the studio turning by -turn about it. The up
      // vector is a direction; turning it as a point about the z axis is
      // the same linear map.
      Camera& c = shot.camera;
      c.eye = rotated_about_z(c.eye, -turn), c.target = rotated_about_z(c.target, -turn), c.up = rotated_about_z(c.up, -turn);
      for (glm::dvec3& light : shot.lights) light = rotated_about_z(light, -turn);
    } else if (turning == Turning::kLight) {
      for (glm::dvec3& light : shot.lights) light = rotated_about_z(light, turn);
    }
    shots.push_back(std::move(shot));
  }
  return shots;
}

}  // namespace umbra
