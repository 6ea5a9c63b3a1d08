// Unit tests of the MPM building blocks: shape functions, elasticity, crack bookkeeping.
#include "fiberbridge/core/error.h"
#include "fiberbridge/law/piecewise_linear_law.h"
#include "fiberbridge/mpm/crack.h"
#include "fiberbridge/mpm/orthotropic_elastic.h"
#include "fiberbridge/mpm/shape_function.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace fiberbridge;
using namespace fiberbridge::mpm;

TEST(MpmShape, UgimpIsPartitionOfUnityWithZeroGradientSum) {
  // Partition of unity and its derivative (sum of gradients = 0) hold to rounding for any particle
  // position and box size, which makes rigid motion exact and internal forces self-equilibrated.
  const double cell = 2.0, origin = -4.0;
  for (double lp : {0.25, 0.5, 1.0})
    for (double xp = -1.9; xp < 3.0; xp += 0.137) {
      const AxisWeights w = ugimp_weights(xp, origin, cell, lp);
      double s = 0, ds = 0, first_moment = 0;
      for (int k = 0; k < 3; ++k) {
        s += w.S[k];
        ds += w.dS[k];
        first_moment += w.S[k] * (origin + (w.first + k) * cell);
      }
      EXPECT_NEAR(s, 1.0, 1e-14);
      EXPECT_NEAR(ds, 0.0, 1e-14);
      // Linear completeness: sum S_i x_i = x_p (the box average of x is its centre).
      EXPECT_NEAR(first_moment, xp, 1e-12);
      for (int k = 0; k < 3; ++k)
        EXPECT_GE(w.S[k], 0.0);
    }
}

TEST(MpmShape, UgimpGradientMatchesFiniteDifference) {
  const double cell = 1.0, lp = 0.25, h = 1e-6;
  for (double xp = 0.3; xp < 2.7; xp += 0.0913) {
    const AxisWeights w = ugimp_weights(xp, 0.0, cell, lp);
    for (int k = 0; k < 3; ++k) {
      const double xn = w.first + k;
      auto weight_at = [&](double x) {
        const AxisWeights v = ugimp_weights(x, 0.0, cell, lp);
        for (int m = 0; m < 3; ++m)
          if (v.first + m == xn)
            return v.S[m];
        return 0.0;
      };
      // Central difference of a C1 piecewise quadratic: error O(h^2) ~ 1e-12, plus rounding
      // 1e-16/h ~ 1e-10.
      EXPECT_NEAR(w.dS[k], (weight_at(xp + h) - weight_at(xp - h)) / (2 * h), 1e-7);
    }
  }
}

TEST(MpmElastic, PlaneStressAndStrainOrthotropicCompliance) {
  specimen::Material m;
  OrthotropicElastic e(m);
  // Uniaxial stress along L: strain (1/E_L, -nu_LT/E_L) must give stress (1, 0).
  const double eps[3] = {1 / m.E_L, -m.nu_LT / m.E_L, 0};
  double s[3];
  e.stress(eps, s);
  EXPECT_NEAR(s[0], 1.0, 1e-12);
  EXPECT_NEAR(s[1], 0.0, 1e-12);
  const double eps_t[3] = {-m.nu_TL() / m.E_T, 1 / m.E_T, 0};
  e.stress(eps_t, s);
  EXPECT_NEAR(s[0], 0.0, 1e-12);
  EXPECT_NEAR(s[1], 1.0, 1e-12);
  const double gam[3] = {0, 0, 0.5 / m.G_LT};
  e.stress(gam, s);
  EXPECT_NEAR(s[2], 1.0, 1e-12);
  // Plane strain: the reduced compliance (specimen::in_plane_compliance, the FEM's) inverted.
  m.plane_stress = false;
  const specimen::InPlaneCompliance c = specimen::in_plane_compliance(m);
  EXPECT_LT(c.s11, 1 / m.E_L); // eps_zz = 0 stiffens
  OrthotropicElastic strain(m);
  const double eps_pe[3] = {c.s11, c.s12, 0};
  strain.stress(eps_pe, s);
  EXPECT_NEAR(s[0], 1.0, 1e-12);
  EXPECT_NEAR(s[1], 0.0, 1e-12);
  m.nu_LR = -0.1;
  EXPECT_THROW(OrthotropicElastic{m}, InputError);
}

TEST(MpmCrack, FieldsSplitAtNodesOnTheCrackUpToTheTipColumn) {
  const auto law = law::make_bilinear(0.1e-3, 600e3, 2e-3);
  Crack crack(-1.0, 10.0, 0.5, law);
  EXPECT_DOUBLE_EQ(crack.tip(), 10.0);
  EXPECT_TRUE(crack.splits(above, 5.0, below));   // node behind the tip, other side
  EXPECT_TRUE(crack.splits(below, 10.0, above));  // the tip's own column is split
  EXPECT_FALSE(crack.splits(above, 10.5, below)); // ahead of the tip: one continuum field
  EXPECT_FALSE(crack.splits(above, 5.0, above));  // same side
  EXPECT_FALSE(crack.splits(above, -1.5, below)); // behind the crack's start (outside the body)
  EXPECT_EQ(crack.root_segment(), -1);            // the notch carries no traction
  crack.advance(10.5, 0.0, 0.0);
  EXPECT_TRUE(crack.splits(above, 10.5, below));
  ASSERT_EQ(crack.root_segment(), static_cast<int>(crack.segments().size()) - 1);
  EXPECT_TRUE(crack.segments().back().bridged);
  EXPECT_EQ(crack.segments().back().delta_max, 0.0);
}

TEST(MpmCrack, SplitColumnsCanLagTheTip) {
  // The DCB model splits the fields up to one cell behind the tip (see Crack::splits).
  const auto law = law::make_bilinear(0.1e-3, 600e3, 2e-3);
  Crack crack(-1.0, 10.0, 0.5, law, 1.0);
  EXPECT_TRUE(crack.splits(above, 9.0, below));
  EXPECT_FALSE(crack.splits(above, 10.0, below));
  crack.advance(10.5, 0.0, 0.0);
  crack.advance(11.0, 0.0, 0.0);
  EXPECT_TRUE(crack.splits(below, 10.0, above));
  EXPECT_FALSE(crack.splits(below, 11.0, above));
}
