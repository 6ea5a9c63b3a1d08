// R at initiation fitted to the dissipated energy (initial_rise.h): a record made from a known
// R(delta) gives it back, whatever came before the first dissipating reading.
#include "fiberbridge/analysis/initial_rise.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

using namespace fiberbridge::analysis;

namespace {

/// Growth readings of a DCB-like record: a from 100 mm in 1 mm steps, delta_root = k sqrt(da)
/// (the crack faces' opening behind a tip), R = J + s max(0, delta - h) and D its integral
/// over a times the width (trapezoid on a fine grid), plus `jump` dissipated before the first
/// reading and `creep` readings where the 1 % strain tip moves ahead without dissipation.
struct Made {
  std::vector<double> a, delta, D;
};

constexpr double width = 0.035, J = 200, s = 3.8e5, h = 0.1e-3;

double R_at(double delta) {
  return J + s * std::max(0.0, delta - h);
}

Made make(double jump, int creep, double noise_D = 0, unsigned seed = 1) {
  Made m;
  std::mt19937 gen(seed);
  std::normal_distribution<double> z(0, 1);
  for (int c = 1; c <= creep; ++c) { // the strain tip creeps 0.3 mm a reading, no dissipation
    m.a.push_back(0.1 + 0.3e-3 * c);
    m.delta.push_back(0.005e-3 * c);
    m.D.push_back(noise_D * z(gen));
  }
  const double a_start = m.a.empty() ? 0.1 : m.a.back();
  double D = jump, a_prev = a_start;
  auto delta_of = [&](double a) { return 0.06e-3 * std::sqrt((a - a_start) / 1e-3); };
  for (int i = 1; i <= 60; ++i) {
    const double a = a_start + 1e-3 * i;
    for (int k = 1; k <= 200; ++k) { // fine trapezoid between readings
      const double x0 = a_prev + (a - a_prev) * (k - 1) / 200, x1 = a_prev + (a - a_prev) * k / 200;
      D += width * 0.5 * (R_at(delta_of(x0)) + R_at(delta_of(x1))) * (x1 - x0);
    }
    a_prev = a;
    m.a.push_back(a);
    m.delta.push_back(delta_of(a));
    m.D.push_back(D + noise_D * z(gen));
  }
  return m;
}

} // namespace

// Exact data: J and the rise come back. The true hinge (0.1 mm) lies between two readings
// (0.085 and 0.104 mm) and the scan puts it on a reading, so the fit is exact only to that
// step: J within 1 %, the rise over the fitted readings within 10 %.
TEST(InitialRise, ExactDataGiveBackTheLaw) {
  const Made m = make(0, 0);
  const InitialRise f = fit_initial_rise(m.a, m.delta, m.D, 0, 0, width);
  ASSERT_TRUE(f.fitted) << f.why;
  EXPECT_NEAR(f.j_tip, J, 0.01 * J);
  ASSERT_GT(f.delta_end, h);
  EXPECT_NEAR(f.R(f.delta_end) - J, R_at(f.delta_end) - J, 0.1 * (R_at(f.delta_end) - J));
  EXPECT_EQ(f.onset, 0u);
}

// What dissipated before the first reading (a real record's jump at a0) is the free constant of
// the fit, not R: the same J as without it. A windowed slope from a0 would read it as R.
TEST(InitialRise, AJumpBeforeTheFirstReadingIsNotR) {
  const InitialRise plain =
      fit_initial_rise(make(0, 0).a, make(0, 0).delta, make(0, 0).D, 0, 0, width);
  const Made m = make(0.05, 0); // 0.05 J: 7 kJ/m^2 over the first 0.2 mm
  const InitialRise f = fit_initial_rise(m.a, m.delta, m.D, 0, 0, width);
  ASSERT_TRUE(f.fitted) << f.why;
  EXPECT_NEAR(f.j_tip, plain.j_tip, 1e-6 * J);
}

// A 1 % strain tip that creeps ahead while the load rises (readings without dissipation) is left
// out: the fit starts at the first reading whose D leaves the noise, and J is unchanged (2 %:
// the creep shifts the fitted readings' delta range).
TEST(InitialRise, ReadingsWithoutDissipationAreLeftOut) {
  const Made m = make(0, 5, 1e-7);
  const InitialRise f = fit_initial_rise(m.a, m.delta, m.D, 0, 1e-7, width);
  ASSERT_TRUE(f.fitted) << f.why;
  EXPECT_EQ(f.onset, 5u);
  EXPECT_NEAR(f.j_tip, J, 0.02 * J);
}

// Too few dissipating readings: not fitted, and why.
TEST(InitialRise, TooFewReadingsAreSaid) {
  Made m = make(0, 0);
  m.a.resize(4);
  m.delta.resize(4);
  m.D.resize(4);
  const InitialRise f = fit_initial_rise(m.a, m.delta, m.D, 0, 0, width);
  EXPECT_FALSE(f.fitted);
  EXPECT_NE(f.why.find("only 4"), std::string::npos) << f.why;
}
