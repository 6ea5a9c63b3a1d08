// The one zone-resolution rule of the FEM and the MPM (result/rcurve.h): a note when the longest
// cohesive zone of the R curve spans fewer than three crack-plane elements or cells; and the
// withdrawal of a steady-state claim that a model finds unsound (the MPM's open energy ledger).
#include "fiberbridge/core/units.h"
#include "fiberbridge/result/rcurve.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace fiberbridge::result {
namespace {

constexpr double mm = units::mm;

SimulationResult with_zones(std::initializer_list<double> zones_mm) {
  SimulationResult r;
  double a = 100 * mm;
  for (const double z : zones_mm) {
    RCurvePoint p;
    a += 5 * mm;
    p.a = a;
    p.zone_length = z * mm;
    r.rcurve.push_back(p);
  }
  return r;
}

TEST(ZoneResolution, ShortZoneIsNotedWithTheSettingThatResolvesIt) {
  // Longest zone 6 mm at a = 110 mm; 5 mm cells: 1.2 cells, under 3.
  SimulationResult r = with_zones({4, 6, 5});
  const double n = note_zone_resolution(r, 5 * mm, "cells", "MPM/Cell size");
  EXPECT_NEAR(n, 1.2, 1e-12);
  ASSERT_EQ(r.notes.size(), 1u);
  const std::string& note = r.notes[0];
  EXPECT_EQ(note.rfind("resolution: the cohesive zone is at most 6 mm long (at a = 110 mm)", 0), 0u)
      << note;
  EXPECT_NE(note.find("1.2 cells of 5 mm"), std::string::npos) << note;
  // 6 mm over the three spacings a zone needs: 2 mm.
  EXPECT_NE(note.find("MPM/Cell size at most 2 mm would resolve the zone read here"),
            std::string::npos)
      << note;
}

TEST(ZoneResolution, AModelsReadingOffsetIsTakenOffFirst) {
  // 17.5 mm read at 5 mm cells is 3.5 cells; less the 2 cells an MPM reads for any zone, 1.5.
  SimulationResult r = with_zones({12.5, 17.5, 12.5});
  EXPECT_NEAR(note_zone_resolution(r, 5 * mm, "cells", "MPM/Cell size", 2), 1.5, 1e-12);
  ASSERT_EQ(r.notes.size(), 1u);
  EXPECT_NE(r.notes[0].find("of which about 2 cells are the model's reading of the root"),
            std::string::npos)
      << r.notes[0];
  // The same reading without the offset counts as resolved (3.5 cells).
  SimulationResult plain = with_zones({12.5, 17.5, 12.5});
  EXPECT_NEAR(note_zone_resolution(plain, 5 * mm, "cells", "MPM/Cell size"), 3.5, 1e-12);
  EXPECT_TRUE(plain.notes.empty());
}

TEST(ZoneResolution, ResolvedZoneOrNoZoneGivesNoNote) {
  SimulationResult resolved = with_zones({10, 30, 20});
  EXPECT_NEAR(note_zone_resolution(resolved, 2 * mm, "elements", "FEM/Element size"), 15, 1e-12);
  EXPECT_TRUE(resolved.notes.empty());
  // Exactly three spacings is resolved (the bound is "fewer than three").
  SimulationResult bound = with_zones({6});
  note_zone_resolution(bound, 2 * mm, "elements", "FEM/Element size");
  EXPECT_TRUE(bound.notes.empty());
  // An LEFM law has no zone: the column is NaN or zero, and nothing is said.
  SimulationResult lefm = with_zones({0, 0});
  lefm.rcurve.push_back(RCurvePoint{});
  EXPECT_EQ(note_zone_resolution(lefm, 2 * mm, "elements", "FEM/Element size"), 0);
  EXPECT_TRUE(lefm.notes.empty());
}

// The MPM's strong short law (10 MPa, 0.1 mm at 5 mm cells) read a flat R_J 23 % below the law
// and called it steady state: a run found unsound withdraws the claim, keeps G_ss, says why.
TEST(SteadyStateClaim, WithdrawnWithItsReasonAndThePlateauKept) {
  SimulationResult r = with_zones({12.5, 17.5, 12.5});
  r.reached_steady_state = true;
  r.G_ss = 459.8;
  r.notes.push_back("resolution: kept");
  r.notes.push_back("steady state: R_J within 2.88 % over the last 15 mm");
  r.steady_state_status = SteadyStateStatus::resolved;
  withdraw_steady_state(r, SteadyStateStatus::ledger_open, "the energy ledger does not close");
  EXPECT_FALSE(r.reached_steady_state);
  EXPECT_EQ(r.steady_state_status, SteadyStateStatus::ledger_open);
  EXPECT_DOUBLE_EQ(r.G_ss, 459.8);
  ASSERT_EQ(r.notes.size(), 2u);
  EXPECT_EQ(r.notes[0], "resolution: kept");
  EXPECT_EQ(r.notes[1], "no steady state claimed: the energy ledger does not close; the plateau "
                        "of R_J (G_ss = 459.8 J/m^2 is its mean) need not be the law's. R_J within "
                        "2.88 % over the last 15 mm");
  // A run without the claim keeps its notes; its status says what was found unsound.
  SimulationResult none = with_zones({12.5});
  none.notes.push_back("no steady state: the notch root did not move");
  withdraw_steady_state(none, SteadyStateStatus::ledger_open, "anything");
  EXPECT_FALSE(none.reached_steady_state);
  EXPECT_EQ(none.steady_state_status, SteadyStateStatus::ledger_open);
  EXPECT_EQ(none.notes[0], "no steady state: the notch root did not move");
}

// Issue 34 item 2: the status a script reads. The stable names of docs/design.md section 5.
TEST(SteadyStateStatus, StableNames) {
  EXPECT_EQ(to_string(SteadyStateStatus::resolved), "resolved");
  EXPECT_EQ(to_string(SteadyStateStatus::not_reached), "not_reached");
  EXPECT_EQ(to_string(SteadyStateStatus::zone_unresolved), "zone_unresolved");
  EXPECT_EQ(to_string(SteadyStateStatus::ledger_open), "ledger_open");
  EXPECT_EQ(SimulationResult{}.steady_state_status, SteadyStateStatus::not_reached);
  for (const auto s : {SteadyStateStatus::resolved, SteadyStateStatus::not_reached,
                       SteadyStateStatus::zone_unresolved, SteadyStateStatus::ledger_open})
    EXPECT_EQ(steady_state_status_from_string(to_string(s)), s);
  EXPECT_THROW(steady_state_status_from_string("converged"), std::invalid_argument);
}

// The case: a 20 MPa / 0.05 mm law on 2 mm elements claimed steady state while its note
// said the zone spans 0.65 elements. The zone rule now withdraws the claim: flag false, status
// zone_unresolved, the plateau's G_ss kept and the steady-state note rewritten.
TEST(SteadyStateStatus, UnresolvedZoneWithdrawsTheClaim) {
  SimulationResult r = with_zones({1.3, 1.3});
  r.reached_steady_state = true;
  r.steady_state_status = SteadyStateStatus::resolved;
  r.G_ss = 617.9;
  r.notes.push_back("steady state: R_J within 0.1 %");
  EXPECT_NEAR(note_zone_resolution(r, 2 * mm, "elements", "FEM/Element size"), 0.65, 1e-12);
  EXPECT_FALSE(r.reached_steady_state);
  EXPECT_EQ(r.steady_state_status, SteadyStateStatus::zone_unresolved);
  EXPECT_DOUBLE_EQ(r.G_ss, 617.9);
  ASSERT_EQ(r.notes.size(), 2u);
  EXPECT_EQ(r.notes[0].rfind("no steady state claimed: the cohesive zone spans 0.65 elements", 0),
            0u)
      << r.notes[0];
  EXPECT_EQ(r.notes[1].rfind("resolution: the cohesive zone is at most 1.3 mm long", 0), 0u);

  // A resolved zone leaves the claim alone.
  SimulationResult ok = with_zones({10, 30});
  ok.reached_steady_state = true;
  ok.steady_state_status = SteadyStateStatus::resolved;
  note_zone_resolution(ok, 2 * mm, "elements", "FEM/Element size");
  EXPECT_TRUE(ok.reached_steady_state);
  EXPECT_EQ(ok.steady_state_status, SteadyStateStatus::resolved);

  // No plateau and an unresolved zone: the flag stays false, the status says to refine.
  SimulationResult flat = with_zones({1.0});
  note_zone_resolution(flat, 2 * mm, "elements", "FEM/Element size");
  EXPECT_FALSE(flat.reached_steady_state);
  EXPECT_EQ(flat.steady_state_status, SteadyStateStatus::zone_unresolved);
}

// The first unsoundness found is the one reported: the MPM checks its ledger before the zone.
TEST(SteadyStateStatus, FirstUnsoundnessIsKept) {
  SimulationResult r = with_zones({1.0});
  r.reached_steady_state = true;
  r.steady_state_status = SteadyStateStatus::resolved;
  r.notes.push_back("steady state: R_J within 0.1 %");
  withdraw_steady_state(r, SteadyStateStatus::ledger_open, "the energy ledger does not close");
  note_zone_resolution(r, 5 * mm, "cells", "MPM/Cell size");
  EXPECT_EQ(r.steady_state_status, SteadyStateStatus::ledger_open);
  EXPECT_FALSE(r.reached_steady_state);
  EXPECT_EQ(r.notes[0].rfind("no steady state claimed: the energy ledger does not close", 0), 0u)
      << r.notes[0];
}

} // namespace
} // namespace fiberbridge::result
