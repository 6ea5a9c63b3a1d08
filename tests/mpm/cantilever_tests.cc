// Elastic sanity of the explicit MPM core without a crack: a clamped cantilever's static tip
// deflection under a slowly applied tip load, and its first free-vibration period, against beam
// theory (Timoshenko deflection, Euler-Bernoulli period).
#include "fiberbridge/mpm/explicit_solver.h"
#include "fiberbridge/specimen/specimen.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

using namespace fiberbridge;
using namespace fiberbridge::mpm;

namespace {

// Isotropic material: the beam formulas then need no orthotropic shear corrections beyond
// Timoshenko's.
specimen::Material isotropic() {
  specimen::Material m;
  m.E_L = m.E_T = 10e9;
  m.nu_LT = 0.3;
  m.G_LT = m.E_L / (2 * (1 + m.nu_LT));
  m.density = 500;
  return m;
}

struct Cantilever {
  double L = 0.080, t = 0.010, B = 0.020, cell = 2.5e-3;
  specimen::Material m = isotropic();
  std::unique_ptr<ExplicitSolver> solver;
  std::vector<int> tip_particles;

  explicit Cantilever(double beta, const specimen::Material& material = isotropic(),
                      double cell_size = 2.5e-3)
      : cell(cell_size), m(material) {
    const int ppc = 2;
    Particles p = Particles::rectangle(0.0, 0.25 * cell, L, t, static_cast<int>(L / cell) * ppc,
                                       static_cast<int>(t / cell) * ppc, m.density, B);
    for (int iy = 0; iy < p.lattice_ny; ++iy)
      tip_particles.push_back(p.index(p.lattice_nx - 1, iy));
    const int nx = static_cast<int>(L / cell) + 6, ny = static_cast<int>(t / cell) + 8;
    Grid grid(-2 * cell, -3 * cell, cell, nx, ny);
    OrthotropicElastic e(m);
    const double dt = 0.5 * cell / e.max_wave_speed();
    solver = std::make_unique<ExplicitSolver>(std::move(grid), std::move(p), e, dt, beta, B);
    // Clamp: both velocity components of the node column at x = 0 (and the empty one behind it).
    VelocityConstraint cx, cy;
    cx.component = 0;
    cy.component = 1;
    const Grid& g = solver->grid();
    for (int i = 1; i <= 2; ++i)
      for (int j = 0; j < g.ny(); ++j) {
        cx.fields.emplace_back(g.node(i, j), g.side_of(j));
        cy.fields.emplace_back(g.node(i, j), g.side_of(j));
      }
    solver->constraints() = {cx, cy};
  }
  void set_tip_load(double P) {
    auto& f = solver->particle_forces();
    f.clear();
    for (int k : tip_particles)
      f.push_back({k, 0.0, P / tip_particles.size()});
  }
  double tip_deflection() const {
    const Particles& p = solver->particles();
    double s = 0;
    for (int k : tip_particles)
      s += p.y[k] - p.Y[k];
    return s / tip_particles.size();
  }
  double I() const { return B * t * t * t / 12; }
  /// Timoshenko tip deflection under P with the bending modulus 1/s11 of the 2D model (E_L in
  /// plane stress, larger in plane strain) and the shear modulus G_LT.
  double timoshenko(double P) const {
    const double E = 1 / specimen::in_plane_compliance(m).s11, kappa = 5.0 / 6;
    return P * std::pow(L, 3) / (3 * E * I()) + P * L / (kappa * m.G_LT * B * t);
  }
  /// Applies P over 3 periods (smooth ramp), holds 2 periods and returns the tip deflection
  /// averaged over the last one (the residual vibration averages out).
  double static_deflection(double P) {
    const double T = euler_period();
    ExplicitSolver& s = *solver;
    double sum = 0;
    long n = 0;
    while (s.time() < 5 * T) {
      const double r = std::min(1.0, s.time() / (3 * T));
      set_tip_load(P * 0.5 * (1 - std::cos(M_PI * r)));
      s.step();
      if (s.time() > 4 * T) {
        sum += tip_deflection();
        ++n;
      }
    }
    return sum / n;
  }
  double euler_period() const {
    return 1.787 * L * L * std::sqrt(m.density * B * t / (m.E_L * I()));
  }
};

} // namespace

TEST(MpmCantilever, StaticTipDeflectionMatchesTimoshenko) {
  Cantilever c(0.2);
  const double P = 200; // N: deflection ~ L/300, well inside small strain
  const ExplicitSolver& s = *c.solver;
  const double deflection = c.static_deflection(P);
  const double expected = c.timoshenko(P);
  // A 2D plane-stress model and the beam share E. 4 cells through the thickness with uGIMP:
  // measured 2.8 % stiffer than Timoshenko; 5 % bounds it and still catches a lost factor in the
  // shape-function gradients, the stress rotation or the particle volume (all >= 25 %).
  EXPECT_NEAR(deflection / expected, 1.0, 0.05) << "MPM " << deflection << " m, beam " << expected;
  // Energy: the work of the load equals strain + kinetic energy + damping loss (measured
  // 1.1e-3 of the work; 1 % would flag a missing term).
  const double balance =
      s.external_work() - s.strain_energy() - s.kinetic_energy() - s.damping_loss();
  EXPECT_LT(std::fabs(balance), 0.01 * s.external_work());
  std::printf("deflection ratio %.4f balance %.3g of W\n", deflection / expected,
              balance / s.external_work());
}

TEST(MpmCantilever, BendingNeedsCellsThroughTheThickness) {
  // The evidence for the MPM's thin-arm check (source/mpm/dcb.cc, setup_body): the static tip
  // deflection against Timoshenko with 2, 3 and 4 cells through the 10 mm thickness.
  double ratio[3];
  for (int n = 2; n <= 4; ++n) {
    Cantilever c(0.2, isotropic(), 10e-3 / n);
    ratio[n - 2] = c.static_deflection(200) / c.timoshenko(200);
    std::printf("%d cells through the thickness: deflection / Timoshenko %.4f\n", n, ratio[n - 2]);
  }
  // Measured 0.943, 0.963, 0.972: two cells bend over 5 % too stiff, three are within 4 %. The
  // DCB therefore refuses fewer than 2 cells through an arm and notes fewer than 3. Bounds: 5 %
  // for 3 and 4 cells (a lost factor in the gradients is >= 25 %), and 2 cells stiffer than 3.
  EXPECT_LT(ratio[0], 0.95);
  EXPECT_LT(ratio[0], ratio[1]);
  EXPECT_NEAR(ratio[1], 1.0, 0.05);
  EXPECT_NEAR(ratio[2], 1.0, 0.05);
}

TEST(MpmCantilever, FreeVibrationPeriodMatchesBeamTheory) {
  Cantilever c(0.2);
  const double P = 200;
  const double T = c.euler_period();
  ExplicitSolver& s = *c.solver;
  while (s.time() < 3 * T) {
    const double r = std::min(1.0, s.time() / (2 * T));
    c.set_tip_load(P * 0.5 * (1 - std::cos(M_PI * r)));
    s.step();
  }
  // Release and let it ring undamped (pure FLIP): time the upward zero crossings of the tip
  // deflection about its mean (zero without load).
  c.set_tip_load(0);
  s.set_pic_fraction(0);
  const double loss0 = s.damping_loss();
  std::vector<double> crossings;
  double previous = c.tip_deflection();
  const double t0 = s.time();
  while (s.time() < t0 + 3.2 * T) {
    s.step();
    const double d = c.tip_deflection();
    if (previous < 0 && d >= 0)
      crossings.push_back(s.time() - s.dt() * d / (d - previous));
    previous = d;
  }
  ASSERT_GE(crossings.size(), 3u);
  const double period = (crossings.back() - crossings.front()) / (crossings.size() - 1);
  // Shear and rotary inertia lengthen the Euler period by about 1.5 % at L/t = 8 (Timoshenko)
  // and the stiff discretization shortens it; measured +0.9 %. 4 % catches a wrong mass or
  // stiffness (a factor 2 in mass is +41 %).
  EXPECT_NEAR(period / T, 1.0, 0.04) << "MPM " << period << " s, Euler " << T;
  // beta = 0 removes nothing: the blend is then the FLIP velocity itself.
  EXPECT_NEAR(s.damping_loss(), loss0, 1e-12 * loss0);
  std::printf("period ratio %.4f\n", period / T);
}

// Plane strain: the same cantilever with the out-of-plane strain held at zero. For the isotropic
// material (E_R = E, nu_LR = nu_RT = nu) the bending modulus becomes E/(1 - nu^2), 9.9 % stiffer
// in bending; the shear term does not change. The ratio of the two MPM deflections against the
// ratio of the two Timoshenko deflections cancels the discretization's own stiffness (2.8 %):
// 0.5 % catches a reduction applied twice or not at all (9 %) and the wrong radial constants.
TEST(MpmCantilever, PlaneStrainStiffensBendingByTheReducedCompliance) {
  specimen::Material strain = isotropic();
  strain.plane_stress = false;
  strain.E_R_over_E_L = 1;
  strain.nu_LR = strain.nu_RT = strain.nu_LT;
  const double P = 200;
  Cantilever c_stress(0.2), c_strain(0.2, strain);
  const double ratio = c_strain.static_deflection(P) / c_stress.static_deflection(P);
  const double expected = c_strain.timoshenko(P) / c_stress.timoshenko(P);
  EXPECT_NEAR(ratio / expected, 1.0, 0.005) << "MPM " << ratio << ", beam theory " << expected;
  std::printf("plane strain / plane stress deflection %.4f (beam theory %.4f)\n", ratio, expected);
}
