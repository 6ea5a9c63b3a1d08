// The one Newton loop of the FEM (source/fem/newton_loop.h) on scalar strategies whose steps are
// known exactly: the line search, the kept trial and each way the loop stops.
#include "newton_loop.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace fiberbridge::fem;

namespace {

/// f(x) = atan(x) = 0 from x0: a plain Newton step overshoots and diverges for |x0| > 1.39.
struct Arctangent {
  double x, dx = 0, tried = 0;
  double tolerance = 1e-12;
  bool ascent = false; // step uphill: no trial can decrease the merit
  std::vector<double> accepted_alphas;
  int trials = 0;

  bool converged() const { return std::abs(std::atan(x)) <= tolerance; }
  void direction() {
    dx = -std::atan(x) * (1 + x * x);
    if (ascent)
      dx = -dx;
  }
  double merit() const { return std::abs(std::atan(x)); }
  double trial(double alpha) {
    ++trials;
    tried = x + alpha * dx;
    return std::abs(std::atan(tried));
  }
  void keep_trial(bool) {}
  bool accept(double alpha, bool last) {
    accepted_alphas.push_back(alpha);
    x = last ? tried : x + alpha * dx;
    return false;
  }
};

/// Merits of the trials given in order; records what the loop asked.
struct Scripted {
  std::vector<double> trial_merits;
  unsigned next = 0;
  std::vector<bool> kept; // keep_trial's argument, per call
  double accepted_alpha = -1;
  bool accepted_last = false;
  bool plateau = false; // accept() reports a plateau

  bool converged() const { return accepted_alpha >= 0 && !plateau; }
  void direction() {}
  double merit() const { return 1.0; }
  double trial(double) { return trial_merits.at(next++); }
  void keep_trial(bool search_goes_on) { kept.push_back(search_goes_on); }
  bool accept(double alpha, bool last) {
    accepted_alpha = alpha;
    accepted_last = last;
    return plateau;
  }
};

} // namespace

TEST(NewtonLoop, BacktrackingConvergesWherePlainNewtonDiverges) {
  // Plain Newton from 2: x -> 2 - atan(2) * 5 = -3.54, then +13.95: diverges.
  Arctangent f{2.0};
  unsigned n = 0;
  EXPECT_EQ(newton_loop(f, 25, n), NewtonStop::converged);
  EXPECT_NEAR(f.x, 0.0, 1e-12);
  ASSERT_FALSE(f.accepted_alphas.empty());
  EXPECT_LT(f.accepted_alphas.front(), 1.0); // the first step was cut back
  EXPECT_EQ(f.accepted_alphas.back(), 1.0);  // the quadratic phase takes full steps
  EXPECT_EQ(n, f.accepted_alphas.size());
}

TEST(NewtonLoop, AnUphillDirectionStopsWithoutDecreaseAfterEveryHalving) {
  Arctangent f{0.5};
  f.ascent = true;
  unsigned n = 0;
  EXPECT_EQ(newton_loop(f, 25, n), NewtonStop::no_decrease);
  EXPECT_EQ(n, 1u); // the failing iteration is counted
  EXPECT_EQ(f.trials, kLineSearchTrials);
  EXPECT_EQ(f.x, 0.5); // the state is left where it was
}

TEST(NewtonLoop, TheIterationLimitIsReportedAfterTheLastTest) {
  Arctangent f{0.5};
  f.tolerance = 0; // never met
  unsigned n = 0;
  EXPECT_EQ(newton_loop(f, 3, n), NewtonStop::iteration_limit);
  EXPECT_EQ(n, 3u);
  EXPECT_EQ(f.accepted_alphas.size(), 3u);
}

TEST(NewtonLoop, TheBestTrialIsTakenWhenNoneDecreasesEnough) {
  // Merit 1 now. alpha 1: worse; 1/2: better but above 1 - 1e-4 / 2 (not enough); the rest
  // worse: the loop takes 1/2, tells the strategy to keep that trial (the search went on past
  // it) and that it is not the last one tried.
  Scripted s;
  s.trial_merits = {1.5, 0.99999, 1.2, 1.1, 1.05, 1.01, 1.001, 1.0001};
  unsigned n = 0;
  EXPECT_EQ(newton_loop(s, 1, n), NewtonStop::converged);
  EXPECT_EQ(s.next, 8u);
  EXPECT_EQ(s.accepted_alpha, 0.5);
  EXPECT_FALSE(s.accepted_last);
  EXPECT_EQ(s.kept, std::vector<bool>{true});
}

TEST(NewtonLoop, ASufficientDecreaseEndsTheSearchAtThatTrial) {
  // alpha 1: worse; 1/2: 0.9 <= 1 - 0.5e-4: taken at once, as the last trial, nothing kept for
  // later (the search stops there).
  Scripted s;
  s.trial_merits = {1.5, 0.9};
  unsigned n = 0;
  EXPECT_EQ(newton_loop(s, 5, n), NewtonStop::converged);
  EXPECT_EQ(s.next, 2u);
  EXPECT_EQ(s.accepted_alpha, 0.5);
  EXPECT_TRUE(s.accepted_last);
  EXPECT_EQ(s.kept, std::vector<bool>{false});
  EXPECT_EQ(n, 1u);
}

TEST(NewtonLoop, APlateauReportedByTheStrategyEndsConverged) {
  Scripted s;
  s.plateau = true;
  s.trial_merits = {0.95};
  unsigned n = 0;
  EXPECT_EQ(newton_loop(s, 25, n), NewtonStop::converged);
  EXPECT_EQ(n, 1u);
}
