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

} // namespace

// The choice on the extreme cases. Long zones (the seed PVA law) and LEFM keep the old default
// 2 mm on the thick seed arms; thin arms take the largest element the aspect bound admits (4
// crack-plane layers of h/4 long: h); short zones take the estimate over 8, not below the cost
// floor Length/600; a given size is honoured.
TEST(AutoMesh, ChoiceFollowsTheArmAndTheZone) {
  const fem::FemParameters prm; // auto
  ASSERT_TRUE(prm.mesh.automatic_size());
  const specimen::Specimen seed;
  const specimen::Material wood;
  const auto pva = fem_test::pva_control();
  auto c = fem::choose_mesh(seed, wood, pva, prm);
  EXPECT_TRUE(c.automatic);
  EXPECT_DOUBLE_EQ(c.element_size, 2 * mm);
  EXPECT_GT(c.zone_estimate, 20 * mm); // tens of mm: the slender-arm length
  EXPECT_DOUBLE_EQ(fem::choose_mesh(seed, wood, law::NoBridgingLaw(), prm).element_size, 2 * mm);
  EXPECT_EQ(fem::choose_mesh(seed, wood, law::NoBridgingLaw(), prm).zone_estimate, 0);

  for (const double arm : {1.5, 1.0}) {
    c = fem::choose_mesh(composite(arm * mm), thin_dcb_case::material(), law::NoBridgingLaw(), prm);
    // h, snapped down to a0 / n (35 mm / 24 = 1.458 mm on the 1.5 mm arms): within the bound.
    EXPECT_LE(c.element_size, arm * mm * (1 + 1e-12)) << arm;
    EXPECT_GT(c.element_size, 0.95 * arm * mm) << arm;
    EXPECT_NO_THROW(fem::dcb_mesh_lines(composite(arm * mm), fem::with_mesh(prm, c))) << arm;
    EXPECT_GE(c.layers_per_arm, prm.mesh.min_layers) << arm;
    EXPECT_NE(c.reason.find("the arm"), std::string::npos) << c.reason;
  }

  // The infinite-body estimate by hand for 10 MPa / 0.1 mm on Douglas-fir: E' = 1.31 GPa
  // (Sih-Paris-Irwin with E_L 13.4, E_T 0.67, G_LT 1.045 GPa, nu_LT 0.449), G_c 500 J/m^2:
  // 1.31e9 * 500 / 1e14 = 6.56 mm; the slender-arm length is 24.5 mm.
  EXPECT_NEAR(fem::crack_modulus(wood) / 1.31e9, 1.0, 0.005);
  const auto ten = law::make_linear_softening(10000 * kPa, 0.1 * mm);
  c = fem::choose_mesh(seed, wood, ten, prm);
  EXPECT_NEAR(c.zone_estimate / (6.56 * mm), 1.0, 0.005);
  // 0.82 mm, snapped down to a0 / n.
  EXPECT_LE(c.element_size, c.zone_estimate / fem::kAutoElementsPerZoneEstimate);
  EXPECT_GT(c.element_size, 0.99 * c.zone_estimate / fem::kAutoElementsPerZoneEstimate);

  const auto thirty = law::make_linear_softening(30000 * kPa, 0.02 * mm);
  c = fem::choose_mesh(seed, wood, thirty, prm);
  EXPECT_NEAR(c.element_size, seed.length / fem::kAutoMostElementsAlongLength, 1e-12); // 0.5
  EXPECT_NE(c.reason.find("cost floor"), std::string::npos) << c.reason;

  fem::FemParameters given;
  given.mesh.element_size = 1.7 * mm;
  c = fem::choose_mesh(seed, wood, thirty, given);
  EXPECT_FALSE(c.automatic);
  EXPECT_DOUBLE_EQ(c.element_size, 1.7 * mm);
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
// 2 mm elements while its note said the zone spans 0.65 elements. The issue asks for either
// G_ss within 2 % of J_tip + J_c or reached_steady_state false with the reason. Auto estimates
// the zone at 1.64 mm, which wants 0.2 mm elements; it runs at the cost floor (0.5 mm on the
// 300 mm specimen), where the zone (measured 0.92 mm) spans 1.8 elements: the run claims no
// steady state and says so (status zone_unresolved), and its G_ss is within the 2 % anyway
// (measured +0.42 %, docs/verification.md "The automatic mesh").
TEST(AutoMesh, TwentyMegapascalLawOnSeedDefaults) {
  const auto law = law::make_linear_softening(20000 * kPa, 0.05 * mm);
  const double j_tip = 100, G = j_tip + law.area();
  ASSERT_NEAR(law.area(), 500, 1e-9);
  const auto r = fem::simulate_dcb(specimen::Specimen(), specimen::Material(), law, j_tip,
                                   fem::FemParameters());
  print(r);
  EXPECT_FALSE(r.reached_steady_state);
  EXPECT_EQ(r.steady_state_status, result::SteadyStateStatus::zone_unresolved);
  EXPECT_TRUE(has_note(r, "no steady state claimed: the cohesive zone spans"));
  EXPECT_TRUE(has_note(r, "resolution: the cohesive zone is at most"));
  EXPECT_NEAR(r.G_ss / G, 1.0, 0.02);
}

// The 30 MPa / 0.02 mm law (J_c 300 J/m^2 on J_tip 100) on the seed defaults: its zone (about
// 0.3-0.5 mm) needs the 0.25 mm elements that took 20 s on the idle machine; auto runs at the
// 0.5 mm floor, where G_ss is +2.7 % (docs/verification.md, "Strong short laws"): outside the
// issue's 2 %, so the run must claim no steady state and give the reason and the size that
// would resolve the zone.
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
