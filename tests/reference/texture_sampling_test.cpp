// The reference's bilinear filter against hand-computed values: it must be
// the GL's (texel centres at (i + 1/2) / n, the wrap modes on texel indices).
#include <gtest/gtest.h>

#include "reference/texture_sampling.hpp"

namespace umbra {
namespace {

// 2 x 2 texels: red, green / blue, white (row 0 at the top, v = 0).
TextureImage two_by_two(TextureImage::Wrap wrap) {
  TextureImage t;
  t.width = t.height = 2;
  t.rgba = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255};
  t.wrap_u = t.wrap_v = wrap;
  return t;
}

void expect_near(const glm::dvec3& got, const glm::dvec3& want) {
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], 1e-12) << c;
}

TEST(TextureSampling, ATexelCentreGivesThatTexel) {
  const TextureImage t = two_by_two(TextureImage::Wrap::kRepeat);
  expect_near(sample_bilinear(t, {0.25, 0.25}), {1, 0, 0});
  expect_near(sample_bilinear(t, {0.75, 0.25}), {0, 1, 0});
  expect_near(sample_bilinear(t, {0.25, 0.75}), {0, 0, 1});
  expect_near(sample_bilinear(t, {0.75, 0.75}), {1, 1, 1});
}

TEST(TextureSampling, BetweenCentresTheTexelsBlendByDistance) {
  const TextureImage t = two_by_two(TextureImage::Wrap::kRepeat);
  expect_near(sample_bilinear(t, {0.5, 0.25}), {0.5, 0.5, 0});      // halfway from red to green
  expect_near(sample_bilinear(t, {0.375, 0.25}), {0.75, 0.25, 0});  // a quarter of the way
  expect_near(sample_bilinear(t, {0.5, 0.5}), {0.5, 0.5, 0.5});     // all four alike
}

TEST(TextureSampling, AtTheEdgeEachWrapModeTakesItsNeighbour) {
  // u = 0 lies halfway between texel 0's centre and texel -1's.
  expect_near(sample_bilinear(two_by_two(TextureImage::Wrap::kRepeat), {0.0, 0.25}), {0.5, 0.5, 0});       // -1 is texel 1
  expect_near(sample_bilinear(two_by_two(TextureImage::Wrap::kClampToEdge), {0.0, 0.25}), {1, 0, 0});      // -1 is texel 0
  expect_near(sample_bilinear(two_by_two(TextureImage::Wrap::kMirroredRepeat), {0.0, 0.25}), {1, 0, 0});   // -1 mirrors to 0
  // One whole period on: repeat is the same, mirrored repeat is turned over.
  expect_near(sample_bilinear(two_by_two(TextureImage::Wrap::kRepeat), {1.25, 0.25}), {1, 0, 0});
  expect_near(sample_bilinear(two_by_two(TextureImage::Wrap::kMirroredRepeat), {1.25, 0.25}), {0, 1, 0});
  expect_near(sample_bilinear(two_by_two(TextureImage::Wrap::kClampToEdge), {-3.0, 7.0}), {0, 0, 1});
}

}  // namespace
}  // namespace umbra
