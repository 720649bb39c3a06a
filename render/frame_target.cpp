#include "render/frame_target.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "image/image.hpp"
#include "render/gl.hpp"
#include "render/gl_functions.hpp"
#include "render/shader_program.hpp"
#include "render/shaders.hpp"

namespace umbra {

FrameTarget::~FrameTarget() {
  release();
  if (show_vao_) glDeleteVertexArrays(1, &show_vao_);
}

void FrameTarget::release() {
  if (framebuffer_) glDeleteFramebuffers(1, &framebuffer_);
  if (colour_) glDeleteTextures(1, &colour_);
  if (depth_stencil_) glDeleteRenderbuffers(1, &depth_stencil_);
  if (count_framebuffer_) glDeleteFramebuffers(1, &count_framebuffer_);
  if (count_) glDeleteTextures(1, &count_);
  framebuffer_ = colour_ = depth_stencil_ = count_framebuffer_ = count_ = 0;
  width_ = height_ = 0;
}

void FrameTarget::bind(int width, int height) {
  if (framebuffer_ && width == width_ && height == height_) {
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    return;
  }
  release();
  require_image_size(width, height, "OpenGL");
  glGenTextures(1, &colour_);
  glBindTexture(GL_TEXTURE_2D, colour_);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGBA, GL_FLOAT, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
  glBindTexture(GL_TEXTURE_2D, 0);
  glGenRenderbuffers(1, &depth_stencil_);
  glBindRenderbuffer(GL_RENDERBUFFER, depth_stencil_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, width, height);
  glGenFramebuffers(1, &framebuffer_);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour_, 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, depth_stencil_);
  require_complete("the frame's framebuffer (RGBA32F, 24-bit depth, 8-bit stencil)", width, height);
  width_ = width;
  height_ = height;
}

void FrameTarget::require_complete(const char* what, int width, int height) {
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status == GL_FRAMEBUFFER_COMPLETE) return;
  release();
  // GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT where the GL could not allocate it:
  // say how large the frame is, and what makes it smaller.
  // 16 bytes of colour, 4 of depth and stencil and 4 of the volumes' count a pixel.
  char size[96];
  std::snprintf(size, sizeof size, "%dx%d, about %.0f MiB", width, height, double(width) * height * 24.0 / (1 << 20));
  throw FrameTooLarge("a frame of " + std::string(size) + " is more than this GL could make (" + what + " incomplete, status " +
                      std::to_string(status) + ")");
}

void FrameTarget::bind_count() {
  if (count_framebuffer_) {
    glBindFramebuffer(GL_FRAMEBUFFER, count_framebuffer_);
    return;
  }
  glGenTextures(1, &count_);
  glBindTexture(GL_TEXTURE_2D, count_);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_R32F, width_, height_, 0, GL_RED, GL_FLOAT, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glBindTexture(GL_TEXTURE_2D, 0);
  glGenFramebuffers(1, &count_framebuffer_);
  glBindFramebuffer(GL_FRAMEBUFFER, count_framebuffer_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, count_, 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, depth_stencil_);
  require_complete("the shadow volumes' count framebuffer (R32F, 24-bit depth, 8-bit stencil)", width_, height_);
}

void FrameTarget::bind_colour() const { glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_); }

void FrameTarget::show(int width, int height, ToneCurve curve, const glm::vec3& nothing, unsigned into) const {
  if (!show_program_) {
    show_program_ = std::make_unique<ShaderProgram>("show", shaders::kShowVertex, shaders::kShowFragment);
    glGenVertexArrays(1, &show_vao_);  // a core profile draws only with one bound; the triangle needs no attributes
  }
  glBindFramebuffer(GL_FRAMEBUFFER, into);
  glViewport(0, 0, width, height);
  GLboolean enabled[4];
  const GLenum states[4] = {GL_DEPTH_TEST, GL_STENCIL_TEST, GL_BLEND, GL_CULL_FACE};
  for (int k = 0; k < 4; ++k) {
    enabled[k] = glIsEnabled(states[k]);
    glDisable(states[k]);
  }
  glActiveTexture(GL_TEXTURE0 + shaders::kShownFrameUnit);
  glBindTexture(GL_TEXTURE_2D, colour_);
  show_program_->use();
  show_program_->set("frame", int(shaders::kShownFrameUnit));
  show_program_->set("samples", width > 0 ? width_ / width : 1);
  show_program_->set("soft", curve == ToneCurve::kSoft ? 1 : 0);
  show_program_->set("knee", float(kToneKnee));
  show_program_->set("nothing", nothing);
  glBindVertexArray(show_vao_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glBindTexture(GL_TEXTURE_2D, 0);
  glActiveTexture(GL_TEXTURE0 + shaders::kMaterialTextureUnit);
  for (int k = 0; k < 4; ++k)
    if (enabled[k]) glEnable(states[k]);
}

Image FrameTarget::read_shown(int width, int height, ToneCurve curve, const glm::vec3& nothing) const {
  GLuint framebuffer = 0, colour = 0;
  glGenRenderbuffers(1, &colour);
  glBindRenderbuffer(GL_RENDERBUFFER, colour);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
  glGenFramebuffers(1, &framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour);
  show(width, height, curve, nothing, framebuffer);
  std::vector<uint8_t> rgba(size_t(width) * size_t(height) * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  bind_colour();
  glDeleteFramebuffers(1, &framebuffer);
  glDeleteRenderbuffers(1, &colour);
  Image image(width, height, 3);
  for (int y = 0; y < height; ++y)  // the GL's row 0 is the bottom
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < 3; ++c) image.at(x, y, c) = rgba[(size_t(height - 1 - y) * size_t(width) + size_t(x)) * 4 + size_t(c)];
  return image;
}

void FrameTarget::for_each_pixel_mean(int samples, const std::function<void(int, int, const glm::dvec4&)>& pixel,
                                      const std::function<glm::dvec4(const glm::dvec4&)>& resolve) const {
  // In strips of 32 output rows: the floats of a whole 800x800 frame would
  // be 10 MB, and nine times that supersampled.
  constexpr int kStripRows = 32;
  const int width = width_ / samples, height = height_ / samples;
  const size_t row_values = size_t(width_) * 4;
  std::vector<float> strip(row_values * size_t(kStripRows * samples));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  const double per_sample = 1.0 / (samples * samples);
  for (int y = 0; y < height; y += kStripRows) {
    const int rows = std::min(kStripRows, height - y);
    glReadPixels(0, y * samples, width_, rows * samples, GL_RGBA, GL_FLOAT, strip.data());
    for (int r = 0; r < rows; ++r)
      for (int x = 0; x < width; ++x) {
        glm::dvec4 sum(0.0);
        for (int j = 0; j < samples; ++j)
          for (int i = 0; i < samples; ++i) {
            const float* drawn = &strip[size_t(r * samples + j) * row_values + size_t(x * samples + i) * 4];
            const glm::dvec4 sample(drawn[0], drawn[1], drawn[2], drawn[3]);
            sum += resolve ? resolve(sample) : sample;
          }
        pixel(x, height - 1 - (y + r), sum * per_sample);  // the GL's row 0 is the bottom
      }
  }
}

std::vector<float> FrameTarget::read_depth() const {
  std::vector<float> depth(size_t(width_) * size_t(height_));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glReadPixels(0, 0, width_, height_, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
  return depth;
}

std::vector<uint8_t> FrameTarget::read_covered() const {
  const std::vector<float> depth = read_depth();
  std::vector<uint8_t> covered(depth.size());
  for (size_t i = 0; i < depth.size(); ++i) covered[i] = depth[i] < 1.0f;
  return covered;
}

}  // namespace umbra
