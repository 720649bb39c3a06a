// OSMesa's header pulls in the system GL/gl.h, which must not meet glad's
// header: this file talks to OSMesa only and hands GL loading to gl_functions.
//
// libOSMesa is opened when the first context is made, not linked: it brings
// Mesa's llvmpipe and LLVM (over 100 MB of libraries), which commands that
// draw nothing, such as umbra check, then never load.
#include <GL/osmesa.h>
#include <dlfcn.h>

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

// The OSMesa functions umbra calls, resolved once from the library.
struct OsMesaLibrary {
  decltype(&OSMesaCreateContextAttribs) create_context_attribs = nullptr;
  decltype(&OSMesaMakeCurrent) make_current = nullptr;
  decltype(&OSMesaGetIntegerv) get_integerv = nullptr;
  decltype(&OSMesaGetProcAddress) get_proc_address = nullptr;
  decltype(&OSMesaDestroyContext) destroy_context = nullptr;
};

template <typename Function>
void resolve(void* library, const char* name, Function& out) {
  out = reinterpret_cast<Function>(dlsym(library, name));
  if (!out) throw std::runtime_error(std::string("OSMesa: libOSMesa has no ") + name);
}

const OsMesaLibrary& osmesa() {
  static const OsMesaLibrary library = [] {
    void* handle = dlopen("libOSMesa.so.8", RTLD_NOW | RTLD_LOCAL);
    if (!handle) handle = dlopen("libOSMesa.so", RTLD_NOW | RTLD_LOCAL);
    if (!handle)
      throw std::runtime_error(std::string("OSMesa: cannot load libOSMesa (Debian's libosmesa6): ") + dlerror());
    OsMesaLibrary l;
    resolve(handle, "OSMesaCreateContextAttribs", l.create_context_attribs);
    resolve(handle, "OSMesaMakeCurrent", l.make_current);
    resolve(handle, "OSMesaGetIntegerv", l.get_integerv);
    resolve(handle, "OSMesaGetProcAddress", l.get_proc_address);
    resolve(handle, "OSMesaDestroyContext", l.destroy_context);
    return l;  // the library stays loaded for the life of the process
  }();
  return library;
}

GlProc osmesa_proc(const char* name) { return reinterpret_cast<GlProc>(osmesa().get_proc_address(name)); }

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
  const OsMesaLibrary& mesa = osmesa();
  osmesa_->context = mesa.create_context_attribs(attributes, nullptr);
  if (!osmesa_->context) throw std::runtime_error("OSMesa: cannot create an OpenGL 3.3 core context");
  osmesa_->buffer.resize(size_t(width) * size_t(height) * 4);
  if (!mesa.make_current(osmesa_->context, osmesa_->buffer.data(), GL_UNSIGNED_BYTE, width, height)) {
    mesa.destroy_context(osmesa_->context);
    throw std::runtime_error("OSMesa: cannot bind a " + std::to_string(width) + "x" + std::to_string(height) +
                             " framebuffer");
  }
  mesa.get_integerv(OSMESA_MAX_WIDTH, &max_width);
  mesa.get_integerv(OSMESA_MAX_HEIGHT, &max_height);
  try {
    if (width > max_width || height > max_height)
      throw std::runtime_error("OSMesa: the image may be at most " + std::to_string(max_width) + "x" +
                               std::to_string(max_height));
    load_gl_functions(osmesa_proc, "OSMesa");
    require_shadow_volume_framebuffer("OSMesa");
  } catch (...) {
    mesa.destroy_context(osmesa_->context);
    throw;
  }
}

HeadlessContext::~HeadlessContext() { osmesa().destroy_context(osmesa_->context); }

}  // namespace umbra
