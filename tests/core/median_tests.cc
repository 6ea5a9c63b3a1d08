// The two medians (core/median.h; issue 40 item 6): what each returns, and that the symmetric one
// is bit for bit the campaign's 0.5 sample quantile it replaced.
#include "fiberbridge/core/median.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>

using namespace fiberbridge;

namespace {
constexpr double nan_ = std::numeric_limits<double>::quiet_NaN();
constexpr double inf_ = std::numeric_limits<double>::infinity();

/// The campaign's type-7 quantile at q = 0.5, as analysis::sample_quantile computes it.
double type7_half(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const double h = 0.5 * (v.size() - 1);
  const std::size_t lo = static_cast<std::size_t>(std::floor(h));
  const std::size_t hi = std::min(lo + 1, v.size() - 1);
  return v[lo] + (h - lo) * (v[hi] - v[lo]);
}
} // namespace

TEST(Median, OddCountGivesTheMiddleValueForBoth) {
  EXPECT_EQ(median({3, 1, 2}), 2);
  EXPECT_EQ(median_upper({3, 1, 2}), 2);
  EXPECT_EQ(median({5}), 5);
  EXPECT_EQ(median_upper({5}), 5);
}

TEST(Median, EvenCountHalfwayOrTheUpperMiddleValue) {
  EXPECT_EQ(median({4, 1, 3, 2}), 2.5);
  EXPECT_EQ(median_upper({4, 1, 3, 2}), 3);
  EXPECT_EQ(median({1, 2}), 1.5);
  EXPECT_EQ(median_upper({1, 2}), 2);
  EXPECT_EQ(median({7, 7}), 7);
}

TEST(Median, NonFiniteValuesAreLeftOutAndNoneGivesNaN) {
  EXPECT_EQ(median({nan_, 1, 3, inf_, 2}), 2);
  EXPECT_EQ(median_upper({nan_, 4, -inf_, 1}), 4);
  EXPECT_EQ(median({nan_, 4, -inf_, 1}), 2.5);
  EXPECT_TRUE(std::isnan(median({})));
  EXPECT_TRUE(std::isnan(median_upper({})));
  EXPECT_TRUE(std::isnan(median({nan_, inf_})));
  EXPECT_TRUE(std::isnan(median_upper({nan_})));
}

TEST(Median, SymmetricMedianIsBitForBitTheHalfSampleQuantile) {
  // The campaign's G_ss screening used sample_quantile(v, 0.5): its numbers must not move.
  std::mt19937 rng(40);
  std::lognormal_distribution<double> d(5, 1);
  for (std::size_t n = 1; n < 60; ++n)
    for (int rep = 0; rep < 20; ++rep) {
      std::vector<double> v(n);
      for (auto& x : v)
        x = d(rng);
      const double a = median(v), b = type7_half(v);
      EXPECT_EQ(std::memcmp(&a, &b, sizeof a), 0) << "n = " << n;
    }
}

TEST(Median, UpperMedianIsAlwaysOneOfTheValues) {
  // The robust scales (reading spacings, MAD noise levels) use it: nth_element at n/2.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> d(-1, 1);
  for (std::size_t n = 1; n < 40; ++n) {
    std::vector<double> v(n);
    for (auto& x : v)
      x = d(rng);
    std::vector<double> s = v;
    std::sort(s.begin(), s.end());
    EXPECT_EQ(median_upper(v), s[n / 2]);
  }
}
