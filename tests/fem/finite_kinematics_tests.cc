// Finite kinematics of the FEM (issue 13 item 5; docs/verification.md, "Finite rotations of the
// FEM arms"): FEM/Kinematics = finite against the elastica where small strain is off by more
// than 5 %, and against small strain where the arms hardly rotate. The LEFM composite DCB of the
// shared records' geometry (tests/common/thin_dcb_case.h) at initiation: J_tip sets the opening
// over crack length, which grows with sqrt(J_tip).
#include "common/notes.h"
#include "common/thin_dcb_case.h"
#include "fiberbridge/beam/dcb_beam.h"
#include "fiberbridge/beam/elastica.h"
#include "fiberbridge/core/units.h"
#include "fiberbridge/fem/dcb_simulation.h"
#include "fiberbridge/law/exponential_law.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <limits>
#include <string>

using namespace fiberbridge;
using units::mm;

namespace {

using test_notes::has_note;

/// The composite in LEFM with the given FEM kinematics; a short steady-state window so that the
/// run stops a few advances after initiation (the LEFM R curve is flat from the first advance).
result::SimulationResult fem_run(double j_tip, bool finite,
                                 const specimen::Material& material = thin_dcb_case::material(),
                                 double max_opening_increment = 0.5 * mm) {
  fem::FemParameters prm;
  prm.steady_state.window = 2 * mm;
  prm.nonlinear.max_opening_increment = max_opening_increment;
  if (finite)
    prm.nonlinear.kinematics = fem::FemParameters::Nonlinear::Kinematics::finite;
  return fem::simulate_dcb(thin_dcb_case::specimen(), material, law::NoBridgingLaw(), j_tip, prm);
}

/// The beam model with the elastica of the free arm (Beam/Kinematics = finite), itself checked
/// against Bisshopp and Drucker's elliptic-integral cantilever to 1e-9
/// (tests/beam/elastica_tests.cc).
result::SimulationResult elastica_run(double j_tip) {
  beam::BeamParameters prm;
  prm.finite_rotations = true;
  return beam::simulate_dcb(thin_dcb_case::specimen(), thin_dcb_case::material(),
                            law::NoBridgingLaw(), j_tip, prm);
}

} // namespace

// A cantilever against the elastica: arms nearly clamped at the crack tip (E_T = G_LT = 10 E_L,
// nu_LT = 0: corrected beam theory's root length chi h shrinks to 0.27 h, measured here as
// a_eff - a = 0.51 mm from the small-strain load). J_tip 30000 J/m^2 opens them to 0.70 of the
// crack length; the small-strain load is then 8 % low. The clamped Euler elastica of length
// a_eff under the FEM's finite-kinematics load (beam::free_arm_elastica, checked against Bisshopp
// and Drucker to 1e-9) predicts the FEM's finite/small load and opening ratios: the root length
// and the small-strain discretization error cancel in the ratios.
TEST(FemFiniteKinematics, ClampedArmFollowsTheElastica) {
  specimen::Material stiff = thin_dcb_case::material();
  stiff.E_T = 10 * stiff.E_L;
  stiff.G_LT = 10 * stiff.E_L;
  stiff.nu_LT = 0;
  const double j_tip = 30000;
  // LEFM is path independent: 2 mm opening steps (a quarter of the default's sub-steps) reach
  // the same states; the elastic solves are what the test pays for.
  const auto s = fem_run(j_tip, false, stiff, 2 * mm).rcurve.front();
  const auto f = fem_run(j_tip, true, stiff, 2 * mm).rcurve.front();
  const auto spec = thin_dcb_case::specimen();
  const double B = spec.width, h = spec.arm_thickness();
  const double EI = stiff.E_L * h * h * h / 12;              // per width
  const double a_eff = std::sqrt(j_tip * EI) / (s.load / B); // small strain: G = (P a / B)^2 / EI
  const auto e = beam::free_arm_elastica(EI, std::numeric_limits<double>::infinity(), a_eff, 0,
                                         f.load / B, {});
  const double load_ratio = f.load / s.load,
               opening_ratio = f.load_point_opening / s.load_point_opening;
  std::cout << "  a_eff " << a_eff / mm << " mm, opening/a " << f.load_point_opening / f.a
            << "; finite/small load " << load_ratio << " (elastica " << a_eff / e.projection
            << "), opening " << opening_ratio << " (elastica " << -2 * e.rise / s.load_point_opening
            << ")\n";
  EXPECT_NEAR(a_eff / f.a, 1.0, 0.02); // the arm is clamped to within 2 % of its length
  EXPECT_GT(load_ratio - 1, 0.05);     // small strain is off by more than 5 % here
  // Load: measured 1.2e-4 apart. The elastica's J at that load, (P X / B)^2 / EI, is J_tip when
  // the ratios agree; 1e-3 is the FEM's tip tolerance of the load search.
  EXPECT_NEAR(load_ratio / (a_eff / e.projection), 1.0, 1e-3);
  // Opening: measured 2.5e-4 apart. The clamped elastica of length a_eff stands in for a root
  // that rotates (a_eff - a = 1.5 % of a): its rotation at large opening is not exactly that of a
  // longer clamped arm. At most the root's share, 3 (a_eff - a)/a of the opening's
  // finite-rotation change (5 %), about 2e-3; 3e-3.
  EXPECT_NEAR(opening_ratio / (-2 * e.rise / s.load_point_opening), 1.0, 3e-3);
}

// J_tip 20000 J/m^2 opens the composite to 0.65 of its crack length at initiation (arm rotations
// of about half a radian): the small-strain load is more than 5 % below the elastica's there.
TEST(FemFiniteKinematics, FollowsTheElasticaWhereSmallStrainIsOff) {
  const double j_tip = 20000;
  const auto small = fem_run(j_tip, false);
  const auto finite = fem_run(j_tip, true);
  const auto elastica = elastica_run(j_tip);
  ASSERT_FALSE(small.rcurve.empty() || finite.rcurve.empty() || elastica.rcurve.empty());
  const auto &s = small.rcurve.front(), &f = finite.rcurve.front(), &e = elastica.rcurve.front();
  ASSERT_DOUBLE_EQ(f.a, e.a);
  std::cout << "  opening/a " << f.load_point_opening / f.a << "; load small " << s.load
            << ", finite " << f.load << ", elastica " << e.load << " N; opening finite "
            << f.load_point_opening / mm << ", elastica " << e.load_point_opening / mm << " mm\n";
  EXPECT_GT(f.load_point_opening / f.a, 0.6);
  // The case is one where small strain is not good enough: measured -5.6 %.
  EXPECT_LT(s.load / e.load - 1, -0.05);
  // FEM finite against the elastica: measured +0.47 % in load. The two models differ in their
  // small-strain part already (the same comparison with small kinematics in both: +0.17 %, the
  // root flexibility of corrected beam theory against the continuum); 1 % is twice the measured
  // gap and a fifth of the small-strain error the test must catch.
  EXPECT_NEAR(f.load / e.load, 1.0, 0.01);
  // Opening: measured -1.0 % (-0.34 % with small kinematics in both). The beam keeps the root
  // region on its elastic foundation at small rotation (docs/verification.md, "Finite rotations
  // of the beam arms"); on these arms that region is chi h = 2.9 mm of the 37.9 mm effective
  // length, and the gap to the FEM grows with the rotation. 1.5 %: half the finite-rotation
  // change of the opening (-4.9 %) would still be caught.
  EXPECT_NEAR(f.load_point_opening / e.load_point_opening, 1.0, 0.015);
  // The domain J in the reference configuration is path independent at this rotation: the
  // far-field domain (in the rotated free arms) and the tip domain agree (measured 1e-5; the
  // small-strain pair agrees to 4e-5). 1e-3 is the tip tolerance of the load search.
  for (const auto& p : finite.rcurve)
    EXPECT_NEAR(p.J_ff / p.J_tip, 1.0, 1e-3) << "a = " << p.a / mm << " mm";
  // The small-strain run says it is out of its range; the finite one has nothing to say.
  EXPECT_TRUE(has_note(small, "small strain: at a = "));
  EXPECT_FALSE(has_note(finite, "small strain: at a = "));
}

// Where the arms hardly rotate the two kinematics agree: at opening/a 0.011 (J_tip 5 J/m^2) the
// elastica puts the difference at 0.13 (opening/a)^2 = 1.6e-5 and the load line held at its mean
// instead of uniformly (an end effect a crack length away from the tip) at about 1e-4 (measured
// together: 9e-5), so 5e-4; at opening/a 0.11 (J_tip 500 J/m^2) the difference is the
// elastica's, 0.15 % (measured 0.22 %): between half and twice that catches a wrong sign or a
// missing geometric term.
TEST(FemFiniteKinematics, AgreesWithSmallStrainAtSmallOpenings) {
  {
    const auto s = fem_run(5, false).rcurve.front(), f = fem_run(5, true).rcurve.front();
    EXPECT_LT(f.load_point_opening / f.a, 0.012);
    EXPECT_NEAR(f.load / s.load, 1.0, 5e-4);
    EXPECT_NEAR(f.load_point_opening / s.load_point_opening, 1.0, 5e-4);
  }
  const auto s = fem_run(500, false).rcurve.front(), f = fem_run(500, true).rcurve.front();
  const double r = f.load_point_opening / f.a, expected = 0.13 * r * r;
  std::cout << "  opening/a " << r << ": finite/small load - 1 = " << f.load / s.load - 1
            << ", elastica estimate " << expected << "\n";
  EXPECT_GT(f.load / s.load - 1, 0.5 * expected);
  EXPECT_LT(f.load / s.load - 1, 2.0 * expected);
}
