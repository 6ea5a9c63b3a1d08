// Unit tests of the traction laws and of Eq. 2 (docs/design.md section 1).
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/units.h"
#include "fiberbridge/law/exponential_law.h"
#include "fiberbridge/law/law_spec.h"
#include "fiberbridge/law/piecewise_linear_law.h"
#include "fiberbridge/law/seed_laws.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace fiberbridge;
using namespace fiberbridge::law;
using units::kPa;
using units::mm;

namespace {
TrilinearParameters pva_control() {
  return {0.1 * mm, 661 * kPa, 1.0 * mm, 187 * kPa, 6.0 * mm};
}
} // namespace

TEST(Law, LinearSofteningForwardRIsExactlyLinear) {
  const auto law = make_linear_softening(500 * kPa, 3 * mm);
  for (double d = 0; d <= 3 * mm; d += 0.1 * mm)
    // Eq. 2 with sigma = s(1 - d/dc): J + s d - s d^2/(2dc) - d s (1 - d/dc)/2 = J + s d/2.
    EXPECT_NEAR(r_curve_eq2(law, 200, d), 200 + 0.5 * 500 * kPa * d, 1e-9);
  EXPECT_DOUBLE_EQ(r_curve_eq2(law, 200, 10 * mm), 200 + law.area());
  EXPECT_NEAR(law.area(), 0.5 * 500 * kPa * 3 * mm, 1e-9);
}

TEST(Law, TrilinearAreaSplitMatchesTable1) {
  const auto t = pva_control();
  // Table 1, PVA control: J1 = 321 J/m^2 printed; (661*1.0 - 187*0.1)/2 = 321.15.
  EXPECT_NEAR(t.j1(), 321.15, 1e-9);
  EXPECT_NEAR(t.j2(), 561.0, 1e-9);
  const auto law = make_trilinear(t);
  EXPECT_NEAR(law.area(), t.j1() + t.j2(), 1e-9); // Eq. 8
  EXPECT_NEAR(law.area(), 0.5 * (t.s1 * t.d2 + t.s2 * (t.dc - t.d1)), 1e-9);
  EXPECT_DOUBLE_EQ(law.peak().first, 661 * kPa);
  EXPECT_DOUBLE_EQ(law.peak().second, 0.1 * mm);
  EXPECT_FALSE(law.rigid_at_zero_opening());
  EXPECT_NEAR(law.initial_stiffness(), 661 * kPa / (0.1 * mm), 1e-3);
}

TEST(Law, EnvelopeRiseIsRecoverableSoRIsFlatBelowD1) {
  // For delta < d1 all work is elastic (unloads to the origin): R = J_tip exactly.
  const auto law = make_trilinear(pva_control());
  for (double d = 0; d < 0.1 * mm; d += 0.01 * mm)
    EXPECT_NEAR(r_curve_eq2(law, 200, d), 200, 1e-9);
}

TEST(Law, LoadUnloadReloadDissipatesExactlyTheArea) {
  // A single cohesive point driven through the whole law with two unload/reload excursions must
  // dissipate exactly J_c. Trapezoid work on a path that is piecewise linear in opening, with
  // steps aligned to the kinks, is exact up to round-off: tolerance 1e-9 relative.
  const auto law = make_trilinear(pva_control());
  std::vector<double> path;
  const auto go = [&](double from, double to, int n) {
    for (int i = 1; i <= n; ++i)
      path.push_back(from + (to - from) * i / n);
  };
  path.push_back(0);
  go(0, 0.1 * mm, 10);
  go(0.1 * mm, 0.5 * mm, 40);
  go(0.5 * mm, -0.01 * mm, 51); // unload into contact
  go(-0.01 * mm, 1.0 * mm, 101);
  go(1.0 * mm, 3.0 * mm, 200);
  go(3.0 * mm, 0.2 * mm, 280);
  go(0.2 * mm, 6.0 * mm, 580);
  go(6.0 * mm, 7.0 * mm, 10);
  double dmax = 0, work = 0, t_prev = 0;
  const double k_contact = law.initial_stiffness();
  for (std::size_t i = 1; i < path.size(); ++i) {
    const auto r = law.respond(path[i], dmax, k_contact);
    work += 0.5 * (t_prev + r.traction) * (path[i] - path[i - 1]);
    t_prev = r.traction;
    dmax = r.delta_max;
  }
  EXPECT_NEAR(work, law.area(), 1e-9 * law.area());
  EXPECT_TRUE(law.respond(7 * mm, dmax, k_contact).failed);
}

TEST(Law, ContactIsElasticAndStoresNoDamage) {
  const auto law = make_trilinear(pva_control());
  const auto r = law.respond(-0.05 * mm, 0.0, 1e12);
  EXPECT_LT(r.traction, 0);
  EXPECT_EQ(r.delta_max, 0.0);
}

TEST(Law, ExponentialIntegralMatchesQuadrature) {
  const ExponentialLaw law(400 * kPa, 4 * mm);
  double q = 0;
  const int n = 200000;
  const double h = 2.5 * mm / n;
  for (int i = 0; i < n; ++i)
    q += law.envelope((i + 0.5) * h) * h; // midpoint rule, error ~1e-10 relative
  EXPECT_NEAR(law.envelope_integral(2.5 * mm), q, 1e-8 * q);
  EXPECT_NEAR(law.envelope(4 * mm - 1e-15), 0.0, 1e-3);
  EXPECT_TRUE(law.rigid_at_zero_opening());
}

TEST(Law, ElasticRiseRegularizesARigidLaw) {
  const auto lin = make_linear_softening(500 * kPa, 3 * mm);
  const auto reg = lin.with_elastic_rise(0.003 * mm);
  EXPECT_FALSE(reg.rigid_at_zero_opening());
  // Area loss is sigma_c delta_e / 2 to first order: 0.75 J/m^2 of 750.
  EXPECT_NEAR(lin.area() - reg.area(), 0.5 * 500 * kPa * 0.003 * mm, 1e-3);
}

TEST(Law, BadLawsAreRejectedWithReasons) {
  EXPECT_THROW(PiecewiseLinearLaw({{0, 0}, {1e-3, -5}, {2e-3, 0}}, "t"), InputError);
  EXPECT_THROW(PiecewiseLinearLaw({{0, 0}, {2e-3, 5}, {1e-3, 0}}, "t"), InputError);
  EXPECT_THROW(PiecewiseLinearLaw({{0, 0}, {1e-3, 5}, {2e-3, 1}}, "t"), InputError);
  EXPECT_THROW(PiecewiseLinearLaw({{1e-4, 0}, {1e-3, 5}, {2e-3, 0}}, "t"), InputError);
  LawSpec s;
  s.type = "trilinear";
  s.delta_c = 0.5 * mm; // before the last point
  s.points = parse_points_mm_kPa("0.1:661, 1.0:187", "test");
  try {
    make_law(s);
    FAIL() << "delta_c before the last point accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("Delta c"), std::string::npos);
  }
  EXPECT_THROW(parse_points_mm_kPa("0.1;661", "test"), InputError);
  s.type = "quadratic";
  EXPECT_THROW(make_law(s), InputError);
}

TEST(Law, SeedControlLawsMatchTable1) {
  // J1 of the PVA control row printed as 321 J/m^2 (Table 1).
  EXPECT_NEAR(seed_control_law("PVA").j1(), 321, 0.5);
  EXPECT_DOUBLE_EQ(seed_control_law("EPI").dc, 3.5 * mm);
  EXPECT_THROW(seed_control_law("MDF"), InputError);
}
