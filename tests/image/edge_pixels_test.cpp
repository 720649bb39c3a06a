// Which pixels of a one-sample picture take antialiasing's samples: those
// that differ from a neighbour (of eight) by more than the bound on a channel.
#include <gtest/gtest.h>

#include "image/edge_pixels.hpp"

namespace umbra {
namespace {

std::vector<uint8_t> marked(const std::vector<std::pair<int, int>>& pixels, int width, int height) {
  std::vector<uint8_t> m(size_t(width) * size_t(height), 0);
  for (const auto& [x, y] : pixels) m[size_t(y) * size_t(width) + size_t(x)] = 1;
  return m;
}

TEST(EdgePixels, APixelPastTheBoundFromItsNeighboursMarksItAndAllEightOfThem) {
  Image image(5, 4, 3, 100);
  image.at(2, 1, 1) = 100 + kEdgeLevels + 1;
  EXPECT_EQ(edge_pixels(image), marked({{1, 0}, {2, 0}, {3, 0}, {1, 1}, {2, 1}, {3, 1}, {1, 2}, {2, 2}, {3, 2}}, 5, 4));
  // At the bound itself, no edge.
  image.at(2, 1, 1) = 100 + kEdgeLevels;
  EXPECT_EQ(edge_pixels(image), marked({}, 5, 4));
  image.at(2, 1, 1) = 100 - kEdgeLevels - 1;
  EXPECT_EQ(edge_pixels(image, kEdgeLevels + 1), marked({}, 5, 4));
  EXPECT_EQ(edge_pixels(image, kEdgeLevels).size(), 20u);
}

TEST(EdgePixels, AStepMarksTheColumnsEitherSideOfIt) {
  Image image(4, 3, 3, 0);
  for (int y = 0; y < 3; ++y)
    for (int x = 2; x < 4; ++x) image.at(x, y, 2) = 255;
  EXPECT_EQ(edge_pixels(image), marked({{1, 0}, {2, 0}, {1, 1}, {2, 1}, {1, 2}, {2, 2}}, 4, 3));
}

TEST(EdgePixels, ASmoothRampIsNoEdge) {
  Image image(64, 2, 3, 0);
  for (int x = 0; x < 64; ++x)
    for (int c = 0; c < 3; ++c) image.at(x, 0, c) = image.at(x, 1, c) = uint8_t(x * kEdgeLevels);
  EXPECT_EQ(edge_pixels(image), marked({}, 64, 2));
}

TEST(EdgePixels, CoverageCountsWhereThePictureHasAlpha) {
  Image image(3, 3, 4, 0);
  image.at(2, 2, 3) = 255;  // the one pixel a surface covers, its colour black as the rest
  EXPECT_EQ(edge_pixels(image), marked({{1, 1}, {2, 1}, {1, 2}, {2, 2}}, 3, 3));
}

}  // namespace
}  // namespace umbra
