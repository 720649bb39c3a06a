// GLFW with GLFW_INCLUDE_NONE: glad's header provides GL, so this file talks
// to GLFW only and hands GL loading to gl_functions (docs/design.md).
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <stdexcept>

#include "render/gl_functions.hpp"
#include "render/window_context.hpp"

namespace umbra {

struct WindowContext::Glfw {
  GLFWwindow* window = nullptr;
  bool dragging = false;
  double last_x = 0.0, last_y = 0.0;
};

namespace {

GlProc glfw_proc(const char* name) { return reinterpret_cast<GlProc>(glfwGetProcAddress(name)); }

WindowContext::Key key_of(int glfw_key) {
  using Key = WindowContext::Key;
  switch (glfw_key) {
    case GLFW_KEY_SPACE: return Key::kSpace;
    case GLFW_KEY_LEFT: return Key::kLeft;
    case GLFW_KEY_RIGHT: return Key::kRight;
    case GLFW_KEY_UP: return Key::kUp;
    case GLFW_KEY_DOWN: return Key::kDown;
    case GLFW_KEY_V: return Key::kV;
    case GLFW_KEY_M: return Key::kM;
    case GLFW_KEY_R: return Key::kR;
    case GLFW_KEY_S: return Key::kS;
    case GLFW_KEY_C: return Key::kC;
    case GLFW_KEY_O: return Key::kO;
    case GLFW_KEY_H: return Key::kH;
    case GLFW_KEY_Q: return Key::kQ;
    case GLFW_KEY_ESCAPE: return Key::kEscape;
    case GLFW_KEY_LEFT_BRACKET: return Key::kLeftBracket;
    case GLFW_KEY_RIGHT_BRACKET: return Key::kRightBracket;
    default: return Key::kOther;
  }
}

WindowContext& owner(GLFWwindow* window) { return *static_cast<WindowContext*>(glfwGetWindowUserPointer(window)); }

}  // namespace

WindowContext::WindowContext(int width, int height, const std::string& title) : glfw_(std::make_unique<Glfw>()) {
  if (!glfwInit()) throw std::runtime_error("GLFW: cannot start (is there a display? try xvfb-run)");
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  // Frames are drawn into a framebuffer object of their own (FrameTarget) and
  // copied here: the window needs neither depth nor stencil.
  glfwWindowHint(GLFW_DEPTH_BITS, 0);
  glfwWindowHint(GLFW_STENCIL_BITS, 0);
  glfwWindowHint(GLFW_SAMPLES, 0);
  glfw_->window = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!glfw_->window) {
    glfwTerminate();
    throw std::runtime_error("GLFW: cannot open a window with an OpenGL 3.3 core context");
  }
  glfwMakeContextCurrent(glfw_->window);
  glfwSwapInterval(1);
  try {
    load_gl_functions(glfw_proc, "GLFW");
  } catch (...) {
    glfwDestroyWindow(glfw_->window);
    glfwTerminate();
    throw;
  }
  glfwSetWindowUserPointer(glfw_->window, this);
  glfwSetKeyCallback(glfw_->window, [](GLFWwindow* w, int key, int, int action, int) {
    WindowContext& self = owner(w);
    if ((action == GLFW_PRESS || action == GLFW_REPEAT) && self.on_key) self.on_key(key_of(key));
  });
  glfwSetMouseButtonCallback(glfw_->window, [](GLFWwindow* w, int button, int action, int) {
    WindowContext& self = owner(w);
    if (button != GLFW_MOUSE_BUTTON_LEFT) return;
    self.glfw_->dragging = action == GLFW_PRESS;
    glfwGetCursorPos(w, &self.glfw_->last_x, &self.glfw_->last_y);
  });
  glfwSetCursorPosCallback(glfw_->window, [](GLFWwindow* w, double x, double y) {
    WindowContext& self = owner(w);
    if (self.glfw_->dragging && self.on_drag) self.on_drag(x - self.glfw_->last_x, y - self.glfw_->last_y);
    self.glfw_->last_x = x;
    self.glfw_->last_y = y;
  });
  glfwSetScrollCallback(glfw_->window, [](GLFWwindow* w, double, double dy) {
    WindowContext& self = owner(w);
    if (self.on_scroll) self.on_scroll(dy);
  });
}

WindowContext::~WindowContext() {
  glfwDestroyWindow(glfw_->window);
  glfwTerminate();
}

bool WindowContext::should_close() const { return glfwWindowShouldClose(glfw_->window); }
void WindowContext::close() { glfwSetWindowShouldClose(glfw_->window, GLFW_TRUE); }
void WindowContext::swap_buffers() { glfwSwapBuffers(glfw_->window); }
void WindowContext::poll_events() { glfwPollEvents(); }
void WindowContext::wait_events(double seconds) { glfwWaitEventsTimeout(seconds); }
void WindowContext::set_title(const std::string& title) { glfwSetWindowTitle(glfw_->window, title.c_str()); }
void WindowContext::framebuffer_size(int& width, int& height) const { glfwGetFramebufferSize(glfw_->window, &width, &height); }
double WindowContext::time_seconds() const { return glfwGetTime(); }
void* WindowContext::native_window() const { return glfw_->window; }

}  // namespace umbra
