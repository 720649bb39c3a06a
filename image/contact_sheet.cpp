#include "image/contact_sheet.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "image/text_drawing.hpp"

namespace umbra {
namespace {

constexpr uint8_t kGround = 235, kInk = 40;
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

// `label`, fitted to `width`: whole if it fits; else without the start that
// every label on the sheet shares (`shared` characters), said as "..."; else
// cut in its middle, so that the part that tells it from the others stays
// at its front and the file's own name at its end.
std::string fitted(const std::string& label, size_t shared, int width) {
  if (text_width(label) <= width) return label;
  const std::string rest = shared > 3 ? "..." + label.substr(shared) : label;
  if (text_width(rest) <= width) return rest;
  for (size_t keep = rest.size(); keep-- > 0;) {
    const std::string cut = rest.substr(0, (keep + 1) / 2) + "..." + rest.substr(rest.size() - keep / 2);
    if (text_width(cut) <= width) return cut;
  }
  return "";
}

}  // namespace

Image contact_sheet(const std::vector<SheetPicture>& pictures, int thumb_width, int columns) {
  std::vector<Image> thumbs;
  int tile_w = 1, tile_h = 1;
  for (const SheetPicture& p : pictures) {
    thumbs.push_back(thumbnail(p.picture, thumb_width));
    tile_w = std::max(tile_w, thumbs.back().width);
    tile_h = std::max(tile_h, thumbs.back().height);
  }
  const int n = int(pictures.size());
  std::vector<std::string> labels;
  for (const SheetPicture& p : pictures) labels.push_back(printable(p.label));
  size_t shared = labels.size() > 1 ? labels[0].size() : 0;  // the start every label has
  for (const std::string& l : labels) shared = std::min<size_t>(shared, std::mismatch(l.begin(), l.end(), labels[0].begin(), labels[0].end()).first - l.begin());
  if (columns <= 0) columns = std::max(1, int(std::ceil(std::sqrt(double(n)))));
  const int rows = std::max(1, (n + columns - 1) / columns);
  const int cell_w = tile_w + 2 * kPad, cell_h = tile_h + kLabelHeight + 2 * kPad;
  Image sheet(columns * cell_w, rows * cell_h, 3, kGround);
  for (int k = 0; k < n; ++k) {
    const int x0 = (k % columns) * cell_w + kPad, y0 = (k / columns) * cell_h + kPad;
    const Image& t = thumbs[size_t(k)];
    for (int y = 0; y < t.height; ++y)
      for (int x = 0; x < t.width; ++x)
        for (int c = 0; c < 3; ++c) sheet.at(x0 + x, y0 + y, c) = t.at(x, y, c);
    draw_text(sheet, x0, y0 + tile_h + 4, fitted(labels[size_t(k)], shared, tile_w), {kInk, kInk, kInk});
  }
  return sheet;
}

}  // namespace umbra
