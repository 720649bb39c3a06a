#pragma once
// An OpenGL 3.3 core context that renders into memory with no display, with
// a default framebuffer of RGBA8, 24-bit depth and 8-bit stencil. Two
// platforms make one: EGL (a pbuffer on a GPU device, or on Mesa's software
// device) and OSMesa (Mesa's llvmpipe). Either library is opened when the
// first context is made, not linked, so commands that draw nothing never
// load them.

#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace umbra {

enum class HeadlessGl { kAuto, kEgl, kOsMesa };

// The platforms, one row each; --gl and UMBRA_GL are read from this table.
struct HeadlessGlRow {
  HeadlessGl gl;
  const char* name;
  const char* help;
};
inline constexpr HeadlessGlRow kHeadlessGlTable[] = {
    {HeadlessGl::kAuto, "auto",
     "an EGL device with a GPU if there is one, else Mesa's software device through EGL, else OSMesa"},
    {HeadlessGl::kEgl, "egl", "EGL only: a GPU device if there is one, else Mesa's software device"},
    {HeadlessGl::kOsMesa, "osmesa", "OSMesa only: Mesa's llvmpipe on the CPU"},
};

std::optional<HeadlessGl> headless_gl_from_name(std::string_view name);
std::string headless_gl_names();  // "auto, egl or osmesa"

// What kAuto means in this process: the UMBRA_GL environment variable's
// platform when it is set, else kAuto. Throws std::runtime_error when
// UMBRA_GL names no platform.
HeadlessGl headless_gl_from_environment();

class HeadlessContext {
 public:
  // Throws std::runtime_error when no such context can be had on `gl` (with
  // kAuto: on any platform, saying why for each), or when it lacks the
  // stencil buffer that shadow volumes need.
  HeadlessContext(int width, int height, HeadlessGl gl = HeadlessGl::kAuto);
  ~HeadlessContext();
  HeadlessContext(const HeadlessContext&) = delete;
  HeadlessContext& operator=(const HeadlessContext&) = delete;

  // A context is current on the thread that made it. Another thread draws
  // in it once it makes it current there, after the first has released it
  // (a Python module's renderer, called from any thread, one at a time).
  void make_current();
  void release_current();

  int width() const { return width_; }
  int height() const { return height_; }
  // "EGL, NVIDIA device /dev/dri/renderD128", "EGL, Mesa's software device"
  // or "OSMesa": the platform the context was made on.
  const std::string& platform() const;
  // The platform, then the GL renderer and version: what --explain and
  // umbra --version print.
  std::string description() const;

  struct Surface;  // one platform's context and framebuffer

 private:
  std::unique_ptr<Surface> surface_;
  int width_;
  int height_;
};

// The context current on this thread for a scope, released at its end.
class CurrentContext {
 public:
  explicit CurrentContext(HeadlessContext& context) : context_(context) { context_.make_current(); }
  ~CurrentContext() { context_.release_current(); }
  CurrentContext(const CurrentContext&) = delete;
  CurrentContext& operator=(const CurrentContext&) = delete;

 private:
  HeadlessContext& context_;
};

}  // namespace umbra
