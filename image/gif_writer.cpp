// A GIF through giflib, with one palette made for the whole animation (so
// that a colour keeps its index from frame to frame and nothing flickers):
// median cut over every frame's colours (Heckbert, "Color Image
// Quantization for Frame Buffer Display", 1982), each frame then dithered
// to it in Bayer's ordered pattern (Bayer, "An Optimum Method for
// Two-Level Rendition of Continuous-Tone Pictures", 1973), which unlike
// error diffusion leaves a pixel that does not change alone from frame to
// frame. The frames are kept until the palette is made, at finish().

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <gif_lib.h>

#include "image/animation_writers.hpp"

namespace umbra {
namespace {

constexpr int kPaletteSize = 256;
constexpr int kCellBits = 5;  // the histogram's cells: 32 levels a channel
constexpr int kCells = 1 << (3 * kCellBits);
constexpr int kLookupBits = 6;  // nearest-colour lookup: 64 levels a channel
// The dither's reach, in channel levels: about half the gap between
// neighbouring colours of a 256-colour palette spread over a picture's few
// hues.
constexpr double kDitherSpread = 12.0;

int cell_of(const uint8_t* rgb) {
  return (rgb[0] >> (8 - kCellBits)) << (2 * kCellBits) | (rgb[1] >> (8 - kCellBits)) << kCellBits | (rgb[2] >> (8 - kCellBits));
}

// Every cell's count and the sums of its colours, over every frame.
struct Histogram {
  std::vector<uint32_t> count = std::vector<uint32_t>(kCells, 0);
  std::vector<std::array<double, 3>> sum = std::vector<std::array<double, 3>>(kCells, {0.0, 0.0, 0.0});
  void add(const uint8_t* rgb) {
    const int c = cell_of(rgb);
    ++count[size_t(c)];
    for (int k = 0; k < 3; ++k) sum[size_t(c)][size_t(k)] += rgb[k];
  }
};

// Median cut: the occupied cells in boxes, the box whose population times
// its longest side is largest split at its population's median along that
// side, until there are `most` boxes; each box's colour is its pixels' mean.
std::vector<std::array<uint8_t, 3>> median_cut(const Histogram& h, int most) {
  struct Cell {
    std::array<int, 3> at;
    uint32_t count;
    int index;
  };
  std::vector<Cell> cells;
  for (int c = 0; c < kCells; ++c)
    if (h.count[size_t(c)] > 0)
      cells.push_back({{c >> (2 * kCellBits), (c >> kCellBits) & ((1 << kCellBits) - 1), c & ((1 << kCellBits) - 1)}, h.count[size_t(c)], c});
  struct Box {
    size_t begin, end;
  };
  std::vector<Box> boxes{{0, cells.size()}};
  const auto longest = [&](const Box& b, int& axis) {
    int best = -1;
    for (int a = 0; a < 3; ++a) {
      int lo = 1 << kCellBits, hi = -1;
      for (size_t i = b.begin; i < b.end; ++i) lo = std::min(lo, cells[i].at[size_t(a)]), hi = std::max(hi, cells[i].at[size_t(a)]);
      if (hi - lo > best) best = hi - lo, axis = a;
    }
    return best;
  };
  while (int(boxes.size()) < most) {
    double best_score = 0.0;
    size_t chosen = boxes.size();
    int chosen_axis = 0;
    for (size_t b = 0; b < boxes.size(); ++b) {
      if (boxes[b].end - boxes[b].begin < 2) continue;
      int axis = 0;
      double population = 0.0;
      for (size_t i = boxes[b].begin; i < boxes[b].end; ++i) population += cells[i].count;
      const double score = population * longest(boxes[b], axis);
      if (score > best_score) best_score = score, chosen = b, chosen_axis = axis;
    }
    if (chosen == boxes.size()) break;  // every box is one cell
    Box& box = boxes[chosen];
    std::sort(cells.begin() + long(box.begin), cells.begin() + long(box.end),
              [&](const Cell& a, const Cell& b) { return a.at[size_t(chosen_axis)] < b.at[size_t(chosen_axis)]; });
    double total = 0.0, running = 0.0;
    for (size_t i = box.begin; i < box.end; ++i) total += cells[i].count;
    size_t split = box.begin + 1;
    for (size_t i = box.begin; i + 1 < box.end; ++i) {
      running += cells[i].count;
      split = i + 1;
      if (running >= total / 2) break;
    }
    boxes.push_back({split, box.end});
    boxes[chosen].end = split;
  }
  std::vector<std::array<uint8_t, 3>> palette;
  for (const Box& b : boxes) {
    double n = 0.0, s[3] = {0.0, 0.0, 0.0};
    for (size_t i = b.begin; i < b.end; ++i) {
      n += cells[i].count;
      for (int k = 0; k < 3; ++k) s[k] += h.sum[size_t(cells[i].index)][size_t(k)];
    }
    if (n > 0) palette.push_back({uint8_t(std::lround(s[0] / n)), uint8_t(std::lround(s[1] / n)), uint8_t(std::lround(s[2] / n))});
  }
  if (palette.empty()) palette.push_back({0, 0, 0});
  return palette;
}

class GifWriter : public AnimationWriter {
 public:
  GifWriter(const std::string& path, const std::string& shown, const AnimationSettings& s) : path_(path), shown_(shown), settings_(s) {}

  void add(const Image& image) override {
    if (image.channels != 3) throw std::logic_error("a GIF's frames are RGB");
    for (size_t i = 0; i < image.pixels.size(); i += 3) histogram_.add(&image.pixels[i]);
    frames_.push_back(image.pixels);
  }

  void finish() override {
    std::vector<std::array<uint8_t, 3>> palette = median_cut(histogram_, kPaletteSize);
    palette.resize(kPaletteSize, palette.back());  // a GIF's palette has a power of two colours
    // The nearest palette colour to each of 64^3 levels.
    constexpr int levels = 1 << kLookupBits;
    std::vector<uint8_t> nearest(size_t(levels) * levels * levels);
    for (int r = 0; r < levels; ++r)
      for (int g = 0; g < levels; ++g)
        for (int b = 0; b < levels; ++b) {
          const int at[3] = {r * 255 / (levels - 1), g * 255 / (levels - 1), b * 255 / (levels - 1)};
          int best = 0, best_distance = 1 << 30;
          for (int p = 0; p < kPaletteSize; ++p) {
            int d = 0;
            for (int k = 0; k < 3; ++k) d += (at[k] - palette[size_t(p)][size_t(k)]) * (at[k] - palette[size_t(p)][size_t(k)]);
            if (d < best_distance) best_distance = d, best = p;
          }
          nearest[size_t((r * levels + g) * levels + b)] = uint8_t(best);
        }
    int error = 0;
    GifFileType* gif = EGifOpenFileName(path_.c_str(), false, &error);
    if (!gif) throw std::runtime_error(shown_ + ": cannot write the GIF: " + GifErrorString(error));
    try {
      write(gif, palette, nearest);
    } catch (...) {
      EGifCloseFile(gif, &error);
      throw;
    }
    if (EGifCloseFile(gif, &error) != GIF_OK) throw std::runtime_error(shown_ + ": cannot write the GIF: " + GifErrorString(error));
  }

 private:
  void check(int result, GifFileType* gif) const {
    if (result != GIF_OK) throw std::runtime_error(shown_ + ": cannot write the GIF: " + GifErrorString(gif->Error));
  }

  void write(GifFileType* gif, const std::vector<std::array<uint8_t, 3>>& palette, const std::vector<uint8_t>& nearest) {
    EGifSetGifVersion(gif, true);
    std::vector<GifColorType> colors;
    for (const auto& c : palette) colors.push_back({c[0], c[1], c[2]});
    ColorMapObject* map = GifMakeMapObject(kPaletteSize, colors.data());
    if (!map) throw std::runtime_error(shown_ + ": out of memory for the GIF's palette");
    const int screen = EGifPutScreenDesc(gif, settings_.width, settings_.height, 8, 0, map);
    GifFreeMapObject(map);
    check(screen, gif);
    // Netscape's extension: loop forever.
    static const unsigned char netscape[] = "NETSCAPE2.0", loop[] = {1, 0, 0};
    check(EGifPutExtensionLeader(gif, APPLICATION_EXT_FUNC_CODE), gif);
    check(EGifPutExtensionBlock(gif, 11, netscape), gif);
    check(EGifPutExtensionBlock(gif, 3, loop), gif);
    check(EGifPutExtensionTrailer(gif), gif);
    // A GIF counts delays in hundredths of a second, and browsers take one
    // under 2 as 10: 30 frames a second play at 33.
    GraphicsControlBlock control{DISPOSE_DO_NOT, false, std::max(2, int(std::lround(100.0 / settings_.fps))), NO_TRANSPARENT_COLOR};
    GifByteType extension[4];
    const size_t length = EGifGCBToExtension(&control, extension);
    static const int bayer[4][4] = {{0, 8, 2, 10}, {12, 4, 14, 6}, {3, 11, 1, 9}, {15, 7, 13, 5}};
    constexpr int levels = 1 << kLookupBits;
    const int w = settings_.width, h = settings_.height;
    std::vector<GifPixelType> row(static_cast<size_t>(w));
    for (const std::vector<uint8_t>& frame : frames_) {
      check(EGifPutExtension(gif, GRAPHICS_EXT_FUNC_CODE, int(length), extension), gif);
      check(EGifPutImageDesc(gif, 0, 0, w, h, false, nullptr), gif);
      for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
          const double offset = ((bayer[y & 3][x & 3] + 0.5) / 16.0 - 0.5) * kDitherSpread;
          int at[3];
          for (int k = 0; k < 3; ++k) {
            const double v = std::clamp(frame[size_t((y * w + x) * 3 + k)] + offset, 0.0, 255.0);
            at[k] = int(std::lround(v * (levels - 1) / 255.0));
          }
          row[size_t(x)] = nearest[size_t((at[0] * levels + at[1]) * levels + at[2])];
        }
        check(EGifPutLine(gif, row.data(), w), gif);
      }
    }
  }

  std::string path_, shown_;
  AnimationSettings settings_;
  Histogram histogram_;
  std::vector<std::vector<uint8_t>> frames_;
};

}  // namespace

std::unique_ptr<AnimationWriter> open_gif(const std::string& path, const std::string& shown, const AnimationSettings& settings) {
  return std::make_unique<GifWriter>(path, shown, settings);
}

}  // namespace umbra
