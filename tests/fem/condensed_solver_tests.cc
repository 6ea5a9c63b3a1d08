// FEM/Linear solver = condensed (issue 34 item 3; docs/design.md section 2, "Condensed arms
// (issue 34 item 3)"): the arms condensed onto the crack plane solve the same Jacobian systems as
// klu, so the whole algorithm (Newton, the secant on tip J, releases, the crack-tip opening
// control) must give the same R curves to what the Newton tolerance allows, on the seed PVA law,
// linear softening, thin (Q2) arms and a snap-back law that switches to the crack-tip control.
//
// Tolerance: both runs stop Newton at |r| <= 1e-9 of the load-line reaction (FEM/Newton
// tolerance) from iterates that differ only by the linear solves' round-off (the condensed solves
// are refined to 1e-11 relative residual or better, condensed_solver.cc). Two states that pass
// the same residual test differ by about that tolerance, 1e-9 relative; R_J is quadratic in the
// fields (2e-9). 1e-7 leaves a factor 50 for the secant on tip J, which takes its iterates from
// these states; any different decision (a tangent branch, a release, the control switch) or a
// wrong Jacobian term that Newton still overcomes shows as a different number of advances, a
// different Newton count or a difference of 1e-5 and more (the tip tolerance is 1e-3).
#include "common/notes.h"
#include "common/thin_dcb_case.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/units.h"
#include "fiberbridge/fem/dcb_simulation.h"
#include "fiberbridge/law/exponential_law.h"
#include "fiberbridge/law/piecewise_linear_law.h"
#include "test_cases.h"

#include <deal.II/base/parameter_handler.h>

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <iostream>
#include <regex>
#include <string>

using namespace fiberbridge;
using units::kPa;
using units::mm;
using LS = fem::FemParameters::Linear::Solver;

namespace {

constexpr double kRoundoff = 1e-7; // see the file comment

struct Timed {
  result::SimulationResult result;
  double seconds = 0;
};

Timed run(const specimen::Specimen& spec, const specimen::Material& mat,
          const law::TractionLaw& law, double j_tip, fem::FemParameters prm, LS solver) {
  prm.linear.solver = solver;
  const auto start = std::chrono::steady_clock::now();
  Timed t;
  t.result = fem::simulate_dcb(spec, mat, law, j_tip, prm);
  t.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return t;
}

bool mentions(const result::SimulationResult& r, const std::string& what) {
  for (const auto& m : r.method)
    if (m.find(what) != std::string::npos)
      return true;
  return false;
}

/// "N Newton iterations" of the run's time line.
int newton_iterations(const result::SimulationResult& r) {
  const std::regex re("([0-9]+) Newton iterations");
  for (const auto& m : r.method) {
    std::smatch match;
    if (std::regex_search(m, match, re))
      return std::stoi(match[1]);
  }
  return -1;
}

/// The condensed run against the full (klu) run of the same case.
void expect_same_rcurve(const Timed& full, const Timed& condensed, const std::string& what,
                        int crack_plane_stops = 0) {
  const auto& k = full.result;
  const auto& c = condensed.result;
  EXPECT_TRUE(mentions(k, "Trilinos Amesos KLU")) << what;
  EXPECT_TRUE(mentions(c, "arms condensed onto the crack plane")) << what;
  ASSERT_EQ(c.rcurve.size(), k.rcurve.size()) << what;
  ASSERT_GE(k.rcurve.size(), 3u) << what;
  EXPECT_EQ(c.reached_steady_state, k.reached_steady_state) << what;
  double largest = 0;
  // Relative to `scale` (the quantity itself, or for a balance of energies, the work).
  auto near = [&](double x, double ref, const char* name, std::size_t i, double scale = 0) {
    scale = std::max(scale, std::abs(ref));
    EXPECT_NEAR(x, ref, kRoundoff * scale) << what << ": " << name << " at advance " << i;
    largest = std::max(largest, std::abs(x - ref) / scale);
  };
  for (std::size_t i = 0; i < k.rcurve.size(); ++i) {
    const auto &p = c.rcurve[i], &q = k.rcurve[i];
    EXPECT_EQ(p.a, q.a) << what << " at advance " << i;
    near(p.R_J, q.R_J, "R_J", i);
    near(p.load, q.load, "load", i);
    near(p.load_point_opening, q.load_point_opening, "load-point opening", i);
    near(p.J_tip, q.J_tip, "J_tip", i);
    near(p.dissipated, q.dissipated, "dissipated energy", i, std::abs(q.external_work));
  }
  if (k.reached_steady_state)
    near(c.G_ss, k.G_ss, "G_ss", 0);
  // The crack-plane Newton (condensed_solver.h) converged wherever the full Newton did: where it
  // stops short the full Newton goes on from its state (one more iteration, the same verdict);
  // a stop where the full Newton converges would mean its residual or test drifted from the
  // full one.
  EXPECT_TRUE(mentions(c, "; " + std::to_string(crack_plane_stops) +
                              " crack-plane Newton runs stopped short"))
      << what;
  // The same Newton path: every iteration solves the same system.
  const int nk = newton_iterations(k), nc = newton_iterations(c);
  EXPECT_GT(nk, 0);
  EXPECT_NEAR(nc, nk, std::max(2.0, 0.01 * nk)) << what << ": Newton iterations";
  std::cout << "  " << what << ": " << k.rcurve.size() << " advances, largest relative difference "
            << largest << ", Newton " << nk << " (klu) / " << nc << " (condensed), run time "
            << full.seconds << " s (klu) / " << condensed.seconds << " s (condensed)\n";
  for (const auto& m : c.method)
    if (m.find("condensed") != std::string::npos || m.rfind("time ", 0) == 0)
      std::cout << "    " << m << "\n";
}

} // namespace

// The seed PVA control law on the seed specimen at 2 mm (prm/fem_pva_control.prm): the lead's
// benchmark case (bench/fem_condensed.sh), 69 advances to steady state.
TEST(FemCondensed, SeedPvaMatchesKlu) {
  fem::FemParameters prm;
  prm.mesh.element_size = 2 * mm;
  const auto law = fem_test::pva_control();
  const specimen::Specimen spec;
  const specimen::Material wood;
  const auto full = run(spec, wood, law, 200, prm, LS::klu);
  const auto cond = run(spec, wood, law, 200, prm, LS::condensed);
  ASSERT_TRUE(full.result.reached_steady_state);
  expect_same_rcurve(full, cond, "seed PVA");
}

// Linear softening with an elastic rise (the law of FemDcb.LinearSofteningFollowsEq2AndPlateaus)
// on the short DCB at 1 mm.
TEST(FemCondensed, LinearSofteningMatchesKlu) {
  fem::FemParameters prm;
  prm.mesh.element_size = 1 * mm;
  prm.steady_state.window = 8 * mm;
  const auto law = law::make_linear_softening(1000 * kPa, 0.4 * mm).with_elastic_rise(0.04 * mm);
  const auto spec = fem_test::short_dcb();
  const specimen::Material wood;
  const auto full = run(spec, wood, law, 200, prm, LS::klu);
  const auto cond = run(spec, wood, law, 200, prm, LS::condensed);
  expect_same_rcurve(full, cond, "linear softening");
}

// Thin arms: the published glass/epoxy DCB (2.7 mm arms) on the default mesh, where auto takes
// Q2 (three crack-plane nodes per segment: a release frees two node pairs), LEFM.
TEST(FemCondensed, ThinQuadraticArmsMatchKlu) {
  fem::FemParameters prm;
  prm.steady_state.window = 4 * mm;
  const auto spec = thin_dcb_case::specimen();
  const auto mat = thin_dcb_case::material();
  const auto full = run(spec, mat, law::NoBridgingLaw(), 500, prm, LS::klu);
  const auto cond = run(spec, mat, law::NoBridgingLaw(), 500, prm, LS::condensed);
  EXPECT_TRUE(test_notes::has_note(cond.result, "FEM/Polynomial degree = auto chose Q2"));
  expect_same_rcurve(full, cond, "thin composite arms, Q2");
}

// The snap-back law of FemThinArm.StrongerShorterLawIsTracedPastTheSnapBack (30 MPa, delta_c
// 0.02 mm) on the seed specimen at 2 mm: the load-point opening loses the state after a release
// and both runs switch to the crack-tip opening control (bordered Newton: two solves per
// iteration) at the same advance.
TEST(FemCondensed, SnapBackUnderTipControlMatchesKlu) {
  fem::FemParameters prm;
  prm.mesh.element_size = 2 * mm;
  const auto law = law::make_linear_softening(30000 * kPa, 0.02 * mm);
  const specimen::Specimen spec;
  const specimen::Material wood;
  const auto full = run(spec, wood, law, 100, prm, LS::klu);
  const auto cond = run(spec, wood, law, 100, prm, LS::condensed);
  ASSERT_TRUE(test_notes::has_note(full.result, "control: at a = "));
  EXPECT_TRUE(test_notes::has_note(cond.result, "control: at a = "));
  // The one re-equilibration at fixed opening that fails (the path turns back there) is the one
  // crack-plane Newton run that stops short; the full Newton then fails the same way.
  expect_same_rcurve(full, cond, "snap-back law under the crack-tip control", 1);
}

// Where the condensed arms do not apply (finite kinematics here; likewise 3D or several MPI
// ranks), an explicit request is an input error naming the key; auto takes klu there.
TEST(FemCondensed, RefusedWhereItCannotApply) {
  fem::FemParameters prm;
  prm.mesh.element_size = 2 * mm;
  prm.nonlinear.kinematics = fem::FemParameters::Nonlinear::Kinematics::finite;
  prm.linear.solver = LS::condensed;
  try {
    fem::simulate_dcb(fem_test::short_dcb(), specimen::Material(), law::NoBridgingLaw(), 200, prm);
    FAIL() << "no input error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("FEM/Linear solver = condensed"), std::string::npos)
        << e.what();
  }
}

// The key's values: auto and condensed are accepted next to the old ones.
TEST(FemCondensed, LinearSolverValues) {
  dealii::ParameterHandler handler;
  fem::FemParameters::declare_parameters(handler);
  fem::FemParameters p;
  for (const auto& [value, solver] :
       {std::make_pair("condensed", LS::condensed), std::make_pair("auto", LS::automatic),
        std::make_pair("klu", LS::klu), std::make_pair("cg_amg", LS::cg_amg)}) {
    handler.parse_input_from_string(std::string("set Linear solver = ") + value + "\n");
    p.parse_parameters(handler);
    EXPECT_EQ(p.linear.solver, solver) << value;
  }
}
