#pragma once
// The staged scene's statements after its mesh, made as values and written
// as scene text together: each value is set to what its text reads back as
// (numbers to 6 significant digits), and each statement's place in the scene
// to the line the text puts it on, so that the text --explain prints and
// --save-scene saves is the scene drawn, and no text is parsed on the way
// to a picture.

#include <string>

#include <glm/vec3.hpp>

#include "scene/scene.hpp"

namespace umbra {

class StageStatements {
 public:
  // Statements for `scene` (named scene.path), the first on line `first_line`.
  StageStatements(Scene& scene, int first_line) : scene_(scene), line_(first_line) {}

  // A number or point as the text writes it, and as it reads back.
  static std::string number(double v);
  static std::string point(const glm::dvec3& p);
  static double written(double v);
  static glm::dvec3 written(const glm::dvec3& p);

  void light(const glm::dvec3& position, const glm::dvec3& color);
  void headlight(const glm::dvec3& intensity);
  void hemisphere(const glm::dvec3& sky, const glm::dvec3& ground);  // up +z
  void soft_tone();
  // The default material (the model's, where its file gives none): ambient and diffuse `color`.
  void model_color(const glm::dvec3& color);
  // The floor's material, "floor": a colour (ambient and diffuse) or a shadow catcher.
  void floor_material(const glm::dvec3& color, bool shadow_catcher);
  // A level square at height z, as the scene format's floor statement makes it, of material "floor".
  void floor(double z, double centre_x, double centre_y, double half_size);
  void camera(const Camera& camera);  // up +z
  void background(const Background& background);
  void size(int width, int height);
  void antialias(int samples, bool all);

  const std::string& text() const { return text_; }

 private:
  FileLoc here() const { return {scene_.path, line_, 1}; }
  void add(const std::string& statement) { text_ += statement + "\n", ++line_; }

  Scene& scene_;
  int line_;
  std::string text_;
};

}  // namespace umbra
