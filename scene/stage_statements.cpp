#include "scene/stage_statements.hpp"

#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

namespace umbra {

std::string StageStatements::number(double v) {
  std::ostringstream s;
  s << std::setprecision(6) << (std::abs(v) < 1e-9 ? 0.0 : v);
  return s.str();
}

std::string StageStatements::point(const glm::dvec3& p) { return number(p.x) + " " + number(p.y) + " " + number(p.z); }

double StageStatements::written(double v) { return std::stod(number(v)); }

glm::dvec3 StageStatements::written(const glm::dvec3& p) { return {written(p.x), written(p.y), written(p.z)}; }

void StageStatements::light(const glm::dvec3& position, const glm::dvec3& color) {
  Light light;
  light.position = written(position), light.color = written(color), light.ambient = glm::dvec3(0.0), light.where = here();
  scene_.lights.push_back(light);
  add("light " + point(position) + " color " + point(color) + " ambient 0 0 0");
}

void StageStatements::headlight(const glm::dvec3& intensity) {
  scene_.fill.headlight = written(intensity);
  add("headlight " + point(intensity));
}

void StageStatements::hemisphere(const glm::dvec3& sky, const glm::dvec3& ground) {
  scene_.fill.sky = written(sky), scene_.fill.ground = written(ground), scene_.fill.up = {0.0, 0.0, 1.0};
  add("hemisphere sky " + point(sky) + " ground " + point(ground) + " up 0 0 1");
}

void StageStatements::soft_tone() {
  scene_.tone = ToneCurve::kSoft;
  add("tone soft");
}

void StageStatements::model_color(const glm::dvec3& color) {
  Material& m = scene_.materials.at(0);
  m = Material{};
  m.name = "default", m.ambient = m.diffuse = written(color);
  add("material default ambient " + point(color) + " diffuse " + point(color));
}

void StageStatements::floor_material(const glm::dvec3& color, bool shadow_catcher) {
  Material m;
  m.name = "floor";
  if (shadow_catcher) {
    m.shadow_catcher = true;
    add("material floor shadow-catcher");
  } else {
    m.ambient = m.diffuse = written(color);
    add("material floor ambient " + point(color) + " diffuse " + point(color));
  }
  scene_.materials.push_back(m);
}

void StageStatements::floor(double z, double centre_x, double centre_y, double half_size) {
  const double h = written(z), x = written(centre_x), y = written(centre_y), s = written(half_size);
  int material = 0;
  for (size_t i = 1; i < scene_.materials.size(); ++i)
    if (scene_.materials[i].name == "floor") material = int(i);
  // Wound as the scene format's floor statement winds them.
  const glm::dvec3 a(x - s, y - s, h), b(x + s, y - s, h), c(x + s, y + s, h), d(x - s, y + s, h);
  scene_.triangles.push_back({a, b, c, material, here()});
  scene_.triangles.push_back({a, c, d, material, here()});
  add("floor " + number(z) + " centre " + number(centre_x) + " " + number(centre_y) + " size " + number(half_size) + " material floor");
}

void StageStatements::camera(const Camera& c) {
  scene_.camera = Camera{written(c.eye), written(c.target), {0.0, 0.0, 1.0}};
  if (c.orthographic()) scene_.camera.ortho_height = written(c.ortho_height);  // its fovy unwritten, the default
  else scene_.camera.fovy_deg = written(c.fovy_deg);
  scene_.camera_from = here();
  add("camera eye " + point(c.eye) + " target " + point(c.target) + " up 0 0 1 " +
      (c.orthographic() ? "orthographic " + number(c.ortho_height) : "fovy " + number(c.fovy_deg)));
}

void StageStatements::background(const Background& background) {
  scene_.background = background.transparent ? Background{glm::dvec3(0.0), true} : Background{written(background.color), false};
  add(background.transparent ? std::string("background transparent") : "background " + point(background.color));
}

void StageStatements::size(int width, int height) {
  scene_.size = {width, height};
  add("size " + std::to_string(width) + " " + std::to_string(height));
}

void StageStatements::antialias(int samples, bool all) {
  scene_.antialias = samples, scene_.antialias_all = all;
  add("antialias " + std::to_string(samples) + (all ? " all" : ""));
}

}  // namespace umbra
