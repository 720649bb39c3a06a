// OSMesa's header pulls in the system GL/gl.h, which must not meet glad's
// header: this file talks to OSMesa only and hands GL loading to gl_functions.
//
// libOSMesa is opened when the first context is made, not linked: it brings
// Mesa's llvmpipe and LLVM (over 100 MB of libraries), which commands that
// draw nothing, such as umbra check, then never load.
#include <GL/osmesa.h>

#include <stdexcept>

#include "render/gl_functions.hpp"
#include "render/headless_surface.hpp"
#include "image/loaded_library.hpp"

namespace umbra {

namespace {

// The OSMesa functions umbra calls, resolved once from the library.
struct OsMesaLibrary {
  decltype(&OSMesaCreateContextAttribs) create_context_attribs = nullptr;
  decltype(&OSMesaMakeCurrent) make_current = nullptr;
  decltype(&OSMesaGetProcAddress) get_proc_address = nullptr;
  decltype(&OSMesaDestroyContext) destroy_context = nullptr;
};

const OsMesaLibrary& osmesa() {
  static const OsMesaLibrary library = [] {
    const LoadedLibrary so("OSMesa", {"libOSMesa.so.8", "libOSMesa.so"}, "libOSMesa (Debian's libosmesa6)");
    OsMesaLibrary l;
    so.resolve("OSMesaCreateContextAttribs", l.create_context_attribs);
    so.resolve("OSMesaMakeCurrent", l.make_current);
    so.resolve("OSMesaGetProcAddress", l.get_proc_address);
    so.resolve("OSMesaDestroyContext", l.destroy_context);
    return l;  // the library stays loaded for the life of the process
  }();
  return library;
}

GlProc osmesa_proc(const char* name) { return reinterpret_cast<GlProc>(osmesa().get_proc_address(name)); }

// A context on OSMesa, current on a one-pixel buffer of our own: frames are
// drawn into framebuffer objects.
class OsMesaSurface : public HeadlessContext::Surface {
 public:
  OsMesaSurface() {
    platform = "OSMesa";
    const int attributes[] = {OSMESA_FORMAT,        OSMESA_RGBA,
                              OSMESA_DEPTH_BITS,    0,
                              OSMESA_STENCIL_BITS,  0,
                              OSMESA_ACCUM_BITS,    0,
                              OSMESA_PROFILE,       OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION, 3,
                              OSMESA_CONTEXT_MINOR_VERSION, 3,
                              0};
    const OsMesaLibrary& mesa = osmesa();
    context_ = mesa.create_context_attribs(attributes, nullptr);
    if (!context_) throw std::runtime_error("OSMesa: cannot create an OpenGL 3.3 core context");
    try {
      if (!mesa.make_current(context_, pixel_, GL_UNSIGNED_BYTE, 1, 1))
        throw std::runtime_error("OSMesa: cannot make the context current");
      load_gl_functions(osmesa_proc, "OSMesa");
    } catch (...) {
      mesa.destroy_context(context_);
      throw;
    }
  }
  ~OsMesaSurface() override { osmesa().destroy_context(context_); }

  void make_current() override {
    if (!osmesa().make_current(context_, pixel_, GL_UNSIGNED_BYTE, 1, 1))
      throw std::runtime_error("OSMesa: cannot make the context current on this thread");
  }
  void release_current() override { osmesa().make_current(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0); }

 private:
  OSMesaContext context_ = nullptr;
  unsigned char pixel_[4] = {};  // the default framebuffer: one RGBA8 pixel
};

}  // namespace

std::unique_ptr<HeadlessContext::Surface> make_osmesa_surface() {
  return std::make_unique<OsMesaSurface>();
}

}  // namespace umbra
