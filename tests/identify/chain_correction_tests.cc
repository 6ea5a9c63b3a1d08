// The chain corrected by simulation (identify/chain_correction.h): the simulated record follows the
// machine's path and the record's own layout; the fixed point is found where it exists, the
// alternating case is averaged, and a chain that fails or diverges is said, never passed on.
#include "fiberbridge/identify/chain_correction.h"

#include "fiberbridge/core/error.h"
#include "fiberbridge/core/units.h"

#include <gtest/gtest.h>

#include <cmath>

namespace fiberbridge::identify {
namespace {

using units::kPa;
using units::mm;

result::RCurvePoint state(double a_mm, double opening_mm, double load, double root_mm) {
  result::RCurvePoint p;
  p.a = a_mm * mm;
  p.load_point_opening = opening_mm * mm;
  p.load = load;
  p.delta_root = root_mm * mm;
  return p;
}

TEST(SimulatedRecord, FollowsTheMachinePathAtTheRecordsOpenings) {
  result::SimulationResult sim;
  sim.rcurve = {state(100, 2.0, 300, 0.0), state(102, 2.5, 290, 0.1),
                state(104, 2.4, 250, 0.2), // snap-back: the opening falls below 2.5 mm
                state(106, 3.0, 240, 0.3)};
  analysis::TestRecord measured;
  measured.name = "r";
  measured.opening = {0, 1.0 * mm, 2.0 * mm, 2.5 * mm, 2.75 * mm, 2.9 * mm, 3.5 * mm};
  measured.load = std::vector<double>(7, 1.0);
  measured.time = {0, 1, 2, 3, 4, 5, 6};
  const double nan = std::nan("");
  // Readings on rows 2, 3 and 4, row 5 repeats row 4's (a stale reading), row 1 has none.
  measured.crack_length = {100 * mm, nan, 101 * mm, 102 * mm, 103 * mm, 103 * mm, 105 * mm};
  measured.delta_root = {0, 0, 0.01 * mm, 0.1 * mm, 0.2 * mm, 0.2 * mm, 0.3 * mm};
  std::vector<std::string> notes;
  const analysis::TestRecord r = simulated_record(measured, sim, notes);
  ASSERT_EQ(r.opening.size(), 6u); // the 3.5 mm row is past the simulation's 3.0 mm
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("1 rows past"), std::string::npos) << notes[0];
  // Elastic from the origin to initiation: 150 N at half of initiation's 2 mm.
  EXPECT_NEAR(r.load[1], 150, 1e-9);
  EXPECT_NEAR(r.load[2], 300, 1e-9);
  // At the largest opening before the snap-back: the state there, before the load drops.
  EXPECT_NEAR(r.load[3], 290, 1e-9);
  // The machine holds 2.5 mm while the load drops to the returning branch, (2.4 mm, 250 N) to
  // (3.0 mm, 240 N) at 2.5 mm: 248.33 N, a 104.33 mm; 2.75 mm is halfway from there to 3.0 mm.
  EXPECT_NEAR(r.load[4], 0.5 * (250 - 10.0 / 6 + 240), 1e-9);
  EXPECT_NEAR(r.crack_length[4], 0.5 * (104 + 2.0 / 6 + 106) * mm, 1e-12);
  EXPECT_NEAR(r.delta_root[4], 0.5 * (0.2 + 0.1 / 6 + 0.3) * mm, 1e-12);
  // The crack column keeps the record's layout: none where it had none, the last simulated
  // reading repeated where it repeated its own.
  EXPECT_TRUE(std::isnan(r.crack_length[1]));
  EXPECT_EQ(r.crack_length[5], r.crack_length[4]);
  EXPECT_EQ(r.time[5], 5);
}

TEST(SimulatedRecord, TheCrackDoesNotShortenWhenTheOpeningDips) {
  // A lab record whose opening dips with noise between two crack readings: the simulated crack
  // follows the largest opening so far, never shorter than the reading before (reduce refuses a
  // crack reading that decreases).
  result::SimulationResult sim;
  sim.rcurve = {state(100, 2.0, 300, 0.0), state(110, 3.0, 250, 1.0)};
  analysis::TestRecord measured;
  measured.name = "r";
  measured.opening = {0, 2.5 * mm, 2.49 * mm, 2.6 * mm};
  measured.load = std::vector<double>(4, 1.0);
  measured.crack_length = {100 * mm, 104 * mm, 104.5 * mm, 106 * mm};
  std::vector<std::string> notes;
  const analysis::TestRecord r = simulated_record(measured, sim, notes);
  ASSERT_EQ(r.crack_length.size(), 4u);
  EXPECT_NEAR(r.crack_length[1], 105 * mm, 1e-12);
  EXPECT_NEAR(r.crack_length[2], 105 * mm, 1e-12); // at 2.5 mm, not at the dip's 2.49 mm
  EXPECT_NEAR(r.load[2], 300 - 50 * 0.49, 1e-9);   // the load at the opening itself
  EXPECT_NEAR(r.crack_length[3], 106 * mm, 1e-12);
}

TEST(SimulatedRecord, AFlatStretchReadsTheSameCrackToTheLastBit) {
  // Before initiation the crack is a0 on every row: an interpolation that drifted by an ulp would
  // read as a crack that shortens, which reduce refuses (a re-exported lab record met it).
  result::SimulationResult sim;
  sim.rcurve = {state(35.02, 3.046331, 300, 0.0), state(35.4599, 3.126582, 290, 0.1)};
  analysis::TestRecord measured;
  measured.name = "r";
  for (int i = 0; i <= 300; ++i) {
    measured.opening.push_back(0.01 * i * mm);
    measured.load.push_back(1.0);
    measured.crack_length.push_back(i == 0 ? 35.02 * mm : (i % 3 ? 35.02 * mm : NAN));
  }
  std::vector<std::string> notes;
  const analysis::TestRecord r = simulated_record(measured, sim, notes);
  for (std::size_t i = 0; i < r.crack_length.size(); ++i) {
    if (std::isfinite(r.crack_length[i])) {
      EXPECT_EQ(r.crack_length[i], 35.02 * mm) << "row " << i;
    }
  }
}

TEST(SimulatedRecord, NoCriticalStateIsAnError) {
  std::vector<std::string> notes;
  analysis::TestRecord measured;
  measured.name = "r";
  measured.opening = {0, 1 * mm};
  measured.load = {0, 1};
  EXPECT_THROW(simulated_record(measured, result::SimulationResult{}, notes), ComputationError);
}

/// A forward model that keeps the law it was last asked to run (`running`): a test's chain
/// "measures" that law with a known bias, so the chain depends on the law as a real one does
/// through the simulated records (which carry nothing the test chains read).
struct Rig {
  ChainEstimate running;
  int runs = 0;
  ForwardModel model() {
    ForwardModel m;
    m.name = "rig";
    m.run = [this](const specimen::Specimen&, const specimen::Material&,
                   const law::TractionLaw& law, double j_tip, double) {
      const auto& p = dynamic_cast<const law::PiecewiseLinearLaw&>(law).points();
      running.j_tip = j_tip;
      running.law = {p[1].delta, p[1].sigma, p[2].delta, p[2].sigma, p[3].delta};
      ++runs;
      result::SimulationResult r;
      r.rcurve = {state(100, 2.0, 300, 0.0), state(110, 3.0, 280, 1.0)};
      return r;
    };
    return m;
  }
};

ChainEstimate truth() {
  ChainEstimate e;
  e.law = {0.1 * mm, 320 * kPa, 1.0 * mm, 190 * kPa, 3.5 * mm};
  e.j_tip = 200;
  return e;
}

/// The bias a smooth chain adds: sigma1 +8 % + 3 kPa, sigma2 -3 %, J_tip -4 %, delta_c +3 %.
ChainEstimate biased(const ChainEstimate& p) {
  ChainEstimate c = p;
  c.law.s1 = 1.08 * p.law.s1 + 3 * kPa;
  c.law.s2 = 0.97 * p.law.s2;
  c.j_tip = 0.96 * p.j_tip;
  c.law.dc = 1.03 * p.law.dc;
  return c;
}

std::vector<analysis::TestRecord> one_record() {
  analysis::TestRecord r;
  r.name = "r";
  r.opening = {0, 1 * mm, 2 * mm, 2.5 * mm, 3 * mm};
  r.load = {0, 150, 300, 290, 280};
  r.crack_length = {100 * mm, 100 * mm, 100 * mm, 105 * mm, 110 * mm};
  r.delta_root = {0, 0, 0, 0.5 * mm, 1 * mm};
  return {r};
}

TEST(ChainCorrection, UndoesASmoothBias) {
  Rig rig;
  const MeasuringChain chain = [&](const std::vector<analysis::TestRecord>& records) {
    EXPECT_EQ(records.size(), 1u);
    return biased(rig.running);
  };
  const ChainCorrection c =
      correct_chain(one_record(), {specimen::Specimen{}}, specimen::Material{}, biased(truth()),
                    chain, rig.model());
  ASSERT_TRUE(c.converged) << (c.notes.empty() ? "" : c.notes.back());
  // Tolerance: the correction stops within 1 % (its default) of the measured estimate in the
  // chain's image; the chain's slope is near 1, so the law is within about 1 % too.
  const ChainEstimate t = truth();
  EXPECT_NEAR(c.corrected.law.s1, t.law.s1, 0.01 * t.law.s1);
  EXPECT_NEAR(c.corrected.law.s2, t.law.s2, 0.01 * t.law.s1);
  EXPECT_NEAR(c.corrected.j_tip, t.j_tip, 0.01 * t.j_tip);
  EXPECT_NEAR(c.corrected.law.dc, t.law.dc, 0.01 * t.law.dc);
  EXPECT_EQ(c.forward_runs, static_cast<int>(c.steps.size()));
  EXPECT_EQ(rig.runs, c.forward_runs);
  EXPECT_GT(c.steps.front().mismatch, 0.05); // the bias was there to undo
}

/// The smooth bias plus a step of +-`step` (a fraction of sigma1) where the law's sigma1 crosses
/// the true one, as the chain's automatic choices flip with the data. The step goes the way that
/// leaves no fixed point: below the truth the chain reads low, above it high, so each side's
/// solution lies on the other side.
ChainEstimate stepped(const ChainEstimate& p, double step) {
  ChainEstimate c = biased(p);
  c.law.s1 *= p.law.s1 < truth().law.s1 ? 1 - step : 1 + step;
  return c;
}

/// The correction of biased(truth()) by a chain with steps of +-`step`.
ChainCorrection correct_stepped(double step) {
  Rig rig;
  const MeasuringChain chain = [&](const std::vector<analysis::TestRecord>&) {
    return stepped(rig.running, step);
  };
  return correct_chain(one_record(), {specimen::Specimen{}}, specimen::Material{}, biased(truth()),
                       chain, rig.model());
}

TEST(ChainCorrection, FindsTheLawToTheChainsOwnSteps) {
  // Steps of +-2 % in sigma1: no single law meets the 1 % tolerance. The mean of the trailing
  // laws is run once more, and accepted because the chain lands on it within its own steps; the
  // note says to what resolution the law is found.
  const ChainCorrection c = correct_stepped(0.02);
  ASSERT_TRUE(c.converged) << (c.notes.empty() ? "" : c.notes.back());
  ASSERT_FALSE(c.notes.empty());
  EXPECT_NE(c.notes.back().find("found to that resolution"), std::string::npos) << c.notes.back();
  // The last step is the chain on the law handed on, within the chain's steps (4 % peak to
  // peak, so 4 % of the larger stress at most).
  EXPECT_LE(c.steps.back().mismatch, 0.04);
  // 3 %: the +-2 % steps, through the chain's slope of 1.08.
  EXPECT_NEAR(c.corrected.law.s1, truth().law.s1, 0.03 * truth().law.s1);
}

TEST(ChainCorrection, AChainTooCoarseForTheLawIsSaid) {
  // Steps of +-8 %: beyond 5 tolerances, the law cannot be found to a resolution worth handing on.
  const ChainCorrection c = correct_stepped(0.08);
  EXPECT_FALSE(c.converged);
  ASSERT_FALSE(c.notes.empty());
  EXPECT_EQ(c.notes.back().rfind("not corrected", 0), 0u) << c.notes.back();
}

TEST(ChainCorrection, AChainThatFailsIsSaidNotPassedOn) {
  Rig rig;
  const MeasuringChain chain = [](const std::vector<analysis::TestRecord>&) -> ChainEstimate {
    throw ComputationError("no steady state in the simulated records");
  };
  const ChainCorrection c = correct_chain(one_record(), {specimen::Specimen{}},
                                          specimen::Material{}, truth(), chain, rig.model());
  EXPECT_FALSE(c.converged);
  ASSERT_FALSE(c.notes.empty());
  EXPECT_NE(c.notes.back().find("no steady state"), std::string::npos) << c.notes.back();
}

TEST(ChainCorrection, AChainThatRunsAwayIsSaid) {
  // The chain amplifies every change of the law threefold: p + (m - C(p)) overshoots more each
  // time, and the correction stops rather than pass a law on.
  Rig rig;
  const ChainEstimate t = truth();
  const MeasuringChain chain = [&](const std::vector<analysis::TestRecord>&) {
    ChainEstimate c = rig.running;
    c.law.s1 = t.law.s1 + 3 * (rig.running.law.s1 - t.law.s1) + 20 * kPa;
    return c;
  };
  const ChainCorrection c = correct_chain(one_record(), {specimen::Specimen{}},
                                          specimen::Material{}, t, chain, rig.model());
  EXPECT_FALSE(c.converged);
  ASSERT_FALSE(c.notes.empty());
  // Stopped by the rule for an iteration that moves away (twice worse than the first), not by
  // running out of iterations.
  EXPECT_NE(c.notes.back().find("moves away"), std::string::npos) << c.notes.back();
  EXPECT_EQ(c.steps.size(), 3u);
}

} // namespace
} // namespace fiberbridge::identify
