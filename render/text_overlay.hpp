#pragma once
// A few lines of text drawn over the frame in a window (Dear ImGui, from
// Debian's libimgui-dev): the viewer's status and key help.

#include <string>
#include <vector>

namespace umbra {

class WindowContext;

class TextOverlay {
 public:
  // Requires the window's GL context to be current; keeps a pointer to it.
  explicit TextOverlay(WindowContext& window);
  ~TextOverlay();
  TextOverlay(const TextOverlay&) = delete;
  TextOverlay& operator=(const TextOverlay&) = delete;

  // Draws `lines` in a translucent box at the top left of the framebuffer.
  void draw(const std::vector<std::string>& lines);
};

}  // namespace umbra
