#include "image/contact_sheet.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "image/text_drawing.hpp"

namespace umbra {
namespace {

constexpr uint8_t kGround = 235, kInk = 40;
constexpr std::array<uint8_t, 3> kFailedGround = {246, 222, 222}, kFailedInk = {150, 20, 20};  // a tile with no picture
constexpr int kPad = 6;                       // around each tile
constexpr int kLabelHeight = kTextLineHeight;  // one line

}  // namespace

Image thumbnail(const Image& picture, int max_width) {
  const int factor = std::max(1, (picture.width + max_width - 1) / std::max(max_width, 1));
  if (factor <= 1 && picture.channels == 3) return picture;
  // A picture with alpha (a transparent background) is laid on the sheet's ground.
  const auto on_ground = [&](int x, int y, int c) {
    if (picture.channels != 4) return int(picture.at(x, y, c));
    const int a = picture.at(x, y, 3);
    return (picture.at(x, y, c) * a + kGround * (255 - a) + 127) / 255;
  };
  Image out(picture.width / factor, picture.height / factor, 3);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x)
      for (int c = 0; c < 3; ++c) {
        int sum = 0;
        for (int dy = 0; dy < factor; ++dy)
          for (int dx = 0; dx < factor; ++dx) sum += on_ground(x * factor + dx, y * factor + dy, c);
        out.at(x, y, c) = uint8_t((sum + factor * factor / 2) / (factor * factor));
      }
  return out;
}

namespace {

// The ways a label may be shortened to fit its tile, in the order a reader
// would have them: whole; the end of the file's stem, which tells a folder
// of numbered or named files apart better than their common extension;
// without the start every label on the sheet shares (said as "..."); cut in
// its middle, keeping the front and the back. Each is the longest of its
// kind that fits `width` ("" when none does).
constexpr int kShortenings = 4;
std::string shortened(const std::string& label, size_t shared, int width, int way) {
  const std::string rest = shared > 3 ? "..." + label.substr(shared) : label;
  const auto longest_fitting = [&](const std::function<std::string(size_t)>& keeping, size_t most) {
    for (size_t keep = most + 1; keep-- > 0;)
      if (const std::string s = keeping(keep); text_width(s) <= width) return s;
    return std::string();
  };
  switch (way) {
    case 0: return text_width(label) <= width ? label : "";
    case 2: return text_width(rest) <= width ? rest : "";
    case 1: {
      const size_t slash = label.rfind('/'), dot = label.rfind('.');
      const size_t start = slash == std::string::npos ? 0 : slash + 1;
      const std::string stem = label.substr(start, dot != std::string::npos && dot > start ? dot - start : std::string::npos);
      return longest_fitting([&](size_t keep) { return keep >= stem.size() ? stem : "..." + stem.substr(stem.size() - keep); },
                             stem.size());
    }
    default:
      return longest_fitting(
          [&](size_t keep) { return keep >= rest.size() ? rest : rest.substr(0, (keep + 1) / 2) + "..." + rest.substr(rest.size() - keep / 2); },
          rest.size());
  }
}

// Each label fitted to `width`: the first shortening that fits and that no
// other label shortened the same way shares; where none is its own, the
// first that fits.
std::vector<std::string> fitted(const std::vector<std::string>& labels, int width) {
  size_t shared = labels.size() > 1 ? labels[0].size() : 0;  // the start every label has
  for (const std::string& l : labels)
    shared = std::min<size_t>(shared, std::mismatch(l.begin(), l.end(), labels[0].begin(), labels[0].end()).first - l.begin());
  std::vector<std::vector<std::string>> ways(kShortenings);
  std::vector<std::map<std::string, size_t>> counts(kShortenings);
  for (int w = 0; w < kShortenings; ++w)
    for (const std::string& l : labels) ++counts[w][ways[w].emplace_back(shortened(l, shared, width, w))];
  std::vector<std::string> out;
  for (size_t k = 0; k < labels.size(); ++k) {
    std::string first;
    for (int w = 0; w < kShortenings && out.size() == k; ++w) {
      const std::string& s = ways[w][k];
      if (s.empty()) continue;
      if (first.empty()) first = s;
      if (counts[w][s] == 1) out.push_back(s);
    }
    if (out.size() == k) out.push_back(first);
  }
  return out;
}

}  // namespace

Image contact_sheet(const std::vector<SheetPicture>& pictures, int thumb_width, int columns) {
  std::vector<Image> thumbs;
  int tile_w = 1, tile_h = 1;
  bool any_picture = false;
  for (const SheetPicture& p : pictures) {
    thumbs.push_back(p.picture.width > 0 ? thumbnail(p.picture, thumb_width) : Image());
    tile_w = std::max(tile_w, thumbs.back().width);
    tile_h = std::max(tile_h, thumbs.back().height);
    any_picture = any_picture || p.picture.width > 0;
  }
  if (!any_picture) tile_w = thumb_width, tile_h = thumb_width * 3 / 4;  // failures alone: tiles of a picture's usual shape
  const int n = int(pictures.size());
  std::vector<std::string> labels;
  for (const SheetPicture& p : pictures) labels.push_back(printable(p.label));
  const std::vector<std::string> shown = fitted(labels, tile_w);
  if (columns <= 0) columns = std::max(1, int(std::ceil(std::sqrt(double(n)))));
  const int rows = std::max(1, (n + columns - 1) / columns);
  const int cell_w = tile_w + 2 * kPad, cell_h = tile_h + kLabelHeight + 2 * kPad;
  Image sheet(columns * cell_w, rows * cell_h, 3, kGround);
  for (int k = 0; k < n; ++k) {
    const int x0 = (k % columns) * cell_w + kPad, y0 = (k / columns) * cell_h + kPad;
    const Image& t = thumbs[size_t(k)];
    if (t.width == 0) {  // no picture: a pale tile that says why
      for (int y = 0; y < tile_h; ++y)
        for (int x = 0; x < tile_w; ++x)
          for (int c = 0; c < 3; ++c) sheet.at(x0 + x, y0 + y, c) = kFailedGround[c];
      const std::string note = printable(pictures[size_t(k)].note);
      draw_text(sheet, x0 + std::max(0, (tile_w - text_width(note)) / 2), y0 + (tile_h - kTextLineHeight) / 2, note, kFailedInk);
    }
    for (int y = 0; y < t.height; ++y)
      for (int x = 0; x < t.width; ++x)
        for (int c = 0; c < 3; ++c) sheet.at(x0 + x, y0 + y, c) = t.at(x, y, c);
    draw_text(sheet, x0, y0 + tile_h + 4, shown[size_t(k)], {kInk, kInk, kInk});
  }
  return sheet;
}

}  // namespace umbra
