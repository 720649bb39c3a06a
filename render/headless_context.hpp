#pragma once
// An OpenGL 3.3 core context that renders into memory with no display
// (OSMesa, Mesa's llvmpipe), with a default framebuffer of RGBA8, 24-bit depth
// and 8-bit stencil. Its functions are loaded through OSMesaGetProcAddress.

#include <memory>
#include <string>

namespace umbra {

class HeadlessContext {
 public:
  // Throws std::runtime_error when no such context can be had, or when it
  // lacks the stencil buffer that shadow volumes need.
  HeadlessContext(int width, int height);
  ~HeadlessContext();
  HeadlessContext(const HeadlessContext&) = delete;
  HeadlessContext& operator=(const HeadlessContext&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }

 private:
  struct OsMesa;
  std::unique_ptr<OsMesa> osmesa_;
  int width_;
  int height_;
};

}  // namespace umbra
