#include "mesh/predicates/orientation.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace umbra {
namespace {

TEST(Orientation, SignOfTheTripleProduct) {
  const glm::dvec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  EXPECT_EQ(orientation(a, b, c, {0, 0, 1}), 1);   // (AB x AC) = +z
  EXPECT_EQ(orientation(a, b, c, {0, 0, -1}), -1);
  EXPECT_EQ(orientation(a, c, b, {0, 0, 1}), -1);  // swapping two vertices flips it
  EXPECT_EQ(orientation(a, b, c, {5, -3, 0}), 0);
}

TEST(Orientation, ExactWhereTheDoubleTripleProductUnderflows) {
  // d = midpoint of ab (exact in doubles) lifted by the smallest denormal: the
  // double triple product 0.01 * 4.9e-324 underflows to 0; the exact sign does not.
  const glm::dvec3 a(0.1, 0, 0), b(0, 0.1, 0), c(0, 0, 0.1);  // normal (b-a) x (c-a) ~ (1, 1, 1)
  const double tiny = std::numeric_limits<double>::denorm_min();
  EXPECT_EQ(orientation(a, b, c, {0.05, 0.05, 0.0}), 0);
  EXPECT_EQ(orientation(a, b, c, {0.05, 0.05, tiny}), 1);
  EXPECT_EQ(orientation(a, b, c, {0.05, 0.05, -tiny}), -1);
}

TEST(Collinear, RepeatedAndCollinearPoints) {
  EXPECT_TRUE(collinear({0, 0, 0}, {0, 0, 0}, {1, 2, 3}));
  EXPECT_TRUE(collinear({0, 0, 0}, {1, 1, 1}, {3, 3, 3}));
  EXPECT_FALSE(collinear({0, 0, 0}, {1, 1, 1}, {3, 3, 3.0000001}));
}

}  // namespace
}  // namespace umbra
