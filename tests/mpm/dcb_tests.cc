// Verification runs of the DCB model on a small specimen (120 x 20 mm, a0 40 mm, 4 cells through
// each arm): a stationary crack (path independence of J, energy balance, compliance), LEFM
// propagation (no bridging) and a linear-softening zone (R_J against J_tip + s_c delta/2).
// Coarse on purpose: each run takes seconds; the tolerances state what 4 cells per arm give.
// Energy release during growth was 15-20 % low with the per-line CRAMP crossing test (a
// free end of the crack-face layer at the tip recoiled at every advance and left a strain in the
// face particles that no later step undid); the fields now split per node (Crack::splits).
#include "fiberbridge/core/error.h"
#include "fiberbridge/law/exponential_law.h"
#include "fiberbridge/law/piecewise_linear_law.h"
#include "fiberbridge/mpm/dcb.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

using namespace fiberbridge;
using namespace fiberbridge::mpm;

namespace {

specimen::Specimen small_specimen() {
  specimen::Specimen s;
  s.length = 0.120;
  s.height = 0.020;
  s.initial_crack = 0.040;
  s.width = 0.035;
  return s;
}

MpmParameters coarse() {
  MpmParameters p;
  p.cell_size = 2.5e-3;
  p.loading_periods = 8;
  p.vtu_every_advances = 0;
  return p;
}

} // namespace

TEST(MpmDcb, StationaryCrackJIsPathIndependentAndEnergyBalances) {
  const specimen::Specimen s = small_specimen();
  const specimen::Material m;
  const law::NoBridgingLaw none;
  DcbModel model(s, m, none, 200, coarse());
  const double T = 8 * model.vibration_period();
  while (model.solver().time() < T)
    ASSERT_TRUE(model.step(false));
  const ExplicitSolver& solver = model.solver();

  // Path independence: the tip frame (2-4 cells) and the far-field strips (2 cells wide, at
  // a0/2 and in the ligament) enclose the same traction-free crack. Measured: 1.4 % apart at 4
  // cells per arm.
  const double j_tip = model.tip_j();
  const double j_ff = model.far_field_j();
  EXPECT_NEAR(j_tip / j_ff, 1.0, 0.04) << "J_tip " << j_tip << ", J_ff " << j_ff;

  // Energy: work of the loading block = strain + kinetic energy + PIC damping loss + numerical
  // loss of the explicit update, to the scheme's higher-order remainder.
  const double W = solver.external_work();
  const double balance = W - solver.strain_energy() - solver.kinetic_energy() -
                         solver.damping_loss() - solver.numerical_loss();
  // Measured 1.5e-4 of the work (4e-3 before the numerical loss was counted).
  EXPECT_LT(std::fabs(balance), 0.002 * W);

  // Compliance against corrected beam theory. The crack's end lies one cell ahead of the last
  // split node column (Crack::splits), where the partly split cell separates the material:
  // measured load 3.4 % above CBT at 4 cells per arm (the crack acts 0.3 cell shorter), a
  // first-order discretization error. 5 % bounds that level and catches a wrong modulus or a
  // missing arm (factors of 2 and more).
  const double P_cbt =
      model.load_point_opening() / specimen::cbt_opening(s, m, 1.0, s.initial_crack);
  EXPECT_NEAR(model.load() / P_cbt, 1.0, 0.05);
  // Quasi-static: the kinetic energy of the moving arms stays far below the strain energy.
  EXPECT_LT(solver.kinetic_energy(), 0.01 * solver.strain_energy());
  std::printf("stationary: J_tip/J_ff %.4f, balance %.2e W, P/P_cbt %.4f\n", j_tip / j_ff,
              balance / W, model.load() / P_cbt);
}

// Cell-size convergence of the load-point response: the stationary crack's stiffness (load over
// load-line opening after 8 arm periods of quasi-static loading) against corrected beam theory
// at 5, 2.5 and 1.25 mm cells (2, 4 and 8 cells per arm). Measured: +12.4, +3.4, -0.5 %, an
// observed order of 1.2 (the tip column makes the crack act about 0.3 cell shorter: first
// order), extrapolated limit -3.6 %. CBT is not the exact answer: the serial FEM on the same
// specimen measures -1.1 % at 1 mm and -1.6 % at 0.5 mm elements (stiffness at initiation), and
// the MPM's load, a moving average of the reaction, lags the rising load by about 0.7 %; the
// limits then agree to about 1 %. That limit is not asserted (it rests on an extrapolation).
// Asserted: the error falls in magnitude at each level, with an order of at least 0.7 (a scheme
// that stopped converging, e.g. a load line or tip fixed in cells, gives about 0).
TEST(MpmDcb, StationaryLoadPointResponseConvergesWithTheCell) {
  const specimen::Specimen s = small_specimen();
  const specimen::Material m;
  const law::NoBridgingLaw none;
  std::vector<double> error;
  for (const double cell : {5e-3, 2.5e-3, 1.25e-3}) {
    MpmParameters p = coarse();
    p.cell_size = cell;
    DcbModel model(s, m, none, 200, p);
    const double T = 8 * model.vibration_period();
    while (model.solver().time() < T)
      ASSERT_TRUE(model.step(false));
    const double stiffness_cbt = 1 / specimen::cbt_opening(s, m, 1.0, s.initial_crack);
    error.push_back(model.load() / model.load_point_opening() / stiffness_cbt - 1);
  }
  const double order = std::log2((error[0] - error[1]) / (error[1] - error[2]));
  const double limit = error[2] - (error[1] - error[2]) / (std::pow(2.0, order) - 1);
  std::printf("stationary stiffness vs CBT: %+.4f %+.4f %+.4f at 5, 2.5, 1.25 mm; order %.2f, "
              "extrapolated %+.4f\n",
              error[0], error[1], error[2], order, limit);
  EXPECT_LT(std::fabs(error[1]), std::fabs(error[0]));
  EXPECT_LT(std::fabs(error[2]), std::fabs(error[1]));
  EXPECT_GT(order, 0.7);
}

TEST(MpmDcb, ParallelParticleLoopsGiveTheSameResponse) {
  // Two threads share the particle chunks and the coloured scatter blocks; the chunks, the
  // blocks and the order their sums are added in do not depend on the threads, so the response
  // is the same to the bit (a tolerance would hide a race).
  const specimen::Specimen s = small_specimen();
  const specimen::Material m;
  const auto law = law::make_linear_softening(1e6, 0.2e-3);
  MpmParameters p = coarse();
  p.threads = 1;
  DcbModel serial(s, m, law, 200, p);
  p.threads = 2;
  DcbModel parallel(s, m, law, 200, p);
  const double T = 3 * serial.vibration_period();
  while (serial.solver().time() < T) {
    ASSERT_TRUE(serial.step(true));
    ASSERT_TRUE(parallel.step(true));
  }
  EXPECT_EQ(serial.solver().parallel_steps(), 0);
  // The probe runs 20 of every 1000 steps with the helper, whichever way is faster.
  EXPECT_GE(parallel.solver().parallel_steps(), 20);
  const double U = serial.solver().strain_energy();
  EXPECT_GT(U, 0);
  EXPECT_EQ(parallel.solver().strain_energy(), U);
  EXPECT_EQ(parallel.solver().damping_loss(), serial.solver().damping_loss());
  EXPECT_EQ(parallel.load(), serial.load());
  EXPECT_EQ(parallel.tip_j(), serial.tip_j());
  EXPECT_EQ(parallel.crack().tip(), serial.crack().tip());
}

TEST(MpmDcb, RejectsUnusableInput) {
  specimen::Specimen s = small_specimen();
  const law::NoBridgingLaw none;
  MpmParameters p = coarse();
  p.cell_size = 6e-3; // fewer than 2 cells through a 10 mm arm
  EXPECT_THROW(DcbModel(s, specimen::Material{}, none, 200, p), InputError);
  p = coarse();
  p.cfl = 1.5;
  EXPECT_THROW(DcbModel(s, specimen::Material{}, none, 200, p), InputError);
  EXPECT_THROW(DcbModel(s, specimen::Material{}, none, -1, coarse()), InputError);
}

TEST(MpmDcb, NotesArmsWithFewerThanThreeCellsThroughTheThickness) {
  // 4 mm cells on a 10 mm arm: 2.5 cells, accepted (>= 2) but noted (under 3 the arm bends over
  // 5 % too stiff, MpmCantilever.BendingNeedsCellsThroughTheThickness); 2.5 mm cells: 4, quiet.
  const specimen::Specimen s = small_specimen();
  const law::NoBridgingLaw none;
  auto thin_arm_noted = [&](double cell) {
    MpmParameters p = coarse();
    p.cell_size = cell;
    p.max_steps = 3; // the note is made at setup; no need to load
    DcbModel model(s, specimen::Material{}, none, 200, p);
    const auto r = model.run();
    return std::any_of(r.notes.begin(), r.notes.end(), [](const std::string& n) {
      return n.find("thin arm: MPM/Cell size") != std::string::npos;
    });
  };
  EXPECT_TRUE(thin_arm_noted(4e-3));
  EXPECT_FALSE(thin_arm_noted(2.5e-3));
}

namespace {

/// The propagation runs load 4x slower than the default: quasi-static growth, where the result
/// no longer depends on the growth criterion's J window (linear softening, G_ss for windows of
/// 0.25, 0.35 and 0.5 arm periods: -2.3, -2.4, -2.1 %; at the default 8 loading periods the
/// loading rate cuts the window at some advances and G_ss moved between -0.6 and -6.0 % with
/// the window rule, docs/verification.md). A verification run should measure the
/// discretization, not the rate.
MpmParameters quasi_static() {
  MpmParameters p = coarse();
  p.loading_periods = 32;
  return p;
}

/// One propagation run per law, shared by the tests that read it (each run takes seconds).
struct PropagationRun {
  specimen::Specimen specimen = small_specimen();
  specimen::Material material;
  std::unique_ptr<law::TractionLaw> law;
  result::SimulationResult result;
  PropagationRun(std::unique_ptr<law::TractionLaw> l) : law(std::move(l)) {
    result = simulate_dcb(specimen, material, *law, 200, quasi_static(), "");
  }
};

const PropagationRun& lefm_run() {
  static const PropagationRun run(std::make_unique<law::NoBridgingLaw>());
  return run;
}

// Linear softening, s_c 1 MPa, delta_c 0.2 mm (J_c = 100 J/m^2): a zone of about 4 cells that
// reaches steady state within the specimen.
const PropagationRun& linear_run() {
  static const PropagationRun run(
      std::make_unique<law::PiecewiseLinearLaw>(law::make_linear_softening(1e6, 0.2e-3)));
  return run;
}

double mean(const std::vector<double>& v) {
  double s = 0;
  for (double x : v)
    s += x;
  return v.empty() ? result::not_available : s / v.size();
}

} // namespace

namespace {

// Quasi-static energy released per crack area by one advance of `da` at constant load-line
// opening from a state with G = J_tip at length a, over J_tip: the mean of G over the step,
// f = (1/C(a) - 1/C(a + da)) C(a)^2 / (da C'(a)) with the corrected-beam-theory compliance C
// (about 1 - 2 da/(a + chi h)). A discrete tip that advances when G reaches J_tip releases this,
// not J_tip: the finite-step error that vanishes with da.
double step_release_fraction(const specimen::Specimen& s, const specimen::Material& m, double a,
                             double da) {
  auto C = [&](double x) { return specimen::cbt_opening(s, m, 1.0, x); };
  const double h = 1e-6;
  const double dC = (C(a + h) - C(a - h)) / (2 * h);
  return (1 / C(a) - 1 / C(a + da)) * C(a) * C(a) / (da * dC);
}

double standard_error(const std::vector<double>& v) {
  const double m = mean(v);
  double s = 0;
  for (double x : v)
    s += (x - m) * (x - m);
  return std::sqrt(s / (v.size() - 1) / v.size());
}

} // namespace

TEST(MpmDcbPropagation, LefmGrowthCriterionStabilityAndEnergyRelease) {
  const auto& run = lefm_run();
  const auto& r = run.result;
  ASSERT_GT(r.rcurve.size(), 15u);
  const double J = 200, da = coarse().cell_size * coarse().growth_step_cells;
  double previous_a = 0;
  std::vector<double> load_ratio, jff, ren, ren_expected;
  for (const auto& p : r.rcurve) {
    // The criterion: growth when the window-averaged tip J reaches J_tip; the average, reported
    // here, overshoots by the J rise within one check interval (5 % would mean the window or
    // the check interval is broken).
    EXPECT_GE(p.J_tip, J * (1 - 1e-12));
    EXPECT_LT(p.J_tip, 1.05 * J);
    EXPECT_GT(p.a, previous_a);
    previous_a = p.a;
    EXPECT_TRUE(std::isfinite(p.load) && std::isfinite(p.J_ff) && std::isfinite(p.R_energy));
    // LEFM: Eq. 2 at a zero-length zone is J_tip, the zone is empty.
    EXPECT_DOUBLE_EQ(p.R_eq2, J);
    EXPECT_DOUBLE_EQ(p.zone_length, 0);
    // Load and J_ff are measured on the state that triggered the advance, i.e. at the crack
    // length before it (p.a is the new tip).
    const double a_before = p.a - da;
    load_ratio.push_back(
        p.load / specimen::cbt_load_at_crack_length(run.specimen, run.material, J, a_before));
    jff.push_back(p.J_ff / J);
    ren.push_back(p.R_energy / J);
    ren_expected.push_back(step_release_fraction(run.specimen, run.material, a_before, da));
  }
  EXPECT_TRUE(r.reached_steady_state);
  // Displacement control: the load falls as the crack grows (P ~ 1/(a + chi h)).
  EXPECT_LT(r.rcurve.back().load, 0.8 * r.rcurve.front().load);

  // Targets. Each sample rings with the arm (the advance before it released its energy at
  // once), so each mean gets three standard errors of its samples on top of the stated
  // discretization tolerance.
  // (1) Far-field J at growth = J_tip (path independence, seed Eq. 1 with no zone): 2 %, the
  //     stationary tip/far-field agreement at 4 cells per arm.
  EXPECT_NEAR(mean(jff), 1.0, 0.02 + 3 * standard_error(jff));
  // (2) Released energy per area = the quasi-static release of one-cell steps at J_tip (exact
  //     energy balance; 2 % for the tip J's path independence).
  const double f = mean(ren_expected);
  EXPECT_NEAR(mean(ren) / f, 1.0, 0.02 + 3 * standard_error(ren) / f);
  // (3) Load = CBT at J_tip. The stationary test measures the load 3.4 % above CBT at equal
  //     opening (the crack acts 0.3 cell shorter), which raises the load at equal J by about
  //     1 %; the J_ff tolerance of (1) allows 1 % less: 3 % in all.
  EXPECT_NEAR(mean(load_ratio), 1.0, 0.03 + 3 * standard_error(load_ratio));
  std::printf("lefm: load/CBT %.3f +- %.3f, J_ff/J_tip %.3f +- %.3f, R_energy/J_tip %.3f +- %.3f "
              "(one-cell step releases %.3f)\n",
              mean(load_ratio), standard_error(load_ratio), mean(jff), standard_error(jff),
              mean(ren), standard_error(ren), f);

  // Energy balance: W = U + K + U_zone + D at every advance, D = PIC damping loss + numerical
  // loss of the explicit update (ExplicitSolver::numerical_loss, computed from the grid and
  // particle velocity increments and the strain increments, not from the energies). Without
  // that term 42 % of the released energy was missing: it leaves within 50 steps of each
  // advance (measured), where the cut's unbalanced stress acts on light node fields. With it the
  // residual is the explicit scheme's higher-order remainder: measured 2.3e-4 of the work.
  const double B = run.specimen.width;
  double residual = 0, numerical = 0;
  for (const auto& p : r.rcurve) {
    residual =
        p.external_work - p.strain_energy - p.kinetic_energy - p.zone_recoverable - p.dissipated;
    EXPECT_LT(std::fabs(residual), 0.005 * p.external_work) << "a = " << p.a;
  }
  numerical = r.rcurve.back().dissipated; // LEFM: no zone; damping + numerical loss
  std::printf("lefm: energy residual %.2e of W; tip losses (damping + numerical) %.3f of J_tip B "
              "(a - a0)\n",
              residual / r.rcurve.back().external_work,
              numerical / (J * B * (r.rcurve.back().a - run.specimen.initial_crack)));
}

TEST(MpmDcbPropagation, LinearSofteningZoneDevelopsAndReachesSteadyState) {
  const auto& run = linear_run();
  const auto& r = run.result;
  ASSERT_GT(r.rcurve.size(), 15u);
  const double sc = 1e6, dc = 0.2e-3, G_ss = 200 + 0.5 * sc * dc;
  bool root_moved = false;
  for (const auto& p : r.rcurve) {
    // The root stays at the notch until delta_root reaches delta_c, then follows the tip.
    if (p.root > run.specimen.initial_crack + 1e-9)
      root_moved = true;
    else
      EXPECT_LT(p.delta_root, dc);
    EXPECT_GE(p.zone_length, 0);
    // Eq. 2 of the law at the measured delta_root (the paper's convention) is exact by
    // construction: the rigid law is inserted extrinsically, no elastic rise (round-off only).
    EXPECT_NEAR(p.R_eq2, std::min(G_ss, 200 + 0.5 * sc * std::min(p.delta_root, dc)), 1e-9 * G_ss);
  }
  EXPECT_TRUE(root_moved);
  // Issue 34: at these 2.5 mm cells the zone reads fewer than the 3 cells the zone rule asks for
  // once the MPM's 2-cell root reading is taken off (result::note_zone_resolution), so the run
  // claims no steady state (status zone_unresolved) although R_J has its plateau; G_ss is that
  // plateau's mean.
  EXPECT_FALSE(r.reached_steady_state);
  EXPECT_EQ(r.steady_state_status, result::SteadyStateStatus::zone_unresolved);
  for (const auto& n : r.notes)
    if (n.rfind("resolution:", 0) == 0 || n.rfind("no steady state", 0) == 0)
      std::printf("linear: note: %s\n", n.c_str());
  std::printf("linear: G_ss %.1f (law %.1f), rdelta error %.3f\n", r.G_ss, G_ss,
              r.rdelta_rel_error_vs_eq2);
  // Energy balance with a zone: the residual W - U - K - U_zone - D is the law's work that the
  // tractions never paid: a segment born at an advance starts at half the tip particle's
  // opening (the partly split tip cell, see the notes), and its law energy counts from zero.
  // Measured -0.9 % of the work (-0.0075 J, 3.7 J/m^2 per unit growth); 1.5 % bounds it, and a
  // positive residual (energy lost outside the ledger) is held to the LEFM level.
  double worst = 0;
  for (const auto& p : r.rcurve) {
    const double residual =
        p.external_work - p.strain_energy - p.kinetic_energy - p.zone_recoverable - p.dissipated;
    EXPECT_GT(residual, -0.015 * p.external_work) << "a = " << p.a;
    EXPECT_LT(residual, 0.005 * p.external_work) << "a = " << p.a;
    worst = std::min(worst, residual / p.external_work);
  }
  std::printf("linear: most negative energy residual %.2e of the work\n", worst);
  // The zone dissipates: at the end the dissipation exceeds J_c over the failed length.
  const auto& last = r.rcurve.back();
  EXPECT_GT(last.dissipated,
            0.5 * sc * dc * run.specimen.width * (last.root - run.specimen.initial_crack));

  // Targets (seed Eq. 1 and 2): R_J plateaus at J_tip + J_c of the law the crack carries (the
  // rigid law as given: extrinsic insertion) and follows Eq. 2 while the zone develops.
  // Measured: G_ss 293.1 against 300 (-2.3 %; with the former elastic rise to 0.005 delta_c,
  // 292.6 against its 299.5), R_J against Eq. 2 2.8 % (relative L2). What the 2.3 % is, measured at
  // the advances (time averages over the steady part): J_ff reads 1.6 % below tip J + zone work
  // (the path independence of the two domain integrals, 1.6 % also on the stationary crack), and
  // the zone's tractions work 1 % of G_ss below the law's envelope (segments that unload a little
  // while the arm rings follow the unloading line). The 5 % bounds leave room for that level
  // (3 %) and the scatter of the advances with the arm's ringing (+-1 %); the earlier rule
  // (J window fixed at the a0 arm period) measured -6.0 % and 5.2 % and fails them.
  const double G_law = 200 + 0.5 * sc * dc;
  EXPECT_NEAR(r.G_ss / G_law, 1.0, 0.05);
  EXPECT_LT(r.rdelta_rel_error_vs_eq2, 0.05);
}
