#pragma once
// An OpenGL 3.3 core context in a window (GLFW), with a double-buffered
// default framebuffer of 24-bit depth and 8-bit stencil; functions are loaded
// through glfwGetProcAddress. Input arrives through the callbacks below.

#include <functional>
#include <memory>
#include <string>

namespace umbra {

class WindowContext {
 public:
  // Throws std::runtime_error when there is no display or no such context.
  WindowContext(int width, int height, const std::string& title);
  ~WindowContext();
  WindowContext(const WindowContext&) = delete;
  WindowContext& operator=(const WindowContext&) = delete;

  bool should_close() const;
  void close();
  void swap_buffers();
  void poll_events();
  // Waits for an event, at most `seconds`, then handles what came.
  void wait_events(double seconds);
  void set_title(const std::string& title);
  void framebuffer_size(int& width, int& height) const;
  double time_seconds() const;
  void* native_window() const;  // the GLFWwindow, for render/'s own GLFW code

  // The keys the viewer uses; press and repeat both call on_key.
  enum class Key { kSpace, kLeft, kRight, kUp, kDown, kV, kM, kR, kS, kC, kO, kH, kQ, kEscape, kLeftBracket, kRightBracket, kOther };
  std::function<void(Key key)> on_key;
  std::function<void(double dx, double dy)> on_drag;  // cursor moved with the left button down, in pixels
  std::function<void(double steps)> on_scroll;

 private:
  struct Glfw;
  std::unique_ptr<Glfw> glfw_;
};

}  // namespace umbra
