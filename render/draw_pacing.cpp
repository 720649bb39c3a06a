#include "render/draw_pacing.hpp"

#include <algorithm>
#include <string>

#include "render/gl.hpp"
#include "render/gl_functions.hpp"

namespace umbra {

std::vector<size_t> draw_pieces(size_t count, size_t limit) {
  if (limit == 0 || count <= limit) return {count};
  limit = std::max<size_t>(limit, 5);  // so that one less is still four or more
  std::vector<size_t> pieces;
  for (size_t left = count; left > 0;) {
    size_t piece = std::min(left, limit);
    if (left - piece == 3) --piece;  // leaves four, not three
    pieces.push_back(piece);
    left -= piece;
  }
  return pieces;
}

DrawPacing::~DrawPacing() {
  if (fence_) glDeleteSync(static_cast<GLsync>(fence_));
}

void DrawPacing::draw(size_t count, const std::function<void(size_t first, size_t count)>& send) {
  size_t first = 0;
  for (const size_t piece : draw_pieces(count, limit_)) {
    send(first, piece);
    first += piece;
    if (limit_ == 0 || (unfenced_ += piece) < limit_) continue;
    GLsync fence = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
    glFlush();  // the piece goes to the rasteriser now
    if (fence_) {
      glClientWaitSync(static_cast<GLsync>(fence_), 0, GL_TIMEOUT_IGNORED);
      glDeleteSync(static_cast<GLsync>(fence_));
    }
    fence_ = fence;
    unfenced_ = 0;
  }
}

size_t draw_piece_limit_for_current_gl() {
  const std::string renderer = gl_renderer();
  const bool on_cpu = renderer.rfind("llvmpipe", 0) == 0 || renderer.rfind("softpipe", 0) == 0;
  return on_cpu ? kCpuRasteriserPiece : 0;
}

}  // namespace umbra
