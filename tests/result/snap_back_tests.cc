// The one snap-back detector (result::find_snap_backs, rcurve.h; issue 30 item 5): the FEM's and
// the beam's notes both read it.
#include "fiberbridge/result/rcurve.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

using namespace fiberbridge;

namespace {

std::vector<result::RCurvePoint> rows_with_openings(const std::vector<double>& openings) {
  std::vector<result::RCurvePoint> rows;
  for (std::size_t i = 0; i < openings.size(); ++i) {
    result::RCurvePoint p;
    p.a = 0.05 + 1e-3 * double(i);
    p.load_point_opening = openings[i];
    rows.push_back(p);
  }
  return rows;
}

} // namespace

TEST(SnapBack, StretchesFromTheMaximumToTheRecovery) {
  // Falls after row 2 (2.0), lowest at row 4, back above 2.0 at row 6; falls again after row 7
  // and the curve ends before it recovers.
  const auto s =
      result::find_snap_backs(rows_with_openings({0, 1, 2, 1.5, 1.2, 1.8, 2.5, 3, 2.9, 2.95}));
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].from, 2u);
  EXPECT_EQ(s[0].lowest, 4u);
  EXPECT_EQ(s[0].to, 6u);
  EXPECT_EQ(s[1].from, 7u);
  EXPECT_EQ(s[1].lowest, 8u);
  EXPECT_EQ(s[1].to, 10u) << "no recovery: the end of the curve";
}

TEST(SnapBack, NoneOnARisingOrFlatCurveAndNaNStartsNone) {
  EXPECT_TRUE(result::find_snap_backs(rows_with_openings({0, 1, 1, 2, 3})).empty());
  EXPECT_TRUE(result::find_snap_backs(rows_with_openings({})).empty());
  EXPECT_TRUE(result::find_snap_backs(rows_with_openings({1})).empty());
  const double nan = result::not_available;
  const auto s = result::find_snap_backs(rows_with_openings({0, nan, 1, 0.5}));
  ASSERT_EQ(s.size(), 1u);
  EXPECT_EQ(s[0].from, 2u);
  EXPECT_EQ(s[0].to, 4u);
  // Recovering to exactly the earlier maximum ends the stretch (the test reaches that state).
  const auto eq = result::find_snap_backs(rows_with_openings({0, 2, 1, 2, 1.5}));
  ASSERT_EQ(eq.size(), 2u);
  EXPECT_EQ(eq[0].to, 3u);
  EXPECT_EQ(eq[1].from, 3u);
}

TEST(SnapBack, JumpedRowsAreTheRowsBelowAnEarlierOpening) {
  // The beam's note counted the rows below the largest earlier opening; the FEM's note names the
  // stretches. On any finite curve the rows inside the stretches are exactly those rows.
  std::mt19937 rng(30);
  std::uniform_real_distribution<double> step(-1.0, 1.5);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<double> x = {0};
    for (int i = 0; i < 40; ++i)
      x.push_back(x.back() + step(rng));
    std::vector<bool> inside(x.size(), false);
    for (const auto& s : result::find_snap_backs(rows_with_openings(x))) {
      ASSERT_LT(s.from, s.lowest);
      ASSERT_LT(s.lowest, s.to);
      for (std::size_t k = s.from + 1; k < s.to; ++k)
        inside[k] = true;
    }
    double max_before = x[0];
    for (std::size_t k = 1; k < x.size(); ++k) {
      EXPECT_EQ(inside[k], x[k] < max_before) << "trial " << trial << ", row " << k;
      max_before = std::max(max_before, x[k]);
    }
  }
}
