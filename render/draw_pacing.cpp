#include "render/draw_pacing.hpp"

#include <algorithm>
#include <string>

#include "render/gl.hpp"
#include "render/gl_functions.hpp"

namespace umbra {

namespace {

// The next piece of a draw with `left` triangles still to send.
size_t next_piece(size_t left, size_t limit) {
  if (limit == 0 || left <= limit) return left;
  limit = std::max<size_t>(limit, 5);  // so that one less is still four or more
  const size_t piece = std::min(left, limit);
  return left - piece == 3 ? piece - 1 : piece;  // leaves four, not three
}

}  // namespace

std::vector<size_t> draw_pieces(size_t count, size_t limit) {
  std::vector<size_t> pieces;
  for (size_t left = count; left > 0; left -= pieces.back()) pieces.push_back(next_piece(left, limit));
  if (pieces.empty()) pieces.push_back(0);
  return pieces;
}

DrawPacing::~DrawPacing() {
  if (fence_) glDeleteSync(static_cast<GLsync>(fence_));
}

void DrawPacing::draw(size_t count, const std::function<void(size_t first, size_t count)>& send) {
  if (limit_ == 0) {  // a GPU, or a run of frames: no pieces to cut, nothing to allocate per draw
    send(0, count);
    return;
  }
  for (size_t first = 0; first < count;) {
    const size_t piece = next_piece(count - first, limit_);
    send(first, piece);
    first += piece;
    if ((unfenced_ += piece) < limit_) continue;
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
