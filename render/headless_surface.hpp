#pragma once
// What each headless platform makes: a current GL context with the GL
// functions loaded. Its default framebuffer is one pixel: frames are drawn
// into a framebuffer object of their own (FrameTarget). Only
// headless_context.cpp chooses between them.

#include <memory>
#include <string>

#include "render/headless_context.hpp"

namespace umbra {

struct HeadlessContext::Surface {
  virtual ~Surface() = default;
  virtual void make_current() = 0;     // on the calling thread; throws std::runtime_error
  virtual void release_current() = 0;  // from the calling thread
  std::string platform;
};

// Each throws std::runtime_error, starting with its platform's name, when it
// cannot make the context.
std::unique_ptr<HeadlessContext::Surface> make_egl_surface();
std::unique_ptr<HeadlessContext::Surface> make_osmesa_surface();

}  // namespace umbra
