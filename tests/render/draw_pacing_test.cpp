// Draws sent to a CPU rasteriser in fenced pieces (render/draw_pacing.hpp):
// how a draw is cut, and that the pacing is on where the GL bins on the CPU.
// That the pieces draw the same picture is checked by every mask test of a
// mesh larger than a piece (the engine, mannequin-devil) against the
// ray-cast reference.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <string>
#include <vector>

#include "render/draw_pacing.hpp"
#include "render/headless_context.hpp"

namespace umbra {
namespace {

TEST(DrawPacing, CutsADrawIntoPiecesOfAtMostTheLimitInOrder) {
  EXPECT_EQ(draw_pieces(10, 0), (std::vector<size_t>{10}));
  EXPECT_EQ(draw_pieces(10, 10), (std::vector<size_t>{10}));
  EXPECT_EQ(draw_pieces(10, 5), (std::vector<size_t>{5, 5}));
  EXPECT_EQ(draw_pieces(11, 5), (std::vector<size_t>{5, 5, 1}));
  EXPECT_EQ(draw_pieces(40000, kCpuRasteriserPiece), (std::vector<size_t>{16384, 16384, 7232}));
}

TEST(DrawPacing, LeavesNoPieceOfThreeTrianglesThatTheDrawWasNot) {
  // Nine vertices may be taken for a rectangle by llvmpipe.
  EXPECT_EQ(draw_pieces(8, 5), (std::vector<size_t>{4, 4}));
  EXPECT_EQ(draw_pieces(16387, kCpuRasteriserPiece), (std::vector<size_t>{16383, 4}));
  EXPECT_EQ(draw_pieces(3, 0), (std::vector<size_t>{3}));
  // Limits under five count as five, so that one less still leaves four.
  EXPECT_EQ(draw_pieces(7, 2), (std::vector<size_t>{5, 2}));
  EXPECT_EQ(draw_pieces(8, 4), (std::vector<size_t>{4, 4}));
  for (const size_t limit : {0, 1, 3, 4, 5, 6, 7, 16})
    for (size_t count = 1; count <= 200; ++count) {
      const std::vector<size_t> pieces = draw_pieces(count, limit);
      EXPECT_EQ(std::accumulate(pieces.begin(), pieces.end(), size_t(0)), count) << count << " by " << limit;
      for (const size_t piece : pieces) {
        EXPECT_GT(piece, 0u) << count << " by " << limit;
        if (limit > 0 && pieces.size() > 1) {
          EXPECT_LE(piece, std::max<size_t>(limit, 5)) << count << " by " << limit;
          EXPECT_NE(piece, 3u) << count << " by " << limit;
        }
      }
    }
}

TEST(DrawPacing, IsOnWhereTheGlRasterisesOnTheCpu) {
  HeadlessContext context(8, 8);
  if (context.platform().find("software") == std::string::npos && context.platform().find("OSMesa") == std::string::npos)
    GTEST_SKIP() << "a GPU draws here: " << context.description();
  EXPECT_EQ(draw_piece_limit_for_current_gl(), kCpuRasteriserPiece) << context.description();
}

}  // namespace
}  // namespace umbra
