// Unit tests of ISO 15024 / ASTM D5528's F and N
// (include/fiberbridge/specimen/large_displacement.h) against the standard's formulas evaluated by
// hand in exact fractions. The elastica check of F/N is
// RecordReduction.ElasticaDcbIsReducedExactlyWithFOverN (tests/analysis).
#include "fiberbridge/specimen/large_displacement.h"

#include <gtest/gtest.h>

using namespace fiberbridge::specimen;

// delta = 20 mm, a = 100 mm, l1 = 5 mm: delta/a = 1/5, delta l1/a^2 = 1/100.
constexpr double delta = 0.020, a = 0.100, l1 = 0.005;
// Tolerance: the values are sums of four terms of order 1e-2 computed in doubles; 1e-14 is a few
// ulps of 1 and far below the smallest term (3/250 = 0.012), so a wrong coefficient fails.
constexpr double tol = 1e-14;

TEST(LargeDisplacement, FMatchesIso15024) {
  // F = 1 - 3/10 (1/25) - 3/2 (1/100) = 1 - 3/250 - 3/200 = 973/1000.
  EXPECT_NEAR(large_displacement_F(delta, a, l1), 973.0 / 1000.0, tol);
}

TEST(LargeDisplacement, NWithoutEndBlocksKeepsTheElasticaTerm) {
  // l2 = 0: N = 1 - 9/8 (1/100) - 9/35 (1/25) = 1 - 9/800 - 9/875.
  EXPECT_NEAR(end_block_N(delta, a, l1, 0.0), 1 - 9.0 / 800.0 - 9.0 / 875.0, tol);
}

TEST(LargeDisplacement, NWithEndBlocks) {
  // l2 = 20 mm: l2/a = 1/5, N = 1 - 1/125 - 9/8 (24/25) (1/100) - 9/35 (1/25).
  const double expected = 1 - 1.0 / 125.0 - 9.0 / 8.0 * 24.0 / 25.0 / 100.0 - 9.0 / 875.0;
  EXPECT_NEAR(end_block_N(delta, a, l1, 0.020), expected, tol);
}

TEST(LargeDisplacement, SmallOpeningsNeedNoCorrection) {
  // delta -> 0: F = 1, and N = 1 - (l2/a)^3 (the stiff end block alone).
  EXPECT_DOUBLE_EQ(large_displacement_F(0.0, a, l1), 1.0);
  EXPECT_DOUBLE_EQ(end_block_N(0.0, a, l1, 0.0), 1.0);
  EXPECT_NEAR(end_block_N(0.0, a, l1, 0.020), 1 - 1.0 / 125.0, tol);
}

TEST(LargeDisplacement, DependsOnDeltaOverAAndL1OverAOnly) {
  // Both are dimensionless: scaling every length by 7 leaves them unchanged (to round-off).
  EXPECT_NEAR(large_displacement_F(7 * delta, 7 * a, 7 * l1), large_displacement_F(delta, a, l1),
              tol);
  EXPECT_NEAR(end_block_N(7 * delta, 7 * a, 7 * l1, 7 * 0.02), end_block_N(delta, a, l1, 0.02),
              tol);
}
