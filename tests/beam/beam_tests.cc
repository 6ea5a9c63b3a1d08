// Unit and verification tests of the beam model of the DCB (docs/design.md sections 2 and 3).
#include "banded_lu.h" // private to the beam library: tests/beam/CMakeLists.txt adds its path
#include "fiberbridge/beam/arm_on_foundation.h"
#include "fiberbridge/beam/dcb_beam.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/units.h"
#include "fiberbridge/law/exponential_law.h"
#include "fiberbridge/law/piecewise_linear_law.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace fiberbridge;
using namespace fiberbridge::beam;
using result::SimulationResult;
using specimen::Material;
using specimen::Specimen;
using units::kPa;
using units::mm;
using units::MPa;

namespace {

constexpr double j_tip = 200; // seed: Douglas-fir initiation toughness [J/m^2]

bool has_note(const SimulationResult& r, const std::string& text) {
  return std::any_of(r.notes.begin(), r.notes.end(),
                     [&](const std::string& n) { return n.find(text) != std::string::npos; });
}

double energy_balance_error(const result::RCurvePoint& p) {
  return std::abs(p.external_work - p.strain_energy - p.zone_recoverable - p.dissipated) /
         p.external_work;
}

/// Allowed |R_J - Eq. 2| while the zone develops. The tip criterion holds the discrete tip J at
/// J_tip, so what remains is the trapezoid rule over the zone (second order: 0.2, 0.057, 0.015
/// J/m^2 for the PVA law at 200, 400, 800 elements; at most 4.5e-4 relative for the steep
/// 16 MPa/mm linear softening at 400). 1e-3 bounds these.
double eq2_tolerance(double exact) {
  return 1e-3 * exact;
}

/// The J_tip column is the other measure of the tip's release rate, k delta_tip^2/2 at the tip
/// node, which differs from the discrete tip J (the criterion) by the O(h_e^2) lumping of the
/// foundation: 0.23 % in the LEFM limit, up to 0.46 % with the steep bridging laws used here,
/// at 400 elements.
constexpr double tip_column_tolerance = 1e-2;

/// W = strain + foundation + zone recoverable + J_tip da + zone dissipation: the external work
/// is integrated by the trapezoid rule over the recorded states and the zone by the nodal
/// trapezoid rule, both second order; measured at most 5.3e-5 at 400 elements.
constexpr double balance_tolerance = 2e-4;

/// The first state whose notch root has left a0 (size() if none).
std::size_t root_move_index(const SimulationResult& r, double a0) {
  std::size_t k = 0;
  while (k < r.rcurve.size() && !(r.rcurve[k].root > a0 + 1e-9))
    ++k;
  return k;
}

// A law with a zone much shorter than the ligament (about 15 mm on the seed specimen), so the
// specimen reaches a self-similar steady state well before its far end.
law::PiecewiseLinearLaw short_zone_law() {
  return law::make_linear_softening(4 * MPa, 0.25 * mm);
}

} // namespace

TEST(BandedLU, SolvesWithPivotingLikeADenseSolve) {
  // Zero diagonal entries force row exchanges; compare with the known solution.
  const std::size_t n = 7;
  internal::BandedLU A(n, 2, 1);
  for (std::size_t i = 0; i < n; ++i) {
    A(i, i) = (i % 2 == 0) ? 0.0 : 3.0 + i;
    if (i + 1 < n)
      A(i, i + 1) = 1.0 + 0.5 * i;
    if (i >= 1)
      A(i, i - 1) = 2.0 - 0.25 * i;
    if (i >= 2)
      A(i, i - 2) = 0.5 + 0.1 * i;
  }
  std::vector<double> x_exact(n), b(n, 0.0);
  for (std::size_t i = 0; i < n; ++i)
    x_exact[i] = 1.0 + 0.3 * i - 0.05 * i * i;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = (i >= 2 ? i - 2 : 0); j <= std::min(n - 1, i + 1); ++j)
      b[i] += A(i, j) * x_exact[j];
  ASSERT_TRUE(A.factorize());
  A.solve(b);
  for (std::size_t i = 0; i < n; ++i)
    EXPECT_NEAR(b[i], x_exact[i], 1e-12);
}

TEST(ArmOnFoundation, EulerLimitIsKanninensRootRotation) {
  // With a shear-rigid arm the Timoshenko solution must reduce to the Euler beam on a Winkler
  // foundation, whose root rotation length is 1/lambda, lambda^4 = k_w/(4 EI) (Kanninen 1973).
  ArmConstants arm = arm_constants(Specimen{}, Material{}, 5.0 / 6.0, 1e11);
  arm.S *= 1e8;
  const double lambda = std::pow(arm.k_w() / (4 * arm.EI), 0.25);
  // The remaining shear flexibility enters as EI lambda^2/S ~ 1e-14 here.
  EXPECT_NEAR(root_rotation_length(arm) * lambda, 1.0, 1e-8);
  // Hetenyi's end deflection under an end moment: |w(0)| = 2 lambda^2 M/k_w.
  const auto f = semi_infinite_end_flexibility(arm);
  EXPECT_NEAR(std::abs(f.w_M) * arm.k_w() / (2 * lambda * lambda), 1.0, 1e-8);
}

TEST(ArmOnFoundation, CalibratedFoundationGivesCorrectedBeamTheoryLoad) {
  const Specimen s;
  const Material m;
  const double k = calibrated_foundation_modulus(s, m, 5.0 / 6.0);
  const ArmConstants arm = arm_constants(s, m, 5.0 / 6.0, k);
  // Bisection to 1e-13 in k; c(k) is smooth, so c matches chi h to round-off.
  EXPECT_NEAR(root_rotation_length(arm), specimen::cbt_chi(m) * s.arm_thickness(), 1e-9);
  // The tip G of the arm is its section J at the tip (M = P a, Q = -P, theta = P (a t_M - t_Q)):
  // P^2 (a^2 + 2 c a + c2)/(B EI) with c = -EI t_M and c2 = EI/S + 2 EI t_Q. For the
  // semi-infinite Timoshenko arm on a Winkler foundation c2 = c^2, i.e. G = P^2 (a + c)^2/(B EI)
  // as in Kanninen's Euler case; then with c = chi h the analytic LEFM load is CBT's at every
  // crack length, to round-off. (Checked here, with the material of the seed and an isotropic
  // one below.)
  for (double a : {60 * mm, 100 * mm, 150 * mm, 250 * mm})
    EXPECT_NEAR(lefm_state(arm, j_tip, a).load / specimen::cbt_load_at_crack_length(s, m, j_tip, a),
                1.0, 1e-9)
        << "a = " << a / mm << " mm";
  // The physical guess 2 E_T/h is softer: the shear of the arm is not in it.
  EXPECT_GT(k, 2 * m.E_T / s.arm_thickness());
  Material iso;
  iso.E_L = iso.E_T = 70e9;
  iso.G_LT = 70e9 / 2.6;
  iso.nu_LT = 0.3;
  const ArmConstants arm_iso =
      arm_constants(s, iso, 5.0 / 6.0, calibrated_foundation_modulus(s, iso, 5.0 / 6.0));
  EXPECT_NEAR(lefm_state(arm_iso, j_tip, 80 * mm).load /
                  specimen::cbt_load_at_crack_length(s, iso, j_tip, 80 * mm),
              1.0, 1e-9);
}

TEST(ArmOnFoundation, RejectsAMaterialNoFoundationCanMatch) {
  // Extremely shear-soft arm: CBT's chi h is below the rotation that shear alone gives.
  Material m;
  m.G_LT = 0.2 * m.E_T;
  m.E_T = 100 * m.E_L;
  m.nu_LT = 0;
  EXPECT_THROW(calibrated_foundation_modulus(Specimen{}, m, 5.0 / 6.0), InputError);
}

TEST(BeamLefm, LoadFollowsCbtAndEveryRIsJtip) {
  const Specimen s;
  const Material m;
  BeamParameters p;
  p.steady_state_window = 1.0; // run to the end of the ligament
  const auto r = simulate_dcb(s, m, law::NoBridgingLaw{}, j_tip, p);
  ASSERT_GT(r.rcurve.size(), 300u);
  EXPECT_TRUE(has_note(r, "ligament ran out"));
  const double a_max_compared = 200 * mm;
  int compared = 0;
  for (const auto& q : r.rcurve) {
    // R_J (the load-line J) equals the tip J held by the criterion if J is path independent
    // along the traction-free crack: round-off only.
    EXPECT_NEAR(q.R_J / j_tip, 1.0, 1e-9) << "a = " << q.a / mm;
    EXPECT_NEAR(q.J_tip / j_tip, 1.0, 0.5 * tip_column_tolerance) << "a = " << q.a / mm;
    // The energy released per area, (dW - dU)/(B da), is independent of J: it checks that the
    // section J is the energy release rate. Trapezoid work and central differences in a are
    // second order in the 0.5 mm advance: 1e-5 on a long ligament, up to 1.7e-4 where the
    // ligament is under 50 mm and the compliance changes fast (one-sided at the last state).
    EXPECT_NEAR(q.R_energy / j_tip, 1.0, 5e-4) << "a = " << q.a / mm;
    EXPECT_DOUBLE_EQ(q.R_eq2, j_tip);
    EXPECT_NEAR(q.zone_length, 0.0, 1e-12);
    if (q.a > a_max_compared)
      continue;
    // On a ligament longer than ~6/lambda (100 mm) the semi-infinite analytic model holds and
    // its load is exactly CBT's (test above). The FE load differs by the O(h_e^2) lumping
    // (0.006 % at a = 100 mm) and the finite ligament (0.015 % at a = 200 mm); bound 0.1 %.
    const double P_cbt = specimen::cbt_load_at_crack_length(s, m, j_tip, q.a);
    EXPECT_NEAR(q.load / P_cbt, 1.0, 1e-3) << "a = " << q.a / mm;
    // The opening is CBT's in the a^3 and a^2 terms; the a^1 and a^0 terms (shear and
    // foundation) differ: 0.35 % at a = 100 mm, falling like 1/a^2. Bound 0.6 %.
    EXPECT_NEAR(q.load_point_opening / specimen::cbt_opening(s, m, q.load, q.a), 1.0, 6e-3)
        << "a = " << q.a / mm;
    ++compared;
  }
  EXPECT_GT(compared, 150);
  for (const auto& q : r.rcurve)
    EXPECT_LT(energy_balance_error(q), balance_tolerance) << "a = " << q.a / mm;
}

TEST(BeamLefm, GivenFoundationModulusMatchesTheAnalyticArmOnFoundation) {
  // With the physical guess k = 2 E_T/h instead of the CBT calibration, the FE model must still
  // reproduce the closed-form semi-infinite Timoshenko arm on that foundation (same 0.3 % lumping
  // bound as above), and no longer CBT: the test sees the foundation, not just the calibration.
  const Specimen s;
  const Material m;
  BeamParameters p;
  p.foundation_modulus = 2 * m.E_T / s.arm_thickness();
  p.steady_state_window = 1.0;
  p.minimum_ligament = 100 * mm;
  const auto r = simulate_dcb(s, m, law::NoBridgingLaw{}, j_tip, p);
  const ArmConstants arm = arm_constants(s, m, 5.0 / 6.0, p.foundation_modulus);
  double max_cbt_difference = 0;
  for (const auto& q : r.rcurve) {
    const auto exact = lefm_state(arm, j_tip, q.a);
    EXPECT_NEAR(q.load / exact.load, 1.0, 1e-3) << "a = " << q.a / mm;
    EXPECT_NEAR(q.load_point_opening / exact.load_point_opening, 1.0, 1e-3) << "a = " << q.a / mm;
    max_cbt_difference =
        std::max(max_cbt_difference,
                 std::abs(exact.load / specimen::cbt_load_at_crack_length(s, m, j_tip, q.a) - 1));
  }
  EXPECT_GT(max_cbt_difference, 1e-2);
}

TEST(BeamLefm, DiscretizationErrorsConvergeAtSecondOrder) {
  // In the LEFM limit the only discretization error is the nodal lumping of the foundation: the
  // initiation load (vs CBT, which the analytic model matches exactly) and the foundation
  // estimate of the tip release rate (vs J_tip) must improve ~4x per halving of the elements.
  const Specimen s;
  const Material m;
  const double P_cbt = specimen::cbt_load_at_crack_length(s, m, j_tip, s.initial_crack);
  double load_err[3], tip_err[3];
  const int n[3] = {100, 200, 400};
  for (int i = 0; i < 3; ++i) {
    BeamParameters p;
    p.n_elements = n[i];
    p.max_advances = 1;
    const auto r = simulate_dcb(s, m, law::NoBridgingLaw{}, j_tip, p);
    load_err[i] = std::abs(r.rcurve.front().load / P_cbt - 1);
    tip_err[i] = std::abs(r.rcurve.front().J_tip / j_tip - 1);
  }
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(load_err[i] / load_err[i + 1], 4.0, 0.6) << n[i] << " elements";
    EXPECT_NEAR(tip_err[i] / tip_err[i + 1], 4.0, 0.6) << n[i] << " elements";
  }
  EXPECT_LT(load_err[2], 1e-4);
}

TEST(BeamLefm, ShortLigamentEndsInSnapBackWithoutGarbage) {
  // Near the far end the arm compliance explodes: the load-point opening falls while the crack
  // grows (a displacement-controlled test would jump). The crack-length control must still give
  // R = J_tip, and J_ff must include the lifted far end of the ligament.
  BeamParameters p;
  p.steady_state_window = 1.0;
  p.minimum_ligament = 5 * mm;
  const auto r = simulate_dcb(Specimen{}, Material{}, law::NoBridgingLaw{}, j_tip, p);
  EXPECT_TRUE(has_note(r, "snap-back"));
  const auto& last = r.rcurve.back();
  EXPECT_GT(last.a, 290 * mm);
  double max_opening = 0;
  for (const auto& q : r.rcurve)
    max_opening = std::max(max_opening, q.load_point_opening);
  EXPECT_LT(last.load_point_opening, 0.9 * max_opening);
  for (const auto& q : r.rcurve) {
    ASSERT_TRUE(std::isfinite(q.load) && std::isfinite(q.R_energy));
    // J_ff without its far-end term would fall to a few J/m^2 here (the ligament lifts).
    EXPECT_NEAR(q.J_ff / j_tip, 1.0, 1e-9) << "a = " << q.a / mm;
    // The compliance changes fast near the end: the second-order R_energy error grows, and the
    // difference at the last state is one-sided (first order). 1 % bounds it.
    EXPECT_NEAR(q.R_energy / j_tip, 1.0, 1e-2) << "a = " << q.a / mm;
  }
}

TEST(BeamLinearSoftening, RJFollowsTheAnalyticRCurveWhileTheZoneDevelops) {
  const auto law = short_zone_law();
  const double s_c = 4 * MPa;
  const Specimen s;
  const auto r = simulate_dcb(s, Material{}, law, j_tip, BeamParameters{});
  const std::size_t move = root_move_index(r, s.initial_crack);
  ASSERT_GT(move, 20u);
  ASSERT_LT(move, r.rcurve.size());
  double max_rel_bridging_excess = 0;
  for (std::size_t k = 1; k < move; ++k) {
    const auto& q = r.rcurve[k];
    // Linear softening: Eq. 2 is exactly J_tip + s_c delta_root/2 (seed Eq. 7's case).
    const double exact = j_tip + 0.5 * s_c * q.delta_root;
    // R_J = J_ff - delta sigma/2 with J_ff the section J at the load line: path independence
    // (Eq. 1) up to the tip lumping (0.47 J/m^2 here) and the trapezoid rule on the zone.
    EXPECT_NEAR(q.R_J, exact, eq2_tolerance(exact)) << "a = " << q.a / mm;
    const double eq1 = law::j_far_field_eq1(law, j_tip, q.delta_root);
    EXPECT_NEAR(q.J_ff, eq1, eq2_tolerance(eq1)) << "a = " << q.a / mm;
    EXPECT_NEAR(q.J_tip / j_tip, 1.0, tip_column_tolerance) << "a = " << q.a / mm;
    max_rel_bridging_excess =
        std::max(max_rel_bridging_excess, (q.R_energy - q.R_eq2) / (q.R_eq2 - j_tip));
  }
  // The energy-based R exceeds Eq. 2 while the zone grows (not self-similar): docs/design.md
  // section 2 expects a few per cent; a bridging part off by more than 10 % would point at an
  // energy error.
  std::printf("linear softening: max (R_energy - R_eq2)/(R_eq2 - J_tip) before the root moves "
              "= %.4f\n",
              max_rel_bridging_excess);
  EXPECT_GT(max_rel_bridging_excess, 0.0);
  EXPECT_LT(max_rel_bridging_excess, 0.10);
  EXPECT_LT(r.rdelta_rel_error_vs_eq2, 1e-3);
}

TEST(BeamLinearSoftening, PlateauAtJtipPlusAreaAndEnergyBalanceCloses) {
  const auto law = short_zone_law();
  const double g_ss = j_tip + law.area();
  const auto r = simulate_dcb(Specimen{}, Material{}, law, j_tip, BeamParameters{});
  ASSERT_TRUE(r.reached_steady_state);
  // R_energy's plateau is G_ss for a self-similar zone; a DCB zone shortens slowly with a (the
  // root runs ~0.5 % faster than the tip here), which adds ~0.26 %. 1 % bounds it.
  EXPECT_NEAR(r.G_ss / g_ss, 1.0, 1e-2);
  // R_J is J_ff once sigma(delta_root) = 0: Eq. 1, up to the zone quadrature (eq2_tolerance).
  EXPECT_NEAR(r.rcurve.back().R_J / g_ss, 1.0, 1e-3);
  EXPECT_GT(r.rcurve.back().delta_root, law.critical_opening());
  EXPECT_NEAR(r.rcurve.back().R_eq2, g_ss, 1e-9);
  for (const auto& q : r.rcurve)
    EXPECT_LT(energy_balance_error(q), balance_tolerance) << "a = " << q.a / mm;
}

TEST(BeamLinearSoftening, SteadyStateToughnessConvergesWithTheMesh) {
  const auto law = short_zone_law();
  const double g_ss = j_tip + law.area();
  double g[3];
  const int n[3] = {100, 200, 400};
  for (int i = 0; i < 3; ++i) {
    BeamParameters p;
    p.n_elements = n[i];
    p.tip_advance = 2 * mm; // the same recorded states on every mesh
    const auto r = simulate_dcb(Specimen{}, Material{}, law, j_tip, p);
    ASSERT_TRUE(r.reached_steady_state) << n[i] << " elements";
    g[i] = r.G_ss;
    std::printf("G_ss with %d elements: %.3f J/m^2 (J_tip + J_c = %.3f)\n", n[i], g[i], g_ss);
  }
  // Successive differences shrink at least like a first-order method (the root position is
  // interpolated between nodes); the finest two differ by under 0.1 %. The limit is not J_tip +
  // J_c: the DCB zone is not exactly self-similar (see the plateau test).
  EXPECT_LT(std::abs(g[2] - g[1]), 0.5 * std::abs(g[1] - g[0]));
  EXPECT_LT(std::abs(g[2] - g[1]) / g_ss, 1e-3);
}

TEST(BeamLinearSoftening, ZoneLongerThanTheLigamentEndsWithADiagnosis) {
  // sigma_c 0.3 MPa, delta_c 20 mm: the root opening cannot reach delta_c on a 200 mm ligament.
  const auto law = law::make_linear_softening(0.3 * MPa, 20 * mm);
  const Specimen s;
  const auto r = simulate_dcb(s, Material{}, law, j_tip, BeamParameters{});
  EXPECT_FALSE(r.reached_steady_state);
  EXPECT_TRUE(std::isnan(r.G_ss));
  EXPECT_TRUE(has_note(r, "bridging zone is longer than the ligament"));
  ASSERT_FALSE(r.rcurve.empty());
  for (const auto& q : r.rcurve) {
    ASSERT_TRUE(std::isfinite(q.R_J) && std::isfinite(q.R_energy) && std::isfinite(q.load));
    EXPECT_DOUBLE_EQ(q.root, s.initial_crack);
  }
  EXPECT_LT(r.rcurve.back().delta_root, law.critical_opening());
  EXPECT_LE(r.rcurve.back().a, s.length - s.height + 1e-9);
}

TEST(BeamLinearSoftening, UnresolvedZoneIsDiagnosedAndTheAdviceWorks) {
  // sigma_c 1 MPa, delta_c 0.01 mm: the steady zone is about 1.1 mm, two tip advances of the
  // default mesh. The result must refuse a G_ss and say how to refine; refined as advised
  // (3000 elements, 0.07 mm advances: 16 per zone) the plateau is J_tip + J_c.
  const auto law = law::make_linear_softening(1 * MPa, 0.01 * mm);
  const double g_ss = j_tip + law.area();
  const auto coarse = simulate_dcb(Specimen{}, Material{}, law, j_tip, BeamParameters{});
  EXPECT_FALSE(coarse.reached_steady_state);
  EXPECT_TRUE(std::isnan(coarse.G_ss));
  EXPECT_TRUE(has_note(coarse, "unresolved bridging zone"));
  BeamParameters fine;
  fine.n_elements = 3000;
  fine.tip_advance = 0.07 * mm;
  const auto r = simulate_dcb(Specimen{}, Material{}, law, j_tip, fine);
  ASSERT_TRUE(r.reached_steady_state);
  // A 1 mm zone in a 17.5 mm thick arm is nearly self-similar; bound 0.1 %.
  EXPECT_NEAR(r.G_ss / g_ss, 1.0, 1e-3);
  for (const auto& q : r.rcurve)
    EXPECT_LT(energy_balance_error(q), balance_tolerance) << "a = " << q.a / mm;
}

TEST(BeamExponential, RigidLawFollowsEq2) {
  // A rigid law without regularization: the tip node carries sigma(0+), the rest respond().
  const law::ExponentialLaw law(2 * MPa, 0.5 * mm);
  const Specimen s;
  const auto r = simulate_dcb(s, Material{}, law, j_tip, BeamParameters{});
  const std::size_t move = root_move_index(r, s.initial_crack);
  ASSERT_GT(move, 10u);
  for (std::size_t k = 1; k < move; ++k) {
    const auto& q = r.rcurve[k];
    const double exact = law::r_curve_eq2(law, j_tip, q.delta_root);
    EXPECT_NEAR(q.R_J, exact, eq2_tolerance(exact)) << "a = " << q.a / mm;
  }
}

TEST(BeamPva, ControlTrilinearLawOnTheSeedSpecimen) {
  // Seed Table 1, PVA control: d1 0.1 mm/661 kPa, d2 1.0 mm/187 kPa, dc 6 mm, J_tip 200.
  const auto law = law::make_trilinear({0.1 * mm, 661 * kPa, 1.0 * mm, 187 * kPa, 6.0 * mm});
  const Specimen s;
  const auto r = simulate_dcb(s, Material{}, law, j_tip, BeamParameters{});
  const double g_ss = j_tip + law.area();
  const std::size_t move = root_move_index(r, s.initial_crack);
  ASSERT_LT(move, r.rcurve.size()) << "the root never moved";
  double peak = 0, a_peak = 0, max_dev = 0, a_dev = 0;
  for (const auto& q : r.rcurve) {
    if (q.load > peak) {
      peak = q.load;
      a_peak = q.a;
    }
    EXPECT_LT(energy_balance_error(q), balance_tolerance) << "a = " << q.a / mm;
  }
  for (std::size_t k = 1; k < move; ++k) {
    const auto& q = r.rcurve[k];
    EXPECT_NEAR(q.R_J, q.R_eq2, eq2_tolerance(q.R_eq2)) << "a = " << q.a / mm;
    const double dev = (q.R_energy - q.R_eq2) / (q.R_eq2 - j_tip);
    // Relative to a bridging part of at least 10 % of J_c (before that it divides small numbers).
    if (q.R_eq2 - j_tip > 0.1 * law.area() && std::abs(dev) > std::abs(max_dev)) {
      max_dev = dev;
      a_dev = q.a;
    }
  }
  const auto& mv = r.rcurve[move];
  std::printf("PVA control on the seed DCB (%zu states, %.3f s): root moves at a = %.1f mm "
              "(growth %.1f mm, zone %.1f mm, delta_root %.2f mm); peak load %.1f N at a = %.1f "
              "mm; G_ss %.1f J/m^2 (J_tip + J_c = %.1f), steady state %s; max (R_energy - "
              "R_eq2)/(R_eq2 - J_tip) = %.4f at a = %.1f mm\n",
              r.rcurve.size(), r.wall_time_s, mv.a / mm, (mv.a - s.initial_crack) / mm,
              mv.zone_length / mm, mv.delta_root / mm, peak, a_peak / mm, r.G_ss, g_ss,
              r.reached_steady_state ? "reached" : "not reached", max_dev, a_dev / mm);
  for (const auto& n : r.notes)
    std::printf("  note: %s\n", n.c_str());
  // R_J after the root moved is Eq. 1 at delta_c: J_tip + J_c up to the zone quadrature.
  EXPECT_NEAR(mv.R_J / g_ss, 1.0, 1e-3);
  // docs/design.md section 2: R_energy differs from Eq. 2 by a few per cent while the zone
  // develops.
  EXPECT_GT(max_dev, 0.0);
  EXPECT_LT(max_dev, 0.10);
  EXPECT_NEAR(r.G_ss / g_ss, 1.0, 1e-3);
  EXPECT_LT(r.rdelta_rel_error_vs_eq2, 1e-3);
}

TEST(BeamInput, UnusableInputIsReportedWithTheKey) {
  const auto law = short_zone_law();
  BeamParameters p;
  p.tip_advance = 0;
  EXPECT_THROW(simulate_dcb(Specimen{}, Material{}, law, j_tip, p), InputError);
  EXPECT_THROW(simulate_dcb(Specimen{}, Material{}, law, -1.0, BeamParameters{}), InputError);
  Specimen s;
  s.initial_crack = 0.29;
  EXPECT_THROW(simulate_dcb(s, Material{}, law, j_tip, BeamParameters{}), InputError);
  try {
    BeamParameters q;
    q.n_elements = 2;
    simulate_dcb(Specimen{}, Material{}, law, j_tip, q);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("Number of elements"), std::string::npos);
  }
}
