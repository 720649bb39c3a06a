// A headless context through EGL: a pbuffer on an EGL device
// (EGL_EXT_platform_device), a GPU's where there is one, else Mesa's software
// device (llvmpipe). libEGL is opened when the first context is made, not
// linked, as libOSMesa is (osmesa_context.cpp).
#define EGL_NO_X11 1  // no X11 types in eglplatform.h: there is no display
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "render/gl_functions.hpp"
#include "render/headless_surface.hpp"
#include "image/loaded_library.hpp"

namespace umbra {

namespace {

// The EGL functions umbra calls: the core ones resolved from libEGL, the
// device extension's through eglGetProcAddress.
struct EglLibrary {
  decltype(&eglGetProcAddress) get_proc_address = nullptr;
  decltype(&eglGetError) get_error = nullptr;
  decltype(&eglQueryString) query_string = nullptr;
  decltype(&eglInitialize) initialize = nullptr;
  decltype(&eglChooseConfig) choose_config = nullptr;
  decltype(&eglGetConfigAttrib) get_config_attrib = nullptr;
  decltype(&eglBindAPI) bind_api = nullptr;
  decltype(&eglCreateContext) create_context = nullptr;
  decltype(&eglCreatePbufferSurface) create_pbuffer_surface = nullptr;
  decltype(&eglMakeCurrent) make_current = nullptr;
  decltype(&eglDestroySurface) destroy_surface = nullptr;
  decltype(&eglDestroyContext) destroy_context = nullptr;
  PFNEGLQUERYDEVICESEXTPROC query_devices = nullptr;
  PFNEGLQUERYDEVICESTRINGEXTPROC query_device_string = nullptr;
  PFNEGLGETPLATFORMDISPLAYEXTPROC get_platform_display = nullptr;
};

template <typename Function>
void resolve_extension(const EglLibrary& egl, const char* name, Function& out) {
  out = reinterpret_cast<Function>(egl.get_proc_address(name));
  if (!out) throw std::runtime_error(std::string("EGL: no ") + name + " (EGL_EXT_device_enumeration and "
                                     "EGL_EXT_platform_device are needed)");
}

const EglLibrary& egl() {
  static const EglLibrary library = [] {
    const LoadedLibrary so("EGL", {"libEGL.so.1"}, "libEGL (Debian's libegl1 and libegl-mesa0)");
    EglLibrary l;
    so.resolve("eglGetProcAddress", l.get_proc_address);
    so.resolve("eglGetError", l.get_error);
    so.resolve("eglQueryString", l.query_string);
    so.resolve("eglInitialize", l.initialize);
    so.resolve("eglChooseConfig", l.choose_config);
    so.resolve("eglGetConfigAttrib", l.get_config_attrib);
    so.resolve("eglBindAPI", l.bind_api);
    so.resolve("eglCreateContext", l.create_context);
    so.resolve("eglCreatePbufferSurface", l.create_pbuffer_surface);
    so.resolve("eglMakeCurrent", l.make_current);
    so.resolve("eglDestroySurface", l.destroy_surface);
    so.resolve("eglDestroyContext", l.destroy_context);
    resolve_extension(l, "eglQueryDevicesEXT", l.query_devices);
    resolve_extension(l, "eglQueryDeviceStringEXT", l.query_device_string);
    resolve_extension(l, "eglGetPlatformDisplayEXT", l.get_platform_display);
    return l;  // the library stays loaded for the life of the process
  }();
  return library;
}

GlProc egl_proc(const char* name) { return reinterpret_cast<GlProc>(egl().get_proc_address(name)); }

std::string error_code() {
  char hex[16];
  std::snprintf(hex, sizeof hex, "0x%04x", unsigned(egl().get_error()));
  return hex;
}

bool has_extension(const char* extensions, const char* name) {
  if (!extensions) return false;
  const size_t length = std::strlen(name);
  for (const char* at = std::strstr(extensions, name); at; at = std::strstr(at + 1, name))
    if ((at == extensions || at[-1] == ' ') && (at[length] == ' ' || at[length] == '\0')) return true;
  return false;
}

// A device's display, initialised, with the configuration umbra makes its
// one-pixel pbuffer with: RGBA8, for desktop OpenGL (frames are drawn into
// framebuffer objects, which bring their own depth and stencil).
struct EglDisplay {
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLConfig config = nullptr;
  std::string platform;
};

EGLConfig exact_config(EGLDisplay display) {
  const EglLibrary& l = egl();
  const EGLint wanted[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                           EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8, EGL_ALPHA_SIZE, 8, EGL_NONE};
  EGLint count = 0;
  l.choose_config(display, wanted, nullptr, 0, &count);
  std::vector<EGLConfig> configs(size_t(std::max(count, 0)));
  if (count == 0 || !l.choose_config(display, wanted, configs.data(), count, &count)) return nullptr;
  // eglChooseConfig puts deeper colour first; any RGBA8 will do, the
  // smallest (configs come sorted by depth and stencil size too).
  const auto value = [&](EGLConfig c, EGLint attribute) {
    EGLint v = -1;
    l.get_config_attrib(display, c, attribute, &v);
    return v;
  };
  for (EGLConfig c : configs)
    if (value(c, EGL_RED_SIZE) == 8 && value(c, EGL_GREEN_SIZE) == 8 && value(c, EGL_BLUE_SIZE) == 8 &&
        value(c, EGL_ALPHA_SIZE) == 8 && value(c, EGL_SAMPLES) <= 1)
      return c;
  return nullptr;
}

// The first device that gives a display with that configuration, GPUs before
// Mesa's software device. Chosen once: EGL displays are per process, and
// terminating one would pull it from under other threads' contexts.
const EglDisplay& egl_display() {
  static const EglDisplay chosen = [] {
    const EglLibrary& l = egl();
    EGLint count = 0;
    if (!l.query_devices(0, nullptr, &count) || count == 0)
      throw std::runtime_error("EGL: no devices (" + error_code() + ")");
    std::vector<EGLDeviceEXT> devices(static_cast<size_t>(count));
    l.query_devices(count, devices.data(), &count);
    std::vector<EGLDeviceEXT> ordered;
    for (const bool software : {false, true})
      for (EGLDeviceEXT d : devices)
        if (has_extension(l.query_device_string(d, EGL_EXTENSIONS), "EGL_MESA_device_software") == software)
          ordered.push_back(d);
    std::string why;
    for (EGLDeviceEXT device : ordered) {
      const char* extensions = l.query_device_string(device, EGL_EXTENSIONS);
      const bool software = has_extension(extensions, "EGL_MESA_device_software");
      const char* file = has_extension(extensions, "EGL_EXT_device_drm")
                             ? l.query_device_string(device, EGL_DRM_DEVICE_FILE_EXT) : nullptr;
      std::string name = software ? "Mesa's software device" : std::string("device ") + (file ? file : "(no file)");
      EglDisplay d;
      d.display = l.get_platform_display(EGL_PLATFORM_DEVICE_EXT, device, nullptr);
      EGLint major = 0, minor = 0;
      if (d.display == EGL_NO_DISPLAY || !l.initialize(d.display, &major, &minor)) {
        why += "; " + name + ": cannot initialise (" + error_code() + ")";
        continue;
      }
      d.config = exact_config(d.display);
      if (!d.config) {
        why += "; " + name + ": no RGBA8 pbuffer for OpenGL";
        continue;
      }
      const char* vendor = l.query_string(d.display, EGL_VENDOR);
      d.platform = "EGL " + std::to_string(major) + "." + std::to_string(minor) + ", " +
                   (software ? name : (vendor ? std::string(vendor) + " " : std::string()) + name);
      return d;
    }
    throw std::runtime_error("EGL: no device can draw shadow volumes" + why);
  }();
  return chosen;
}

class EglSurface : public HeadlessContext::Surface {
 public:
  EglSurface() : display_(egl_display()) {
    const EglLibrary& l = egl();
    platform = display_.platform;
    if (!l.bind_api(EGL_OPENGL_API))  // per thread: batch rendering makes contexts on several
      throw std::runtime_error("EGL: no desktop OpenGL (" + error_code() + ")");
    const EGLint context_attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                                         EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                         EGL_NONE};
    context_ = l.create_context(display_.display, display_.config, EGL_NO_CONTEXT, context_attributes);
    if (context_ == EGL_NO_CONTEXT)
      throw std::runtime_error("EGL: cannot create an OpenGL 3.3 core context (" + error_code() + ")");
    const EGLint surface_attributes[] = {EGL_WIDTH, 1, EGL_HEIGHT, 1, EGL_NONE};
    surface_ = l.create_pbuffer_surface(display_.display, display_.config, surface_attributes);
    try {
      if (surface_ == EGL_NO_SURFACE)
        throw std::runtime_error("EGL: cannot create a pbuffer (" + error_code() + ")");
      if (!l.make_current(display_.display, surface_, surface_, context_))
        throw std::runtime_error("EGL: cannot make the context current (" + error_code() + ")");
      load_gl_functions(egl_proc, "EGL");
    } catch (...) {
      release();
      throw;
    }
  }
  ~EglSurface() override { release(); }

  void make_current() override {
    const EglLibrary& l = egl();
    if (!l.bind_api(EGL_OPENGL_API) || !l.make_current(display_.display, surface_, surface_, context_))
      throw std::runtime_error("EGL: cannot make the context current on this thread (" + error_code() + ")");
  }
  void release_current() override {
    egl().make_current(display_.display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  }

 private:
  void release() {
    const EglLibrary& l = egl();
    l.make_current(display_.display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (surface_ != EGL_NO_SURFACE) l.destroy_surface(display_.display, surface_);
    l.destroy_context(display_.display, context_);
  }

  const EglDisplay& display_;
  EGLContext context_ = EGL_NO_CONTEXT;
  EGLSurface surface_ = EGL_NO_SURFACE;
};

}  // namespace

std::unique_ptr<HeadlessContext::Surface> make_egl_surface() {
  return std::make_unique<EglSurface>();
}

}  // namespace umbra
