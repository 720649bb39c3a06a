#pragma once
// The framebuffer a frame is drawn into: floating-point colour (RGBA32F) with
// 24-bit depth and 8-bit stencil. Each light's pass adds its term by
// blending; in an 8-bit buffer every pass would round, and with two or three
// lights a pixel could end two levels from the exact sum (as seen on NVIDIA's
// driver). Here the sum is kept and rounded once, when it is read or shown;
// llvmpipe's image of a bundled scene then equals the ray-cast reference's
// byte for byte away from edges, but for a few channels one level off.
// (RGBA16F still left a level on 2% of channels.)
//
// Beside it, a second framebuffer for the shadow volumes' count: one 32-bit
// float channel (R32F) over the same depth and stencil, summed by additive
// blending. A float holds every whole number to 2^24 exactly, where the
// 8-bit stencil counts modulo 256 (Everitt and Kilgard 2002), so no count
// wraps and no bound on a mesh's layers is needed. Assarsson and
// Akenine-Moeller (2003) likewise sum their soft shadow volumes by additive
// blending in a colour buffer (their V-buffer) rather than the stencil.

#include <cstdint>
#include <functional>
#include <memory>
#include <stdexcept>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "image/image.hpp"
#include "image/tone_curve.hpp"

namespace umbra {

class ShaderProgram;

// A frame larger than the GL could allocate: the picture's size and samples
// are the user's to make smaller (a command says so as a usage error).
class FrameTooLarge : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class FrameTarget {
 public:
  FrameTarget() = default;
  ~FrameTarget();
  FrameTarget(const FrameTarget&) = delete;
  FrameTarget& operator=(const FrameTarget&) = delete;

  // Binds the target for drawing, made (or remade) at width x height.
  // Throws std::runtime_error when the GL cannot make it.
  void bind(int width, int height);
  // After bind: draws into the count instead of the colour (made on first
  // use, at the frame's size: only the volume methods count), or back again.
  void bind_count();
  void bind_colour() const;
  // The count as a texture, for the lit passes to read (texelFetch).
  unsigned count_texture() const { return count_; }
  // Draws the colour into framebuffer `into` (0: the window) at width x
  // height, each block of samples x samples pixels averaged into one and
  // toned by `curve` as a picture's pixels are (put_pixel_mean, over
  // `nothing`, the sample that sees no surface), rounded by the GL to the
  // window's format. Leaves `into` bound, at its size (for an overlay over
  // it); the next bind binds the target again.
  void show(int width, int height, ToneCurve curve, const glm::vec3& nothing, unsigned into = 0) const;
  // What show draws, read back (RGB, rows from the top) from an 8-bit
  // framebuffer of width x height, as a window would hold it.
  Image read_shown(int width, int height, ToneCurve curve, const glm::vec3& nothing) const;
  // The colour, each block of samples x samples pixels averaged (in double)
  // into one: `pixel` gets each mean with its column and its row counted
  // from the top, to round once (pixel_mean.hpp, as the ray-cast reference
  // rounds).
  // Each sample is first passed through `resolve` (pixel_mean.hpp's
  // resolved_sample), where given.
  void for_each_pixel_mean(int samples, const std::function<void(int x, int y, const glm::dvec4& mean)>& pixel,
                           const std::function<glm::dvec4(const glm::dvec4&)>& resolve = {}) const;
  // Per pixel, 1 where a surface was drawn (its depth is under the cleared
  // 1.0, which no fragment can equal and pass GL_LESS), 0 elsewhere; rows
  // from the bottom. For one sample a pixel.
  std::vector<uint8_t> read_covered() const;
  // The window depth in [0, 1] per pixel, rows from the bottom; 1 where
  // nothing was drawn. For one sample a pixel.
  std::vector<float> read_depth() const;

 private:
  void release();
  // Throws, naming `what`, unless the bound framebuffer is complete.
  void require_complete(const char* what, int width, int height);  // throws, saying the frame's size, unless complete
  int width_ = 0, height_ = 0;
  unsigned framebuffer_ = 0, colour_ = 0, depth_stencil_ = 0;  // the colour a texture, which show reads
  mutable std::unique_ptr<ShaderProgram> show_program_;  // made on first show
  mutable unsigned show_vao_ = 0;
  unsigned count_framebuffer_ = 0, count_ = 0;
};

}  // namespace umbra
