// Thin and flexible arms in the FEM (issue 13, items 1, 2 and 5 in part; docs/verification.md,
// "Thin arms"): the mesh follows the arm, the polynomial degree is chosen where Q1 would lock,
// the default settings reproduce corrected beam theory on a published composite DCB and the
// bridging law of a 3 mm-arm specimen, refinement converges (and never turns a converged run
// into a failure, with either nonlinear solver), and large rotations are noted.
#include "common/notes.h"
#include "common/thin_dcb_case.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/units.h"
#include "fiberbridge/fem/dcb_common.h"
#include "fiberbridge/fem/dcb_simulation.h"
#include "fiberbridge/law/exponential_law.h"
#include "fiberbridge/law/piecewise_linear_law.h"
#include "fiberbridge/law/seed_laws.h"
#include "test_cases.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

using namespace fiberbridge;
using units::kPa;
using units::mm;

namespace {

using test_notes::has_note;

void print(const result::SimulationResult& r) {
  std::cout << "  a_mm load_N opening_mm R_J R_eq2\n";
  for (const auto& p : r.rcurve)
    std::cout << "  " << p.a / mm << " " << p.load << " " << p.load_point_opening / mm << " "
              << p.R_J << " " << p.R_eq2 << "\n";
  for (const auto& n : r.notes)
    std::cout << "  note: " << n << "\n";
  for (const auto& n : r.method)
    std::cout << "  method: " << n << "\n";
}

/// The shared records' glass/epoxy DCB (tests/common/thin_dcb_case.h: B 25 mm, 2.7 mm arms,
/// a0 35 mm; E_L 19.3, E_T 6.11, G_LT 2.29 GPa, data/dcb_records/README.md), LEFM.
constexpr double kCompositeJtip = 500; // a typical glass/epoxy initiation toughness [J/m^2]

} // namespace

// The mesh lines: at least Minimum layers per arm through a thin arm, the crack-plane element
// tied to the arm (refused beyond the aspect bound), the thick seed arm unchanged.
TEST(FemThinArm, MeshFollowsTheArm) {
  fem::FemParameters prm; // defaults: auto (2 mm on these arms), 4 layers, grading 1.3
  const auto thin = fem::dcb_mesh_lines(thin_dcb_case::specimen(), prm);
  const double h = thin_dcb_case::specimen().arm_thickness();
  EXPECT_GE(thin.y.size() - 1, prm.mesh.min_layers);
  EXPECT_NEAR(thin.first_layer, h / prm.mesh.min_layers, 1e-12);
  EXPECT_LE(thin.dx / thin.first_layer, fem::kMaxCrackPlaneAspect);
  EXPECT_DOUBLE_EQ(thin.y.back(), h);
  for (std::size_t j = 1; j < thin.y.size(); ++j)
    EXPECT_LE(thin.y[j] - thin.y[j - 1], h / prm.mesh.min_layers * (1 + 1e-12));

  // The seed's 17.5 mm arms: square 2 mm elements at the crack plane as before (the seed figures
  // of docs/verification.md are measured on this mesh).
  const specimen::Specimen seed;
  const auto thick = fem::dcb_mesh_lines(seed, prm);
  EXPECT_DOUBLE_EQ(thick.first_layer, thick.dx);
  EXPECT_NEAR(thick.y[1], 2 * mm, 1e-12);

  // 1 mm arms with a given 2 mm and 4 layers: 8 times longer than high. Refused, naming the key.
  // On auto the element follows the arm instead (issue 34): 1 mm, 4 times the 0.25 mm layers.
  specimen::Specimen very_thin = thin_dcb_case::specimen();
  very_thin.height = 2 * mm;
  const auto automatic = fem::dcb_mesh_lines(very_thin, prm);
  EXPECT_NEAR(automatic.dx, 1 * mm, 1e-12);
  EXPECT_NEAR(automatic.dx / automatic.first_layer, fem::kMaxCrackPlaneAspect, 1e-9);
  prm.mesh.element_size = 2 * mm;
  try {
    fem::dcb_mesh_lines(very_thin, prm);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("FEM/Element size"), std::string::npos) << e.what();
  }
  prm.mesh.element_size = 0.25 * mm; // 4 x 0.25 mm layers: square
  EXPECT_NO_THROW(fem::dcb_mesh_lines(very_thin, prm));
}

// auto takes Q2 where Q1 would lock (thin arms) and Q1 on the seed; a forced Q1 on a thin arm
// is noted with the element size that would do.
TEST(FemThinArm, DegreeFollowsTheArm) {
  fem::FemParameters prm;
  std::vector<std::string> notes;
  EXPECT_EQ(fem::resolve_degree(specimen::Specimen(), specimen::Material(), prm, notes), 1u);
  EXPECT_TRUE(notes.empty());
  EXPECT_EQ(fem::resolve_degree(thin_dcb_case::specimen(), thin_dcb_case::material(), prm, notes),
            2u);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_EQ(notes[0].rfind("FEM/Polynomial degree = auto chose Q2", 0), 0u) << notes[0];
  prm.mesh.degree = 1;
  notes.clear();
  EXPECT_EQ(fem::resolve_degree(thin_dcb_case::specimen(), thin_dcb_case::material(), prm, notes),
            1u);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_EQ(notes[0].rfind("resolution: Q1 elements", 0), 0u) << notes[0];
}

namespace {
/// LEFM run of the composite DCB; `window` short so that the run stops a few advances after
/// initiation (the LEFM R curve is flat from the first advance).
result::SimulationResult composite_lefm(fem::FemParameters prm, double j_tip = kCompositeJtip) {
  return fem::simulate_dcb(thin_dcb_case::specimen(), thin_dcb_case::material(),
                           law::NoBridgingLaw(), j_tip, prm);
}
} // namespace

// Corrected beam theory on the default settings (2 mm elements on 2.7 mm arms: Q2 by auto, four
// 0.675 mm layers). CBT, P = B sqrt(E_L h^3 J / 12) / (a + chi h), is a beam approximation of
// the 2D orthotropic solid: the FEM ladder converges to within 0.1 % of it (docs/verification.md,
// "Thin arms"), so the 1 % bound leaves room for the discretization at 2 mm and nothing
// for a wrong bending stiffness (Q1 at 2 mm is 8 % off).
TEST(FemThinArm, LefmCompositeFollowsCbtOnDefaults) {
  fem::FemParameters prm;
  prm.steady_state.window = 4 * mm;
  const auto r = composite_lefm(prm);
  print(r);
  ASSERT_TRUE(r.reached_steady_state);
  ASSERT_GE(r.rcurve.size(), 3u);
  EXPECT_TRUE(has_note(r, "FEM/Polynomial degree = auto chose Q2"));
  const auto spec = thin_dcb_case::specimen();
  const auto mat = thin_dcb_case::material();
  for (const auto& p : r.rcurve) {
    EXPECT_NEAR(p.load / specimen::cbt_load_at_crack_length(spec, mat, kCompositeJtip, p.a), 1.0,
                0.01)
        << "a = " << p.a / mm << " mm";
    // R_J is the far-field J: path independence on this mesh within the 0.5 % of the thick-arm
    // LEFM test (FemDcb.LefmFollowsCorrectedBeamTheory).
    EXPECT_NEAR(p.R_J / kCompositeJtip, 1.0, 0.005);
  }
  EXPECT_FALSE(has_note(r, "small strain:")); // opening/a about 0.1 here
}

// Thin-arm bridging (issue 13): the EPI control law of seed Table 1 (0.1 mm:579 kPa, 1.0 mm:177
// kPa, delta_c 3.5 mm, J_tip 200 J/m^2; prm/control_epi.prm) on the seed specimen with 3 mm arms,
// default settings. G_ss against J_tip + J_c and R_J against Eq. 2 at every advance within the
// issue's 1 %: the Eq. 2 check needs only the law, Eq. 1 and a converged far-field J; the
// measured figures are in docs/verification.md ("Thin arms").
TEST(FemThinArm, EpiBridgingOnThreeMillimetreArms) {
  specimen::Specimen spec;
  spec.height = 6 * mm;
  const auto epi = law::make_trilinear(law::seed_control_law("EPI"));
  const double j_tip = 200;
  const auto r = fem::simulate_dcb(spec, specimen::Material(), epi, j_tip, fem::FemParameters());
  print(r);
  ASSERT_TRUE(r.reached_steady_state);
  const double G = j_tip + epi.area();
  EXPECT_NEAR(r.G_ss / G, 1.0, 0.01);
  for (const auto& p : r.rcurve)
    EXPECT_NEAR(p.R_J / p.R_eq2, 1.0, 0.01) << "a = " << p.a / mm << " mm";
  EXPECT_LT(result::rdelta_error_vs_eq2(r, epi, j_tip), 0.01);
  // A bridging zone of tens of mm on 2 mm elements is resolved: no resolution note.
  EXPECT_FALSE(has_note(r, "resolution: the cohesive zone is at most"));
}

// Large rotations: at J_tip 5000 J/m^2 the composite opens to about 0.33 of the crack length at
// initiation, where the beam model's elastica comparison puts the small-rotation load 1.4 % low;
// the run says so in its notes (at the default 500 J/m^2 it does not: see above).
TEST(FemThinArm, SmallStrainRunSaysWhenRotationsAreLarge) {
  fem::FemParameters prm;
  prm.steady_state.window = 2 * mm;
  const auto r = composite_lefm(prm, 5000);
  ASSERT_FALSE(r.rcurve.empty());
  const auto& p = r.rcurve.front();
  std::cout << "  opening/a at initiation " << p.load_point_opening / p.a << "\n";
  EXPECT_GT(p.load_point_opening / p.a, 0.28);
  EXPECT_TRUE(has_note(r, "small strain: at a = "));
}

// Refining one level beyond the default (1 mm elements on the 2.7 mm arms) must not turn a
// converged case into a failure, with either nonlinear solver: both accept a residual at its
// round-off floor (issue 13 item 2). The two solvers meet the same residual test, so their loads
// agree to far better than the 1e-6 checked here (a state off by the Newton tolerance 1e-9 of the
// reaction moves the load by about that much).
TEST(FemThinArm, RefinedCompositeConvergesWithBothSolvers) {
  fem::FemParameters prm;
  prm.mesh.element_size = 1 * mm;
  prm.steady_state.window = 2 * mm;
  const auto newton = composite_lefm(prm);
  prm.nonlinear.solver = fem::FemParameters::Nonlinear::Solver::kinsol;
  const auto kinsol = composite_lefm(prm);
  ASSERT_TRUE(newton.reached_steady_state && kinsol.reached_steady_state);
  ASSERT_EQ(newton.rcurve.size(), kinsol.rcurve.size());
  for (std::size_t i = 0; i < newton.rcurve.size(); ++i)
    EXPECT_NEAR(kinsol.rcurve[i].load / newton.rcurve[i].load, 1.0, 1e-6);
  const auto spec = thin_dcb_case::specimen();
  const auto& p = newton.rcurve.front();
  // Closer to CBT than the default 2 mm (the ladder of docs/verification.md): 0.5 %.
  EXPECT_NEAR(p.load / specimen::cbt_load_at_crack_length(spec, thin_dcb_case::material(),
                                                          kCompositeJtip, p.a),
              1.0, 0.005);
}

// A short refinement ladder (Q2 at 2, 1 and 0.5 mm on the composite): the initiation load
// converges monotonically, each step changing it less than the one before, in the same
// direction. The tip tolerance is tightened to 1e-7 so that the secant search's own scatter
// (up to half the 1e-3 default in the load, P ~ sqrt(J)) does not enter the differences; in
// LEFM the secant on sqrt(J) is exact in one step, so this costs nothing. The full ladder (Q1
// and Q2 down to 0.125 mm) is scripts/thin_arm_fem_ladder.py (docs/verification.md).
TEST(FemThinArm, RefinementLadderConvergesMonotonically) {
  std::vector<double> loads;
  for (const double size : {2.0, 1.0, 0.5}) {
    fem::FemParameters prm;
    prm.mesh.degree = 2;
    prm.mesh.element_size = size * mm;
    prm.nonlinear.tip_tolerance = 1e-7;
    prm.steady_state.window = 1e-6 * mm; // stop two advances after initiation
    const auto r = composite_lefm(prm);
    ASSERT_FALSE(r.rcurve.empty());
    ASSERT_DOUBLE_EQ(r.rcurve.front().a, thin_dcb_case::specimen().initial_crack);
    loads.push_back(r.rcurve.front().load);
    std::cout << "  " << size << " mm: initiation load " << loads.back() << " N\n";
  }
  const double d1 = loads[1] - loads[0], d2 = loads[2] - loads[1];
  EXPECT_GT(d1 * d2, 0) << d1 << " " << d2;
  EXPECT_LT(std::abs(d2), std::abs(d1)) << d1 << " " << d2;
}

// Issue 13's snap-back case: a strong short linear law (10 MPa, delta_c 0.1 mm: J_c 500 J/m^2
// over a zone of about 3.4 mm on the seed specimen) on a J_tip of 100 J/m^2 used to stop with "no
// equilibrium" at the first advances under load-point opening control. With the extrinsic
// insertion (law/rigid_law.h) each new segment starts at the law's stress, so no segment has to
// snap back through an elastic rise; the run now gives its whole R curve on the default settings
// of both specimens (measured: G_ss 602.4 and 598.4 J/m^2 against 600; refined on the seed
// specimen 600.5, 600.1, 599.9 at 1, 0.5, 0.25 mm, docs/verification.md "Thin arms"). 2 % is
// the bound. On the old default 2 mm elements the zone was under two elements long; the
// automatic mesh (issue 34, fem/auto_mesh.h) takes about 0.66 mm on both specimens.
TEST(FemThinArm, StrongShortLawGivesItsWholeRCurve) {
  const auto law = law::make_linear_softening(10000 * kPa, 0.1 * mm);
  const double j_tip = 100, G = j_tip + law.area();
  ASSERT_NEAR(law.area(), 500, 1e-9);
  for (const bool thin : {false, true}) {
    const specimen::Specimen spec = thin ? thin_dcb_case::specimen() : specimen::Specimen();
    const specimen::Material mat = thin ? thin_dcb_case::material() : specimen::Material();
    const auto r = fem::simulate_dcb(spec, mat, law, j_tip, fem::FemParameters());
    print(r);
    ASSERT_TRUE(r.reached_steady_state) << (thin ? "composite" : "seed specimen");
    EXPECT_EQ(r.steady_state_status, result::SteadyStateStatus::resolved);
    EXPECT_NEAR(r.G_ss / G, 1.0, 0.02) << (thin ? "composite" : "seed specimen");
    // The zone (about 2.8-3.2 mm) was under two of the old default 2 mm elements; the automatic
    // mesh (issue 34) resolves it: no resolution note.
    EXPECT_FALSE(has_note(r, "resolution: the cohesive zone is at most"));
  }
}

// Issue 13 item 4: a law three times stronger and five times shorter (30 MPa, delta_c 0.02 mm:
// J_c 300 J/m^2, zone about 0.58 mm) lost equilibrium right after the first release under
// load-point opening control. The run now switches to the crack-tip opening control
// (docs/design.md section 2) and gives its whole R curve. On the short DCB with 0.25 mm elements
// the zone spans about 2.3 elements (so the run claims no steady state, issue 34) and G_ss is
// measured +0.27 % off J_tip + J_c, R_J vs Eq. 2 0.26 %; 2 % is the bound (the 2, 1, 0.5 mm
// seed ladder, +7.2, +4.9, +2.7 %, fails it: the error is the unresolved zone, docs/verification.md
// "Strong short laws"). On the old default 2 mm elements, given, the run completes, must say that
// the zone is unresolved, and claim no steady state.
TEST(FemThinArm, StrongerShorterLawIsTracedPastTheSnapBack) {
  const auto law = law::make_linear_softening(30000 * kPa, 0.02 * mm);
  const double j_tip = 100, G = j_tip + law.area();
  ASSERT_NEAR(law.area(), 300, 1e-9);
  fem::FemParameters prm;
  prm.mesh.element_size = 0.25 * mm;
  const auto fine = fem::simulate_dcb(fem_test::short_dcb(), specimen::Material(), law, j_tip, prm);
  print(fine);
  // The zone spans about 2.3 of these elements, under the zone rule's 3: G_ss is right to 2 %,
  // but the run claims no steady state (issue 34 item 2), G_ss being the plateau's mean.
  EXPECT_FALSE(fine.reached_steady_state);
  EXPECT_EQ(fine.steady_state_status, result::SteadyStateStatus::zone_unresolved);
  EXPECT_TRUE(has_note(fine, "control: at a = "));
  EXPECT_NEAR(fine.G_ss / G, 1.0, 0.02);
  EXPECT_LT(result::rdelta_error_vs_eq2(fine, law, j_tip), 0.02);

  // The old default 2 mm, given: the run completes, says the zone is unresolved, and claims no
  // steady state (issue 34 item 2: the flag a script reads must not contradict the note).
  prm.mesh.element_size = 2 * mm;
  const auto coarse =
      fem::simulate_dcb(specimen::Specimen(), specimen::Material(), law, j_tip, prm);
  EXPECT_FALSE(coarse.reached_steady_state);
  EXPECT_EQ(coarse.steady_state_status, result::SteadyStateStatus::zone_unresolved);
  EXPECT_TRUE(has_note(coarse, "control: at a = "));
  EXPECT_TRUE(has_note(coarse, "resolution: the cohesive zone is at most"));
  EXPECT_TRUE(has_note(coarse, "no steady state claimed: the cohesive zone spans"));
}
