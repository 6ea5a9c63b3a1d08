// FEM/Element size = auto and the honest steady-state flag (issue 34 items 1 and 2;
// docs/design.md section 2, "The automatic mesh"; docs/verification.md, "The automatic mesh"):
// the choice itself (arithmetic), thin arms on the defaults against corrected beam theory, and
// strong short laws on the seed specimen on the defaults, each either within 2 % of
// J_tip + J_c or flagged with the reason.
#include "common/notes.h"
#include "common/thin_dcb_case.h"
#include "fiberbridge/core/units.h"
#include "fiberbridge/fem/auto_mesh.h"
#include "fiberbridge/fem/dcb_common.h"
#include "fiberbridge/fem/dcb_simulation.h"
#include "fiberbridge/law/exponential_law.h"
#include "fiberbridge/law/piecewise_linear_law.h"
#include "fiberbridge/law/seed_laws.h"
#include "fiberbridge/law/traction_law.h"
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
  for (const auto& n : r.notes)
    std::cout << "  note: " << n << "\n";
  for (const auto& n : r.method)
    if (n.rfind("mesh:", 0) == 0)
      std::cout << "  method: " << n << "\n";
  std::cout << "  G_ss " << r.G_ss << " J/m^2, reached " << r.reached_steady_state << ", status "
            << result::to_string(r.steady_state_status) << ", " << r.rcurve.size() << " advances, "
            << r.wall_time_s << " s\n";
}

/// The shared records' composite (tests/common/thin_dcb_case.h) with arms of `arm` [m].
specimen::Specimen composite(double arm) {
  specimen::Specimen s = thin_dcb_case::specimen();
  s.height = 2 * arm;
  return s;
}

/// A choice held by the cost bound: within kAutoMostDofs, the next finer a0 / (n + 1) beyond it,
/// and the reason says so.
void expect_finest_within_cost(const specimen::Specimen& s, const specimen::Material& m,
                               const fem::FemParameters& prm, const fem::MeshChoice& c) {
  const double a0 = s.initial_crack;
  const double n = std::round(a0 / c.element_size);
  EXPECT_NEAR(c.element_size, a0 / n, 1e-15);
  EXPECT_LE(fem::estimated_dofs(s, m, prm, c.element_size), fem::kAutoMostDofs);
  EXPECT_GT(fem::estimated_dofs(s, m, prm, a0 / (n + 1)), fem::kAutoMostDofs);
  EXPECT_NE(c.reason.find("by the cost bound"), std::string::npos) << c.reason;
}

} // namespace

// The choice on the extreme cases. Long zones (the seed PVA law) and LEFM keep the old default
// 2 mm on the thick seed arms; thin arms take the largest element the aspect bound admits (4
// crack-plane layers of h/4 long: h); short zones take the estimate over 6, as far as the mesh
// stays within the cost bound of kAutoMostDofs; a given size is honoured.
TEST(AutoMesh, ChoiceFollowsTheArmAndTheZone) {
  const fem::FemParameters prm; // auto
  ASSERT_TRUE(prm.mesh.automatic_size());
  const specimen::Specimen seed;
  const specimen::Material wood;
  const auto pva = fem_test::pva_control();
  auto c = fem::choose_mesh(seed, wood, pva, 100, prm);
  EXPECT_TRUE(c.automatic);
  EXPECT_DOUBLE_EQ(c.element_size, 2 * mm);
  EXPECT_GT(c.zone_estimate, 20 * mm); // tens of mm: the slender-arm length
  EXPECT_DOUBLE_EQ(fem::choose_mesh(seed, wood, law::NoBridgingLaw(), 100, prm).element_size,
                   2 * mm);
  EXPECT_EQ(fem::choose_mesh(seed, wood, law::NoBridgingLaw(), 100, prm).zone_estimate, 0);

  for (const double arm : {1.5, 1.0}) {
    c = fem::choose_mesh(composite(arm * mm), thin_dcb_case::material(), law::NoBridgingLaw(), 100,
                         prm);
    // h, snapped down to a0 / n (35 mm / 24 = 1.458 mm on the 1.5 mm arms): within the bound.
    EXPECT_LE(c.element_size, arm * mm * (1 + 1e-12)) << arm;
    EXPECT_GT(c.element_size, 0.95 * arm * mm) << arm;
    EXPECT_NO_THROW(fem::dcb_mesh_lines(composite(arm * mm), fem::with_mesh(prm, c))) << arm;
    EXPECT_GE(c.layers_per_arm, prm.mesh.min_layers) << arm;
    EXPECT_NE(c.reason.find("the arm"), std::string::npos) << c.reason;
  }

  // The law's own (infinite-body) length by hand for 10 MPa / 0.1 mm on Douglas-fir: E' = 1.31
  // GPa (Sih-Paris-Irwin with E_L 13.4, E_T 0.67, G_LT 1.045 GPa, nu_LT 0.449), G_c 500 J/m^2:
  // 1.31e9 * 500 / 1e14 = 6.56 mm; the slender-arm length is 24.5 mm. The tip's share at J_tip
  // 100: pi 1.31e9 (1e-4)^2 / (32 * 100) = 12.88 mm (K field; the bending arm's 27.8 mm is
  // longer); the harmonic mean of 6.56 and 12.88 is 4.35 mm.
  EXPECT_NEAR(fem::crack_modulus(wood) / 1.31e9, 1.0, 0.005);
  const auto ten = law::make_linear_softening(10000 * kPa, 0.1 * mm);
  EXPECT_NEAR(fem::bridging_zone_length(seed, wood, ten) / (6.56 * mm), 1.0, 0.005);
  EXPECT_NEAR(fem::tip_opening_length(seed, wood, 0.1 * mm, 100) / (12.88 * mm), 1.0, 0.005);
  c = fem::choose_mesh(seed, wood, ten, 100, prm);
  EXPECT_NEAR(c.zone_estimate / (4.35 * mm), 1.0, 0.005);
  // 0.725 mm, snapped down to a0 / n.
  EXPECT_LE(c.element_size, c.zone_estimate / fem::kAutoElementsPerZoneEstimate);
  EXPECT_GT(c.element_size, 0.99 * c.zone_estimate / fem::kAutoElementsPerZoneEstimate);

  const auto thirty = law::make_linear_softening(30000 * kPa, 0.02 * mm);
  c = fem::choose_mesh(seed, wood, thirty, 100, prm);
  expect_finest_within_cost(seed, wood, prm, c);

  fem::FemParameters given;
  given.mesh.element_size = 1.7 * mm;
  c = fem::choose_mesh(seed, wood, thirty, 100, given);
  EXPECT_FALSE(c.automatic);
  EXPECT_DOUBLE_EQ(c.element_size, 1.7 * mm);
}

// Issue 42 item 7: the estimate sees the tip. The law's own length is the 8.2 mm for
// 0.8 MPa / 0.01 mm (G_c 4 J/m^2: 1.312e9 * 4 / 0.64e12); under J_tip 150 the crack opens to
// 0.01 mm within pi 1.312e9 (1e-5)^2 / (32 * 150) = 0.0859 mm of the tip (the K field), so the
// zone is about that long (the model read 0.34 mm on 1 mm elements: a third of an element, a
// reading, not a length). By hand to the digits given (0.5 %, the rounding of E'). Without
// J_tip the estimate is the law's own length; the 20 MPa / 0.05 mm law keeps most of its own
// (1.64 mm and the tip's 3.22 mm give 1.086 mm; measured 0.92 mm at 0.5 mm elements).
TEST(AutoMesh, ZoneEstimateSeesTheTip) {
  const fem::FemParameters prm;
  const specimen::Specimen seed;
  const specimen::Material wood;
  const auto weak = law::make_linear_softening(800 * kPa, 0.01 * mm);
  ASSERT_NEAR(weak.area(), 4, 1e-12);
  EXPECT_NEAR(fem::bridging_zone_length(seed, wood, weak) / (8.20 * mm), 1.0, 0.005);
  EXPECT_NEAR(fem::tip_opening_length(seed, wood, 0.01 * mm, 150) / (0.0859 * mm), 1.0, 0.005);
  EXPECT_NEAR(fem::estimated_zone_length(seed, wood, weak, 150) / (0.0850 * mm), 1.0, 0.005);
  EXPECT_DOUBLE_EQ(fem::estimated_zone_length(seed, wood, weak, 0),
                   fem::bridging_zone_length(seed, wood, weak));
  auto c = fem::choose_mesh(seed, wood, weak, 150, prm);
  expect_finest_within_cost(seed, wood, prm, c);

  const auto twenty = law::make_linear_softening(20000 * kPa, 0.05 * mm);
  EXPECT_NEAR(fem::bridging_zone_length(seed, wood, twenty) / (1.640 * mm), 1.0, 0.005);
  EXPECT_NEAR(fem::tip_opening_length(seed, wood, 0.05 * mm, 100) / (3.220 * mm), 1.0, 0.005);
  EXPECT_NEAR(fem::estimated_zone_length(seed, wood, twenty, 100) / (1.086 * mm), 1.0, 0.005);
  c = fem::choose_mesh(seed, wood, twenty, 100, prm);
  expect_finest_within_cost(seed, wood, prm, c);
}

// Issue 34's first door: the LEFM composite with 1.5 mm and 1 mm arms used to be refused on the
// defaults ("elements ... would be 5.33 times longer than high"). On auto it runs and follows
// corrected beam theory within 1 %. CBT is a beam approximation of the 2D orthotropic solid good
// to about 2 % against fine plane-stress FE in general (docs/design.md section 3, "Reference
// formulas"); on these arms the FEM ladder meets it within 0.2 % (docs/verification.md, "Thin
// arms"), so 1 % (the issue's bound) leaves room for the discretization and none for a wrong
// bending stiffness. R_J is the far-field J: within 0.5 % of J_tip, the bound of the thick-arm
// LEFM test.
TEST(AutoMesh, ThinLefmCompositeFollowsCbtOnDefaults) {
  constexpr double j_tip = 500;
  for (const double arm : {1.5, 1.0}) {
    const auto spec = composite(arm * mm);
    const auto mat = thin_dcb_case::material();
    fem::FemParameters prm;
    prm.steady_state.window = 4 * mm; // LEFM is flat from the first advance
    const auto r = fem::simulate_dcb(spec, mat, law::NoBridgingLaw(), j_tip, prm);
    print(r);
    ASSERT_TRUE(r.reached_steady_state) << arm;
    EXPECT_EQ(r.steady_state_status, result::SteadyStateStatus::resolved);
    ASSERT_GE(r.rcurve.size(), 3u);
    EXPECT_TRUE(has_note(r, "FEM/Polynomial degree = auto chose Q2"));
    for (const auto& p : r.rcurve) {
      EXPECT_NEAR(p.load / specimen::cbt_load_at_crack_length(spec, mat, j_tip, p.a), 1.0, 0.01)
          << arm << " mm arms, a = " << p.a / mm << " mm";
      EXPECT_NEAR(p.R_J / j_tip, 1.0, 0.005) << arm << " mm arms, a = " << p.a / mm << " mm";
    }
  }
}

// Issue 34's second door, on the defaults of the seed specimen: the 20 MPa / 0.05 mm linear law
// (J_c 500 J/m^2 on J_tip 100) used to end with reached_steady_state true and G_ss +3.0 % on
// 2 mm elements while its note said the zone spans 0.65 elements, and then, at the old cost
// floor Length/600 (0.5 mm), flagged zone_unresolved (zone 0.92 mm over 1.8 elements, G_ss
// +0.42 %). Issue 42 item 7: auto now estimates the zone at 1.09 mm (it sees the tip), wants
// 0.18 mm elements and takes the finest within the cost bound, 0.240 mm (64948 dofs, counted
// exactly before the run): the zone is resolved and the run converges on the defaults. 0.5 %:
// with a resolved zone the ladder's G_ss errors were +0.08 % (0.25 mm) and +0.14 % (0.24 mm),
// against +0.42 % unresolved at 0.5 mm (docs/verification.md, "The automatic mesh: finer where
// the zone needs it"), so 0.5 % fails an unresolved or wrongly dissipating run.
TEST(AutoMesh, TwentyMegapascalLawConvergesOnSeedDefaults) {
  const auto law = law::make_linear_softening(20000 * kPa, 0.05 * mm);
  const double j_tip = 100, G = j_tip + law.area();
  ASSERT_NEAR(law.area(), 500, 1e-9);
  const fem::FemParameters prm;
  const auto r = fem::simulate_dcb(specimen::Specimen(), specimen::Material(), law, j_tip, prm);
  print(r);
  EXPECT_TRUE(r.reached_steady_state);
  EXPECT_EQ(r.steady_state_status, result::SteadyStateStatus::resolved);
  EXPECT_FALSE(has_note(r, "resolution: the cohesive zone is at most"));
  EXPECT_NEAR(r.G_ss / G, 1.0, 0.005);
  // The cost bound counts the engine's own dofs.
  const auto c = fem::choose_mesh(specimen::Specimen(), specimen::Material(), law, j_tip, prm);
  EXPECT_EQ(r.n_dofs_or_particles,
            std::lround(fem::estimated_dofs(specimen::Specimen(), specimen::Material(), prm,
                                            c.element_size)));
}

// The 30 MPa / 0.02 mm law (J_c 300 J/m^2 on J_tip 100) on the seed defaults: its zone (0.25 mm
// read at 0.24 mm elements) needs elements of about 0.08 mm, 6e5 dofs on the seed specimen; auto
// runs at the finest element within the cost bound, 0.240 mm (G_ss +0.26 %; it was +2.7 % at the
// old 0.5 mm floor), where the zone spans one element: the run must claim no steady state and
// give the reason and the size that would resolve the zone.
TEST(AutoMesh, ThirtyMegapascalLawOnSeedDefaultsIsFlagged) {
  const auto law = law::make_linear_softening(30000 * kPa, 0.02 * mm);
  const auto r =
      fem::simulate_dcb(specimen::Specimen(), specimen::Material(), law, 100, fem::FemParameters());
  print(r);
  EXPECT_FALSE(r.reached_steady_state);
  EXPECT_EQ(r.steady_state_status, result::SteadyStateStatus::zone_unresolved);
  EXPECT_TRUE(has_note(r, "no steady state claimed: the cohesive zone spans"));
  EXPECT_TRUE(has_note(r, "resolution: the cohesive zone is at most"));
}

// The same law on the old default 2 mm elements, given: the run still completes, and now its
// flag agrees with its note (issue 34 item 2): no steady state claimed, status zone_unresolved,
// G_ss kept as the plateau's mean.
TEST(AutoMesh, TwentyMegapascalLawOnTwoMillimetresIsFlagged) {
  const auto law = law::make_linear_softening(20000 * kPa, 0.05 * mm);
  fem::FemParameters prm;
  prm.mesh.element_size = 2 * mm;
  const auto r = fem::simulate_dcb(specimen::Specimen(), specimen::Material(), law, 100, prm);
  print(r);
  EXPECT_FALSE(r.reached_steady_state);
  EXPECT_EQ(r.steady_state_status, result::SteadyStateStatus::zone_unresolved);
  EXPECT_TRUE(has_note(r, "no steady state claimed: the cohesive zone spans"));
  EXPECT_TRUE(has_note(r, "resolution: the cohesive zone is at most"));
  EXPECT_TRUE(std::isfinite(r.G_ss));
}
