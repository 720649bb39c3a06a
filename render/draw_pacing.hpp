#pragma once
// Pacing the draws of a CPU rasteriser. Mesa's llvmpipe bins every triangle
// it is sent into the lists of the 64x64-pixel tiles it covers, and its
// threads rasterise such a scene of lists only once it is flushed or full
// (36 MB); meanwhile the draws go on filling the next scenes. A render of
// Khronos's engine at 800x800 held 95 MB of bins at its 120 MB heap peak. Sent
// in fenced pieces, no more than two of them unfinished (one rasterised
// while the next is binned), its heap peaked at 68 MB, and the picture is
// the same bit for bit (docs/performance.md).

#include <cstddef>
#include <functional>
#include <vector>

namespace umbra {

// Triangles a piece on a CPU rasteriser: a few megabytes of bins.
inline constexpr size_t kCpuRasteriserPiece = 16384;

// The sizes of the pieces a draw of `count` triangles is sent in, in
// order: at most `limit` each (0: one piece; a limit under 5 counts as 5).
// No piece is exactly three triangles unless the draw is, since llvmpipe
// may take a draw of nine vertices for a rectangle (surface_buffers.cpp).
std::vector<size_t> draw_pieces(size_t count, size_t limit);

class DrawPacing {
 public:
  // `limit`: triangles a piece, and how many may be sent past the last
  // fence waited on; 0 sends every draw whole and never waits.
  explicit DrawPacing(size_t limit) : limit_(limit) {}
  ~DrawPacing();
  DrawPacing(const DrawPacing&) = delete;
  DrawPacing& operator=(const DrawPacing&) = delete;

  // Calls send(first, count) for each piece of a draw of `count`
  // triangles (`first` counts triangles from the draw's start); once a
  // piece's worth has been sent since the last fence, fences it and waits
  // for the fence before.
  void draw(size_t count, const std::function<void(size_t first, size_t count)>& send);

 private:
  size_t limit_;
  size_t unfenced_ = 0;     // triangles sent since the last fence
  void* fence_ = nullptr;   // GLsync: the last fence, not yet waited on
};

// How a renderer sends its draws: in paced pieces for one picture, where
// the bins' memory is what counts, or whole for a viewer's or a
// benchmark's run of frames, where llvmpipe binning far ahead of its
// rasterising threads is worth more: paced, the frames of the 1.2M-triangle
// bunny in umbra view took 30% longer (docs/performance.md).
enum class DrawSending { kPaced, kWhole };

// kCpuRasteriserPiece where the current context rasterises on the CPU
// (llvmpipe, softpipe); 0 on a GPU, which holds no bins in memory and
// would pay the waits.
size_t draw_piece_limit_for_current_gl();

}  // namespace umbra
