#include "render/headless_context.hpp"

#include <cstdlib>
#include <stdexcept>

#include "mesh/word_list.hpp"
#include "render/gl_functions.hpp"
#include "render/headless_surface.hpp"

namespace umbra {

std::optional<HeadlessGl> headless_gl_from_name(std::string_view name) {
  for (const HeadlessGlRow& row : kHeadlessGlTable)
    if (name == row.name) return row.gl;
  return std::nullopt;
}

std::string headless_gl_names() {
  std::vector<std::string> names;
  for (const HeadlessGlRow& row : kHeadlessGlTable) names.push_back(row.name);
  return word_list(names, "or");
}

HeadlessGl headless_gl_from_environment() {
  const char* value = std::getenv("UMBRA_GL");
  if (!value || !*value) return HeadlessGl::kAuto;
  if (const auto gl = headless_gl_from_name(value)) return *gl;
  throw std::runtime_error(std::string("UMBRA_GL must be ") + headless_gl_names() + ", not \"" + value + "\"");
}

namespace {

// kAuto tries EGL and then OSMesa, and when both fail says why for each.
std::unique_ptr<HeadlessContext::Surface> make_surface(HeadlessGl gl) {
  if (gl == HeadlessGl::kAuto) gl = headless_gl_from_environment();
  if (gl == HeadlessGl::kEgl) return make_egl_surface();
  if (gl == HeadlessGl::kOsMesa) return make_osmesa_surface();
  try {
    return make_egl_surface();
  } catch (const std::exception& egl_failure) {
    try {
      return make_osmesa_surface();
    } catch (const std::exception& osmesa_failure) {
      throw std::runtime_error(std::string("no headless OpenGL context: ") + egl_failure.what() + "; " +
                               osmesa_failure.what());
    }
  }
}

}  // namespace

HeadlessContext::HeadlessContext(int width, int height, HeadlessGl gl)
    : surface_(make_surface(gl)), width_(width), height_(height) {
  require_image_size(width, height, surface_->platform.substr(0, surface_->platform.find(' ')));
}

HeadlessContext::~HeadlessContext() = default;

const std::string& HeadlessContext::platform() const { return surface_->platform; }

void HeadlessContext::make_current() { surface_->make_current(); }

void HeadlessContext::release_current() { surface_->release_current(); }

std::string HeadlessContext::description() const { return surface_->platform + ": " + gl_description(); }

}  // namespace umbra
