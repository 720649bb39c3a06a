// OSMesa's header pulls in the system GL/gl.h, which must not meet glad's
// header: this file talks to OSMesa only and hands GL loading to gl_functions.
#include <GL/osmesa.h>

#include <stdexcept>
#include <vector>

#include "render/gl_functions.hpp"
#include "render/headless_context.hpp"

namespace umbra {

struct HeadlessContext::OsMesa {
  OSMesaContext context = nullptr;
  std::vector<unsigned char> buffer;  // the default framebuffer's colour, RGBA8
};

namespace {
GlProc osmesa_proc(const char* name) { return reinterpret_cast<GlProc>(OSMesaGetProcAddress(name)); }
}  // namespace

HeadlessContext::HeadlessContext(int width, int height)
    : osmesa_(std::make_unique<OsMesa>()), width_(width), height_(height) {
  GLint max_width = 0, max_height = 0;
  const int attributes[] = {OSMESA_FORMAT,        OSMESA_RGBA,
                            OSMESA_DEPTH_BITS,    24,
                            OSMESA_STENCIL_BITS,  8,
                            OSMESA_ACCUM_BITS,    0,
                            OSMESA_PROFILE,       OSMESA_CORE_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION, 3,
                            OSMESA_CONTEXT_MINOR_VERSION, 3,
                            0};
  osmesa_->context = OSMesaCreateContextAttribs(attributes, nullptr);
  if (!osmesa_->context) throw std::runtime_error("OSMesa: cannot create an OpenGL 3.3 core context");
  osmesa_->buffer.resize(size_t(width) * size_t(height) * 4);
  if (!OSMesaMakeCurrent(osmesa_->context, osmesa_->buffer.data(), GL_UNSIGNED_BYTE, width, height)) {
    OSMesaDestroyContext(osmesa_->context);
    throw std::runtime_error("OSMesa: cannot bind a " + std::to_string(width) + "x" + std::to_string(height) +
                             " framebuffer");
  }
  OSMesaGetIntegerv(OSMESA_MAX_WIDTH, &max_width);
  OSMesaGetIntegerv(OSMESA_MAX_HEIGHT, &max_height);
  try {
    if (width > max_width || height > max_height)
      throw std::runtime_error("OSMesa: the image may be at most " + std::to_string(max_width) + "x" +
                               std::to_string(max_height));
    load_gl_functions(osmesa_proc, "OSMesa");
    require_shadow_volume_framebuffer("OSMesa");
  } catch (...) {
    OSMesaDestroyContext(osmesa_->context);
    throw;
  }
}

HeadlessContext::~HeadlessContext() { OSMesaDestroyContext(osmesa_->context); }

}  // namespace umbra
