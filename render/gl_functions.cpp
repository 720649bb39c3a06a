#include "render/gl_functions.hpp"

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

void require_shadow_volume_framebuffer(const std::string& backend) {
  GLint stencil_bits = 0, depth_bits = 0;
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_STENCIL, GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE,
                                        &stencil_bits);
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_DEPTH, GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE,
                                        &depth_bits);
  if (stencil_bits < 8)
    throw std::runtime_error(backend + ": the framebuffer has " + std::to_string(stencil_bits) +
                             " stencil bits; shadow volumes need 8");
  if (depth_bits < 24)
    throw std::runtime_error(backend + ": the framebuffer has " + std::to_string(depth_bits) +
                             " depth bits; 24 are needed");
}

std::string gl_description() {
  const auto text = [](GLenum name) {
    const GLubyte* s = glGetString(name);
    return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
  };
  return text(GL_RENDERER) + ", OpenGL " + text(GL_VERSION);
}

}  // namespace umbra
