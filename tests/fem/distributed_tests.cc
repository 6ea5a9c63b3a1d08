// Verification of the distributed DCB engine (issue 6). Run twice by ctest: on one process
// (FemDistributed.*: the low-rank update against CG + AMG, corrected beam theory) and under
// `mpirun -np 2` (FemMpi.*: the same model on MPI_COMM_WORLD = 2 ranks against MPI_COMM_SELF =
// 1 rank, in one program). Coarse meshes on a short specimen: the whole set takes seconds.
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/units.h"
#include "fiberbridge/fem/dcb_simulation.h"
#include "fiberbridge/fem/distributed_dcb.h"
#include "fiberbridge/law/exponential_law.h"
#include "fiberbridge/law/piecewise_linear_law.h"
#include "test_cases.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <iostream>

using namespace fiberbridge;
using units::kPa;
using units::mm;

using fem_test::pva_control;
using fem_test::short_dcb;

namespace {

/// A trilinear law short enough for the short DCB to reach steady state (the PVA zone, ~120 mm
/// on the seed specimen, is longer than its ligament): G_ss = 200 + 337.5 J/m^2.
law::PiecewiseLinearLaw short_trilinear() {
  law::TrilinearParameters t;
  t.d1 = 0.05 * mm;
  t.s1 = 800 * kPa;
  t.d2 = 0.3 * mm;
  t.s2 = 300 * kPa;
  t.dc = 1.5 * mm;
  return law::make_trilinear(t);
}

unsigned world_size() {
  return dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
}

/// Largest relative difference of R_J, load, load-point opening and root between two runs
/// (the crack positions must agree exactly: both advance element by element).
double max_rel_diff(const result::SimulationResult& a, const result::SimulationResult& b) {
  EXPECT_EQ(a.rcurve.size(), b.rcurve.size());
  double m = 0;
  auto rel = [](double x, double y) { return std::abs(x - y) / std::max(std::abs(x), 1e-300); };
  for (std::size_t i = 0; i < std::min(a.rcurve.size(), b.rcurve.size()); ++i) {
    const auto &p = a.rcurve[i], &q = b.rcurve[i];
    EXPECT_EQ(p.a, q.a) << "row " << i;
    m = std::max({m, rel(p.R_J, q.R_J), rel(p.load, q.load),
                  rel(p.load_point_opening, q.load_point_opening), rel(p.J_ff, q.J_ff)});
    if (p.root > 0)
      m = std::max(m, rel(p.root, q.root));
  }
  return m;
}

void print(const char* what, const result::SimulationResult& r) {
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
    return;
  std::cout << "  " << what << ": " << r.rcurve.size() << " advances, G_ss " << r.G_ss << ", "
            << r.wall_time_s << " s\n  a_mm load_N opening_mm R_J\n";
  for (const auto& p : r.rcurve)
    std::cout << "  " << p.a / mm << " " << p.load << " " << p.load_point_opening / mm << " "
              << p.R_J << "\n";
}

fem::FemParameters distributed_parameters() {
  fem::FemParameters prm;
  prm.linear.solver = fem::FemParameters::Linear::Solver::mumps;
  prm.mesh.element_size = 2 * mm;
  prm.steady_state.window = 6 * mm;
  return prm;
}

} // namespace

// (1) The low-rank (Woodbury) update of the direct solvers against CG + AMG, which sets up its
// preconditioner again at every change of the Jacobian and takes no low-rank shortcut: the same
// residual and Newton test (1e-9 of the reaction), so the R curves differ by the Newton and CG
// tolerances (1e-9, 1e-10) only. 1e-6 leaves three orders of magnitude of margin; a stale or
// wrong Woodbury term (a missed branch change, a wrong condensed opening operator) changes the
// Newton path and, when it does not converge, the curve by per cents. (Replaces the comparison
// with the serial engine, removed in issue 14.)
TEST(FemDistributed, LowRankUpdateMatchesAmgRefactorization2D) {
  const auto spec = short_dcb();
  const specimen::Material wood;
  const auto law = short_trilinear();
  auto prm = distributed_parameters();
  prm.linear.solver = fem::FemParameters::Linear::Solver::klu;
  const auto d = fem::simulate_dcb(spec, wood, law, 200, prm, "", {}, MPI_COMM_SELF);
  prm.linear.solver = fem::FemParameters::Linear::Solver::cg_amg;
  const auto s = fem::simulate_dcb(spec, wood, law, 200, prm, "", {}, MPI_COMM_SELF);
  print("cg_amg", s);
  ASSERT_GE(s.rcurve.size(), 10u);
  EXPECT_TRUE(s.reached_steady_state);
  EXPECT_EQ(d.reached_steady_state, s.reached_steady_state);
  const double diff = max_rel_diff(s, d);
  std::cout << "  max relative difference klu + Woodbury vs cg_amg: " << diff << "\n";
  EXPECT_LT(diff, 1e-6);
  EXPECT_NEAR(d.G_ss, s.G_ss, 1e-6 * s.G_ss);
  for (std::size_t i = 1; i < std::min(s.rcurve.size(), d.rcurve.size()); ++i)
    EXPECT_NEAR(d.rcurve[i].R_energy, s.rcurve[i].R_energy, 1e-6 * s.rcurve[i].R_J);
}

// (3) 3D LEFM: the load during propagation against corrected beam theory. CBT (a plane-stress
// beam theory with the Williams root-rotation correction) is good to about 2 % against 2D
// orthotropic elasticity (fem_tests use 1.5 % on the plane-stress FEM); the 3D specimen with
// free sides is slightly stiffer than plane stress (the Poisson coupling across the width,
// printed below as the 3D/2D load ratio: measured +0.25 %). Measured P_3D/P_CBT - 1 = 0.54 to
// 0.60 %. 1.5 %, as in the 2D test, fails for a wrong width integration, load line or tip J
// (P ~ sqrt(J): a 10 % error in J is 5 % in P).
TEST(FemDistributed, Lefm3dFollowsCorrectedBeamTheory) {
  const auto spec = short_dcb();
  const specimen::Material wood;
  const double j_tip = 200;
  auto prm = distributed_parameters();
  prm.mesh.dimension = 3;
  prm.mesh.width_elements = 4;
  fem::DistributedRunInfo info;
  const auto r =
      fem::simulate_dcb(spec, wood, law::NoBridgingLaw(), j_tip, prm, "", {}, MPI_COMM_SELF, &info);
  print("3D LEFM", r);
  prm.mesh.dimension = 2;
  const auto r2 =
      fem::simulate_dcb(spec, wood, law::NoBridgingLaw(), j_tip, prm, "", {}, MPI_COMM_SELF);
  EXPECT_EQ(info.dimension, 3u);
  ASSERT_GE(r.rcurve.size(), 4u);
  ASSERT_EQ(r.rcurve.size(), r2.rcurve.size());
  EXPECT_TRUE(r.reached_steady_state);
  for (std::size_t i = 0; i < r.rcurve.size(); ++i) {
    const auto& p = r.rcurve[i];
    const double cbt = specimen::cbt_load_at_crack_length(spec, wood, j_tip, p.a);
    std::cout << "  a = " << p.a / mm << " mm: P_3D / P_CBT = " << p.load / cbt
              << ", P_3D / P_2D,plane stress = " << p.load / r2.rcurve[i].load << "\n";
    EXPECT_NEAR(p.load / cbt, 1.0, 0.015) << "a = " << p.a / mm << " mm";
    // The width-averaged tip J is the criterion; the far-field J (another domain) must agree:
    // path independence in 3D, 0.5 % as in the 2D test.
    EXPECT_NEAR(p.J_tip / j_tip, 1.0, prm.nonlinear.tip_tolerance);
    EXPECT_NEAR(p.R_J / j_tip, 1.0, 0.005);
  }
  EXPECT_NEAR(r.G_ss / j_tip, 1.0, 0.005);
}

// (4) A thin 3D specimen (width 1 mm, one element layer, 2 mm elements in x and y) against the
// 2D plane-stress model on the same in-plane mesh, with the short trilinear law.
// (a) Without Poisson coupling to the width direction (nu_LR = nu_RT = 0) the 3D solution has
// u_z = 0 and u_x, u_y independent of z: it IS the plane-stress solution, so the R curves agree
// to the Newton tolerance (1e-9) and round-off; 1e-7 checks the 3D assembly, the width
// integration of the interface and of J, and the load per width exactly.
// (b) With the Poisson coupling, the trilinear layer can make sigma_zz vanish only in the
// finite-element sense (its u_z is bilinear in x, y), a discretization difference of order h^2
// that does not vanish with the width: measured 1.2e-3 at B = 1 mm and at 0.5 mm. 2e-3 bounds
// it; plane strain differs by ~5e-3 on the load, a width mis-scaling by a factor.
TEST(FemDistributed, Thin3dReproducesPlaneStress) {
  const auto law = short_trilinear();
  auto spec = short_dcb();
  spec.width = 1 * mm; // the 2D load is per width times this width
  for (const bool coupled : {false, true}) {
    auto prm = distributed_parameters();
    specimen::Material wood;
    if (!coupled) {
      wood.nu_LR = 0;
      wood.nu_RT = 0;
    }
    const auto r2 = fem::simulate_dcb(spec, wood, law, 200, prm, "", {}, MPI_COMM_SELF);
    ASSERT_GE(r2.rcurve.size(), 10u);
    EXPECT_TRUE(r2.reached_steady_state);
    prm.mesh.dimension = 3;
    prm.mesh.width_elements = 1;
    const auto r3 = fem::simulate_dcb(spec, wood, law, 200, prm, "", {}, MPI_COMM_SELF);
    const double diff = max_rel_diff(r2, r3);
    std::cout << "  " << (coupled ? "with" : "without")
              << " Poisson coupling to z: max relative difference 3D thin vs 2D plane stress "
              << diff << ", G_ss 3D " << r3.G_ss << " vs 2D " << r2.G_ss << "\n";
    EXPECT_EQ(r3.reached_steady_state, r2.reached_steady_state);
    EXPECT_LT(diff, coupled ? 2e-3 : 1e-7);
    EXPECT_NEAR(r3.G_ss, r2.G_ss, (coupled ? 2e-3 : 1e-7) * r2.G_ss);
  }
}

// FEM/Steady-state window is the old name of FEM/Steady state window, the key of the steady-state
// rule shared by every model section (issue 14): still accepted, mapped, and said so in the
// run's notes; a value that is not a length is an error naming the old key.
TEST(FemDistributed, OldSteadyStateWindowKeyIsMappedWithANote) {
  dealii::ParameterHandler handler;
  fem::FemParameters::declare_parameters(handler);
  handler.parse_input_from_string("set Steady-state window = 6\n");
  fem::FemParameters p;
  p.parse_parameters(handler);
  EXPECT_DOUBLE_EQ(p.steady_state.window, 6 * mm);
  ASSERT_EQ(p.deprecation_notes.size(), 1u);
  EXPECT_NE(p.deprecation_notes[0].find("FEM/Steady-state window is deprecated"),
            std::string::npos);
  dealii::ParameterHandler bad;
  fem::FemParameters::declare_parameters(bad);
  bad.parse_input_from_string("set Steady-state window = six mm\n");
  try {
    p.parse_parameters(bad);
    ADD_FAILURE() << "a window that is not a number was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("FEM/Steady-state window"), std::string::npos);
  }
}

// The new name alone carries no note; both names with different values is an error naming both
// (it is not clear which one the scene meant); the same value under both is accepted, with the
// note (the rule of every renamed key, core/renamed_key.h).
TEST(FemDistributed, SteadyStateWindowNewOldAndBothNames) {
  auto parse = [](const std::string& sets) {
    dealii::ParameterHandler handler;
    fem::FemParameters::declare_parameters(handler);
    handler.parse_input_from_string(sets);
    fem::FemParameters p;
    p.parse_parameters(handler);
    return p;
  };
  const auto p = parse("set Steady state window = 6\n");
  EXPECT_DOUBLE_EQ(p.steady_state.window, 6 * mm);
  EXPECT_TRUE(p.deprecation_notes.empty());
  const auto same = parse("set Steady state window = 6\nset Steady-state window = 6\n");
  EXPECT_DOUBLE_EQ(same.steady_state.window, 6 * mm);
  EXPECT_EQ(same.deprecation_notes.size(), 1u);
  try {
    parse("set Steady state window = 6\nset Steady-state window = 8\n");
    ADD_FAILURE() << "two different windows were accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("FEM/Steady state window = 6"), std::string::npos) << what;
    EXPECT_NE(what.find("FEM/Steady-state window = 8"), std::string::npos) << what;
  }
}

// FEM/Engine and Linear solver = umfpack are deprecated (one engine, issue 14): still accepted
// by scenes and said so in the run's notes (docs/cluster.md: what Engine = distributed still
// does in a scene of several simulations).
TEST(FemDistributed, DeprecatedEngineKeysAreNoted) {
  dealii::ParameterHandler handler;
  fem::FemParameters::declare_parameters(handler);
  handler.parse_input_from_string("set Engine = serial\nset Linear solver = umfpack\n");
  fem::FemParameters p;
  p.parse_parameters(handler);
  EXPECT_EQ(p.linear.solver, fem::FemParameters::Linear::Solver::klu);
  ASSERT_EQ(p.deprecation_notes.size(), 2u);
  const auto r = fem::simulate_dcb(short_dcb(), specimen::Material(), short_trilinear(), 200, p);
  unsigned noted = 0;
  for (const auto& n : r.notes)
    noted += n.find("FEM/Engine = serial is deprecated") != std::string::npos ||
             n.find("umfpack is deprecated") != std::string::npos;
  EXPECT_EQ(noted, 2u);
  EXPECT_TRUE(r.reached_steady_state);
}

// (2) 1 rank vs 2 ranks: the same model on MPI_COMM_SELF (every rank alone) and on
// MPI_COMM_WORLD (the mesh split in two; ties, cohesive segments and J domains cross the
// partition). Same discrete problem, so the only difference is the order of floating-point sums
// (assembly across ranks, MUMPS' distributed factorization): measured ~1e-10; the issue asks
// for 1e-6. Skipped on one process unless FIBERBRIDGE_REQUIRE_RANKS says how many are expected
// (the ctest entry sets it, so a launcher that starts one process fails instead of skipping).
class FemMpi : public ::testing::Test {
protected:
  void SetUp() override {
    const char* req = std::getenv("FIBERBRIDGE_REQUIRE_RANKS");
    if (req) {
      ASSERT_EQ(world_size(), unsigned(std::atoi(req))) << "started on the wrong number of ranks";
    }
    if (world_size() < 2)
      GTEST_SKIP() << "needs mpirun -np 2";
  }
};

TEST_F(FemMpi, TwoRanksGiveTheOneRankRCurve2D) {
  const auto spec = short_dcb();
  const auto law = short_trilinear();
  const auto prm = distributed_parameters();
  fem::DistributedRunInfo i1, i2;
  const auto r1 =
      fem::simulate_dcb(spec, specimen::Material(), law, 200, prm, "", {}, MPI_COMM_SELF, &i1);
  const auto r2 =
      fem::simulate_dcb(spec, specimen::Material(), law, 200, prm, "", {}, MPI_COMM_WORLD, &i2);
  EXPECT_EQ(i1.n_ranks, 1u);
  EXPECT_EQ(i2.n_ranks, world_size());
  print("2 ranks", r2);
  ASSERT_GE(r1.rcurve.size(), 10u);
  const double diff = max_rel_diff(r1, r2);
  std::cout << "  2D max relative difference 1 vs " << world_size() << " ranks: " << diff
            << " (wall time " << r1.wall_time_s << " s vs " << r2.wall_time_s << " s)\n";
  EXPECT_LT(diff, 1e-6);
  EXPECT_NEAR(r2.G_ss, r1.G_ss, 1e-6 * r1.G_ss);
}

// KINSOL on Trilinos MPI vectors, 2 ranks, against the own Newton on 2 ranks: both stop at the
// same residual test (1e-9 of the reaction) from the same predictor, so the converged states
// differ by at most that: 1e-7 as in the one-rank KINSOL test.
TEST_F(FemMpi, KinsolOnTwoRanksAgreesWithNewton) {
  const auto spec = short_dcb();
  const auto law = short_trilinear();
  auto prm = distributed_parameters();
  const auto n =
      fem::simulate_dcb(spec, specimen::Material(), law, 200, prm, "", {}, MPI_COMM_WORLD);
  prm.nonlinear.solver = fem::FemParameters::Nonlinear::Solver::kinsol;
  const auto k =
      fem::simulate_dcb(spec, specimen::Material(), law, 200, prm, "", {}, MPI_COMM_WORLD);
  ASSERT_GE(n.rcurve.size(), 10u);
  const double diff = max_rel_diff(n, k);
  std::cout << "  KINSOL vs Newton on " << world_size() << " ranks: max relative difference "
            << diff << "\n";
  EXPECT_LT(diff, 1e-7);
  EXPECT_NEAR(k.G_ss, n.G_ss, 1e-7 * n.G_ss);
  bool says_kinsol = false;
  for (const auto& m : k.method)
    says_kinsol = says_kinsol || m.find("KINSOL") != std::string::npos;
  EXPECT_TRUE(says_kinsol);
}

TEST_F(FemMpi, TwoRanksGiveTheOneRankRCurve3D) {
  const auto spec = short_dcb();
  const auto law = pva_control();
  auto prm = distributed_parameters();
  prm.mesh.dimension = 3;
  prm.mesh.width_elements = 2;
  prm.mesh.element_size = 4 * mm;
  // Q1: this test compares ranks, not bending accuracy (auto would take Q2 for 4 mm elements on
  // the 10 mm arms, indicator 0.012, and a 3D Q2 run on 2 oversubscribed ranks takes minutes).
  prm.mesh.degree = 1;
  prm.steady_state.window = 8 * mm;
  const auto r1 =
      fem::simulate_dcb(spec, specimen::Material(), law, 200, prm, "", {}, MPI_COMM_SELF);
  const auto r2 =
      fem::simulate_dcb(spec, specimen::Material(), law, 200, prm, "", {}, MPI_COMM_WORLD);
  print("3D, 2 ranks", r2);
  ASSERT_GE(r1.rcurve.size(), 5u);
  const double diff = max_rel_diff(r1, r2);
  std::cout << "  3D max relative difference 1 vs " << world_size() << " ranks: " << diff << "\n";
  EXPECT_LT(diff, 1e-6);
}
