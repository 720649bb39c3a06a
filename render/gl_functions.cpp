#include "render/gl_functions.hpp"

#include <algorithm>
#include <stdexcept>

#include "render/gl.hpp"

namespace umbra {

void load_gl_functions(GlProcLoader loader, const std::string& backend) {
  const int version = gladLoadGL(reinterpret_cast<GLADloadfunc>(loader));
  if (version == 0) throw std::runtime_error(backend + ": cannot load the OpenGL functions");
  if (GLAD_VERSION_MAJOR(version) * 10 + GLAD_VERSION_MINOR(version) < 33)
    throw std::runtime_error(backend + ": OpenGL 3.3 core is needed, the context offers " +
                             std::to_string(GLAD_VERSION_MAJOR(version)) + "." +
                             std::to_string(GLAD_VERSION_MINOR(version)));
}

void require_image_size(int width, int height, const std::string& backend) {
  GLint renderbuffer = 0, viewport[2] = {0, 0};
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &renderbuffer);
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
  const int largest_width = std::min(renderbuffer, viewport[0]), largest_height = std::min(renderbuffer, viewport[1]);
  if (width > largest_width || height > largest_height)
    throw std::runtime_error(backend + ": the image may be at most " + std::to_string(largest_width) + "x" +
                             std::to_string(largest_height));
}

namespace {

std::string gl_string(GLenum name) {
  const GLubyte* s = glGetString(name);
  return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
}

}  // namespace

std::string gl_description() { return gl_renderer() + ", OpenGL " + gl_string(GL_VERSION); }

std::string gl_renderer() { return gl_string(GL_RENDERER); }

}  // namespace umbra
