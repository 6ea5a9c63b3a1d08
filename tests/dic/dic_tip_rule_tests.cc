// The threshold rule on hand-made crack-plane profiles (dic/crack_tip.h): where the run that
// starts at the notch root ends, what is bridged over and what is not.
#include "fiberbridge/dic/crack_tip.h"

#include <gtest/gtest.h>

using namespace fiberbridge::dic;

namespace {

/// Stations 1 mm apart from s = 0.
PlaneProfile profile(std::vector<double> eyy) {
  PlaneProfile p;
  for (std::size_t i = 0; i < eyy.size(); ++i)
    p.s.push_back(1e-3 * i);
  p.eyy = std::move(eyy);
  return p;
}

constexpr double h = 1e-3;

} // namespace

TEST(DicTipRule, LinearCrossingAtTheEndOfTheOpenRun) {
  // 0.03, 0.02, then 0.005: the crossing of 0.01 is 2/3 of the way from 1 mm to 2 mm.
  const auto r =
      locate_tip(profile({0.03, 0.02, 0.005, 0.001, 0.0, 0.001, 0.0, 0.0, 0.001, 0.0}), {}, h);
  ASSERT_TRUE(r.found);
  EXPECT_NEAR(r.s, 1e-3 + (0.02 - 0.01) / (0.02 - 0.005) * 1e-3, 1e-12);
  // sd: the 1 mm gap over sqrt(12) and the noise over the slope, so at least the gap's part.
  EXPECT_GE(r.sd, 1e-3 / std::sqrt(12.0));
}

TEST(DicTipRule, OneDipBridgedASpikeAheadIgnored) {
  // A single low station inside the run (a bad subset) is bridged; the spike at 7 mm lies past
  // two stations below the threshold and is not reached.
  const auto r =
      locate_tip(profile({0.05, 0.04, 0.002, 0.03, 0.02, 0.0, 0.0, 0.5, 0.0, 0.0, 0.0}), {}, h);
  EXPECT_NEAR(r.s, 4e-3 + (0.02 - 0.01) / 0.02 * 1e-3, 1e-12);
}

TEST(DicTipRule, FailedStationsOpenOnlyWhereTheRunIs) {
  // Failed stations right after open ones (correlation lost in the opened crack) extend the run:
  // the tip is midway between the last failed and the first valid station below.
  auto r = locate_tip(profile({0.05, NAN, NAN, 0.004, 0.0, 0.0, 0.0, 0.0}), {}, h);
  EXPECT_NEAR(r.s, 2.5e-3, 1e-12);
  EXPECT_NEAR(r.sd, 1e-3 / std::sqrt(12.0), 1e-12);
  // A failed station after one below the threshold does not.
  r = locate_tip(profile({0.05, 0.02, 0.004, NAN, 0.0, 0.0, 0.0, 0.0}), {}, h);
  EXPECT_NEAR(r.s, 1e-3 + (0.02 - 0.01) / (0.02 - 0.004) * 1e-3, 1e-12);
}

TEST(DicTipRule, ClosedAtTheRootBeyondTheViewAndNothingValid) {
  auto r = locate_tip(profile({0.004, 0.003, 0.002, 0.001}), {}, h);
  ASSERT_TRUE(r.found);
  EXPECT_EQ(r.s, 0); // not open to the threshold at the notch root: no growth
  r = locate_tip(profile({0.05, 0.04, 0.03, 0.02}), {}, h);
  EXPECT_TRUE(r.beyond_view);
  EXPECT_NE(r.note.find("left the view"), std::string::npos);
  r = locate_tip(profile({NAN, NAN}), {}, h);
  EXPECT_FALSE(r.found);
  EXPECT_NE(r.note.find("no valid point on the crack plane"), std::string::npos);
}

TEST(DicTipRule, ThresholdMovesTheTip) {
  const auto p = profile({0.04, 0.03, 0.02, 0.01, 0.005, 0.0, 0.0, 0.0, 0.0});
  TipRule low, high;
  low.threshold = 0.005;
  high.threshold = 0.02;
  EXPECT_NEAR(locate_tip(p, low, h).s, 4e-3, 1e-12);
  EXPECT_NEAR(locate_tip(p, high, h).s, 2e-3, 1e-12);
}
