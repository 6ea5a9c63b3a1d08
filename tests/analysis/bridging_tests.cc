// The fiber-bridging model of seed section 3.4 (Eqs. 9-15) and the rho_b column of Table 1.
#include "fiberbridge/analysis/bridging_model.h"
#include "fiberbridge/analysis/degradation.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/units.h"

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

using namespace fiberbridge;
using namespace fiberbridge::analysis;
using units::kPa;
using units::mm;

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();
const std::string table1 = std::string(FIBERBRIDGE_DATA_DIR) + "/reference/seed_table1.csv";

/// sigma1 at delta = 0.1 mm -> rho_b [1/mm^2] from the small-k governing form (Eqs. 13/15).
double rho_per_mm2(double sigma1_kPa, double lb_mm, const BridgingFiber& f) {
  return bridged_density(sigma1_kPa * kPa, 0.1 * mm, lb_mm * mm, f, BridgingMechanism::governing,
                         true) *
         units::mm2;
}

} // namespace

TEST(Bridging, Eq11FactorIsTheIntegralOverRbDividedByRb) {
  // Eq. 11: sigma = E A rho k^3/(4 r_b) int_0^r_b r(1+r)/(1-r)^3 dr, and the closed form printed
  // on its second line is E A rho k^3/4 * F(r_b): so F must equal the integral divided by r_b.
  const auto integrand = [](double r) { return r * (1 + r) / std::pow(1 - r, 3); };
  for (double rb : {1e-6, 1e-3, 0.05, 0.0999, 0.1, 0.3, 0.5, 0.8, 0.95, 0.99}) {
    // The integrand grows like (1 - r)^-3 towards r_b -> 1: integrate in s = -ln(1 - r), where
    // dr = e^-s ds and it becomes the smooth g(r) e^-s, scaled to [0, 1] (s = S tau) so that the
    // quadrature sees an O(F) integrand for every r_b and its relative error estimate means
    // something: F = (S / r_b) int_0^1 g(r(S tau)) e^(-S tau) dtau.
    const double S = -std::log1p(-rb);
    const auto in_tau = [&](double tau) {
      const double s = S * tau;
      return integrand(-std::expm1(-s)) * std::exp(-s);
    };
    double error = 0;
    const double mean = S / rb *
                        boost::math::quadrature::gauss_kronrod<double, 61>::integrate(
                            in_tau, 0.0, 1.0, 15, 1e-14, &error);
    error *= S / rb;
    // Adaptive Gauss-Kronrod on a smooth integrand reaches ~1e-15 relative (asserted through its
    // estimate); the closed form loses at most ~2 digits to cancellation near r_b = 0.1 (where
    // the series takes over). 1e-12 relative covers both with margin.
    ASSERT_LT(error, 1e-13 * mean) << rb;
    EXPECT_NEAR(eq11_factor(rb), mean, 1e-12 * mean) << rb;
  }
  EXPECT_EQ(eq11_factor(0.0), 0.0); // the F(0) = 0 limit
  // Series and closed form meet continuously at the switch r = 0.1 (slope dF/dr ~ 0.7 there).
  EXPECT_NEAR(eq11_factor(std::nextafter(0.1, 0.0)), eq11_factor(0.1), 1e-14);
  EXPECT_THROW(eq11_factor(1.0), InputError);
  EXPECT_THROW(eq11_factor(-0.1), InputError);
}

TEST(Bridging, Eq9ExactStrainTendsToTheSmallKFormAsKSquared) {
  // Expanding Eq. 9 with c = (1+r)/(1-r): eps_exact/eps_small - 1 = -k^2 (c^2 + 3)/16 + O(k^4
  // c^4). At k = 1e-4 the O(k^4 c^4) term is < 1e-6 relative to the leading correction for
  // c <= 9 (r <= 0.8), and round-off in a ratio near 1 - 5e-8 is ~1e-8 of it: tolerance 1e-5.
  const double l_b = 6.7 * mm, k = 1e-4;
  for (double r : {0.05, 0.2, 0.5, 0.8}) {
    const double c = (1 + r) / (1 - r);
    const double exact = fiber_strain_exact(k * l_b, k, r, l_b);
    const double small = fiber_strain_small_k(k, r);
    const double predicted = -k * k * (c * c + 3) / 16;
    EXPECT_NEAR((exact / small - 1) / predicted, 1.0, 1e-5) << r;
  }
  // The correction really is O(k^2): a tenfold smaller k makes it 100 times smaller.
  const double r = 0.5;
  const double at_1 = fiber_strain_exact(1e-2 * l_b, 1e-2, r, l_b) / fiber_strain_small_k(1e-2, r);
  const double at_2 = fiber_strain_exact(1e-3 * l_b, 1e-3, r, l_b) / fiber_strain_small_k(1e-3, r);
  EXPECT_NEAR((at_1 - 1) / (at_2 - 1), 100, 0.1); // O(k^4) part: (c^2+3)k^2/16 ~ 8e-5 of 100
  EXPECT_THROW(fiber_strain_exact(l_b * 0.01, 0.01, 1.0, l_b), InputError); // zero-length fiber
  EXPECT_THROW(fiber_strain_exact(1e-4, 0.01, 0.5, -1.0), InputError);
}

TEST(Bridging, Eq12RootGivesTheBreakingStrainWithTheSmallKStrain) {
  const auto f = seed_tracheid_fiber();
  const double eps_fb = f.sigma_fb / f.E_f;
  for (double k : {1e-5, 1e-3, 0.0149, 0.1, 1.0, 10.0}) {
    const double rb = r_b_breaking(k, f);
    ASSERT_GT(rb, 0.0);
    ASSERT_LT(rb, 1.0);
    // Round-off: r_b itself to ~1 ulp; the strain's condition number in r is 1/r + 2/(1-r).
    const double tol = 8 * eps * (1 / rb + 2 / (1 - rb));
    EXPECT_NEAR(fiber_strain_small_k(k, rb) / eps_fb, 1.0, tol) << k;
    // The printed form of Eq. 12 agrees where it does not cancel (phi of order 1 or less).
    const double phi = k / (2 * std::sqrt(eps_fb));
    if (phi < 1) {
      EXPECT_NEAR(rb, 1 + phi * phi - phi * std::sqrt(2 + phi * phi), 4 * eps) << k;
    }
  }
  EXPECT_EQ(r_b_breaking(0.0, f), 1.0); // no opening: no fiber is strained, none breaks
}

TEST(Bridging, Eq14RootBalancesThePeelingToughness) {
  for (const auto& f : {seed_tracheid_fiber(), seed_bundle_fiber(50), seed_bundle_fiber(200)})
    for (double k : {1e-5, 1e-3, 0.0149, 0.1, 1.0, 10.0}) {
      const double rb = r_b_peeling(k, f);
      ASSERT_GT(rb, 0.0);
      ASSERT_LT(rb, 1.0);
      const double g = f.area() * f.E_f / (4 * f.peel_width()) * std::pow(k, 4) * rb /
                       std::pow(1 - rb, 4); // Eq. 14's energy release rate at r_b
      // r_b is solved to ~4 ulp in 1 - r_b; condition number of G in r: 1/r + 4/(1-r).
      const double tol = 16 * eps * (1 / rb + 4 / (1 - rb));
      EXPECT_NEAR(g / f.G_c, 1.0, tol) << k;
    }
}

TEST(Bridging, SmallKLimitsEq13AndEq15AreApproachedLinearlyInK) {
  // Expanding Eq. 11 about u = 1 - r_b -> 0: F = 1/u^2 - 2/u - ln u + O(1). Breaking (Eq. 12):
  // u = sqrt(2) phi - phi^2 + ..., so sigma/sigma_13 - 1 = -sqrt(2) phi = -k/sqrt(2 eps_fb) + O(k^2
  // ln k). Peeling (Eq. 14): u = s (1 - u)^(1/4), s = k (A E/(4 W G))^(1/4), so sigma/sigma_15 -
  // 1 = -(3/2) s + O(k^2 ln k). The slope of the relative difference in k must approach these.
  const auto f = seed_tracheid_fiber();
  const double l_b = 6.7 * mm, rho = 1e8;
  const double c_break = -1 / std::sqrt(2 * f.sigma_fb / f.E_f);
  const double c_peel = -1.5 * std::pow(f.area() * f.E_f / (4 * f.peel_width() * f.G_c), 0.25);
  double previous_break = 0, previous_peel = 0;
  for (double k : {1e-3, 1e-4, 1e-5, 1e-6}) {
    const double d = k * l_b;
    const double rel_break = bridging_stress_exact(d, l_b, rho, f, BridgingMechanism::breaking) /
                                 bridging_stress_eq13(d, l_b, rho, f) -
                             1;
    const double rel_peel = bridging_stress_exact(d, l_b, rho, f, BridgingMechanism::peeling) /
                                bridging_stress_eq15(d, l_b, rho, f) -
                            1;
    const double e_break = std::abs(rel_break / k / c_break - 1);
    const double e_peel = std::abs(rel_peel / k / c_peel - 1);
    if (previous_break > 0) {
      // The remainder of the slope is O(k ln k): a decade in k shrinks it by 10 ln(10k)/ln(k),
      // 7.5 at k = 1e-3 and more below. Requiring a factor 5 leaves room for the O(k) part.
      EXPECT_LT(e_break, previous_break / 5) << k;
      EXPECT_LT(e_peel, previous_peel / 5) << k;
    }
    previous_break = e_break;
    previous_peel = e_peel;
  }
  // At k = 1e-6 the slope has converged to 1e-3 (measured: 6e-5 breaking, 4e-5 peeling).
  EXPECT_LT(previous_break, 1e-3);
  EXPECT_LT(previous_peel, 1e-3);
}

TEST(Bridging, PeelingGovernsForTracheidsAndDiffersLittleFromBreaking) {
  // Seed section 3.4: "In all calculations, the peeling mechanics determined the cohesive stress,
  // but the differences between peeling and fiber breaking were small." PVA control: delta =
  // 0.1 mm, l_b = 6.7 mm (k = 0.0149).
  const auto f = seed_tracheid_fiber();
  const double d = 0.1 * mm, l_b = 6.7 * mm, k = d / l_b, rho = 1e8;
  EXPECT_EQ(governing_mechanism(k, f), BridgingMechanism::peeling);
  EXPECT_LT(r_b_peeling(k, f), r_b_breaking(k, f)); // larger x_b
  EXPECT_EQ(r_b(k, f, BridgingMechanism::governing), r_b_peeling(k, f));
  const double peel = bridging_stress_exact(d, l_b, rho, f, BridgingMechanism::peeling);
  const double brk = bridging_stress_exact(d, l_b, rho, f, BridgingMechanism::breaking);
  EXPECT_EQ(bridging_stress_exact(d, l_b, rho, f, BridgingMechanism::governing), peel);
  EXPECT_LT(peel, brk);
  // How small: to first order in k (previous test) peel/brk = (sqrt(E G/r_f)/sigma_fb) (1 +
  // (c_peel - c_break) k) = 0.9760 (1 - 2.88 k) = 0.934 here; measured 0.9331. The O(k^2 ln k)
  // remainders are 1.5-1.7 % each at this k; 0.01 tests the first-order difference they share.
  const double c_break = -1 / std::sqrt(2 * f.sigma_fb / f.E_f);
  const double c_peel = -1.5 * std::pow(f.area() * f.E_f / (4 * f.peel_width() * f.G_c), 0.25);
  EXPECT_NEAR(peel / brk,
              std::sqrt(f.E_f * f.G_c / f.r_f) / f.sigma_fb * (1 + (c_peel - c_break) * k), 0.01);
  // Small-k: sqrt(E_f G_c / r_f) = sqrt(40e9 * 200 / 20e-6) = 632.5 MPa < sigma_fb = 648 MPa.
  EXPECT_NEAR(bridging_stress_eq15(d, l_b, rho, f) / bridging_stress_eq13(d, l_b, rho, f),
              std::sqrt(4e17) / 648e6, 1e-14);
  // The stated bundle (G_c = 50): peeling 50 MPa vs. breaking 100 MPa, peeling again.
  EXPECT_EQ(governing_mechanism(k, seed_bundle_fiber(50)), BridgingMechanism::peeling);
}

TEST(Bridging, Table1UpperBoundsFollowFromEq15WithTracheidProperties) {
  // Every printed upper bound of rho_b (20 rows) from sigma1 and l_b of the same row. Tolerance:
  // the printed bound's own rounding plus the first-order effect of the rounding of sigma1 and
  // l_b (rho ~ sigma1 l_b): |d rho| <= rho (h_sigma/sigma + h_l/l_b) + h_rho.
  const auto t = read_property_table(table1);
  const auto f = seed_tracheid_fiber();
  int checked = 0;
  for (const char* m : {"PVA", "EPI", "PRF", "PF", "DF"}) {
    const PropertyRow* s1 = t.find(m, "sigma1");
    const PropertyRow* lb = t.find(m, "lb");
    const PropertyRow* rho = t.find(m, "rho_b");
    ASSERT_TRUE(s1 && lb && rho);
    for (std::size_t i = 0; i < t.cycles.size(); ++i) {
      const double computed = rho_per_mm2(s1->values[i], lb->values[i], f);
      const std::string hi_text = rho->cells[i].substr(rho->cells[i].find('-') + 1);
      const double printed = rho->ranges[i].second;
      const double h_printed = hi_text.find('.') == std::string::npos ? 0.5 : 0.05;
      const double tol = h_printed + computed * (s1->half_units[i] / s1->values[i] +
                                                 lb->half_units[i] / lb->values[i]);
      EXPECT_NEAR(computed, printed, tol) << m << " " << t.cycles[i] << " cycles";
      ++checked;
    }
  }
  EXPECT_EQ(checked, 20);
  // The two anchors of docs/design.md section 1, "Fiber-bridging model": PVA control 111, EPI
  // control 124 per mm^2.
  EXPECT_NEAR(rho_per_mm2(661, 6.7, f), 111.4, 0.05);
  EXPECT_NEAR(rho_per_mm2(579, 8.5, f), 123.8, 0.05);
  // Eq. 13 (breaking, 648 MPa) would give 2.4 % less; the exact Eq. 11 + 14 form 12 % more (its
  // per-fiber stress is lower at k = 0.015). Neither is what the table used.
  EXPECT_NEAR(bridged_density(661 * kPa, 0.1 * mm, 6.7 * mm, f, BridgingMechanism::breaking, true) *
                  units::mm2,
              108.8, 0.05);
  EXPECT_NEAR(
      bridged_density(661 * kPa, 0.1 * mm, 6.7 * mm, f, BridgingMechanism::governing, false) *
          units::mm2,
      125.0, 0.05);
}

TEST(Bridging, StatedBundleValuesDoNotGiveThePrintedLowerBounds) {
  // The stated bundle (E_f 10 GPa, r_f 200 um, sigma_f 100 MPa, G_c 50 J/m^2) gives rho_b about
  // 2.8 times below every printed LVL lower bound (PVA control: 14.1 vs. 40). Reported, not tuned.
  // Diagnosis: rho ~ 1/(A_f sqrt(E G / r_f)) ~ r_f^(-3/2), and 2^(3/2) = 2.83 is the printed
  // upper/lower ratio in every row; r_f = 100 um (200 um taken as the diameter) reproduces all
  // 20 printed lower bounds within the same rounding tolerance as the upper bounds.
  const auto t = read_property_table(table1);
  const auto stated = seed_bundle_fiber(50);
  auto halved = stated;
  halved.r_f = 100e-6;
  EXPECT_NEAR(rho_per_mm2(661, 6.7, stated), 14.10, 0.005);
  EXPECT_NEAR(rho_per_mm2(661, 6.7, seed_bundle_fiber(200)), 7.05, 0.005);
  for (const char* m : {"PVA", "EPI", "PRF", "PF", "DF"}) {
    const PropertyRow* s1 = t.find(m, "sigma1");
    const PropertyRow* lb = t.find(m, "lb");
    const PropertyRow* rho = t.find(m, "rho_b");
    ASSERT_TRUE(s1 && lb && rho);
    for (std::size_t i = 0; i < t.cycles.size(); ++i) {
      const std::string lo_text = rho->cells[i].substr(0, rho->cells[i].find('-'));
      const double printed = rho->ranges[i].first;
      const double h_printed = lo_text.find('.') == std::string::npos ? 0.5 : 0.05;
      const double rel_inputs =
          s1->half_units[i] / s1->values[i] + lb->half_units[i] / lb->values[i];
      const double as_stated = rho_per_mm2(s1->values[i], lb->values[i], stated);
      const double as_diameter = rho_per_mm2(s1->values[i], lb->values[i], halved);
      if (std::string(m) != "DF") { // DF's bounds (0.3-24) are too coarse to tell a factor 2.8
        EXPECT_GT(std::abs(as_stated - printed), h_printed + as_stated * rel_inputs)
            << m << " " << t.cycles[i];
      }
      EXPECT_NEAR(as_diameter, printed, h_printed + as_diameter * rel_inputs)
          << m << " " << t.cycles[i];
    }
  }
}

TEST(Bridging, DensityInversionRoundTripsAndRejectsBadInput) {
  const auto f = seed_tracheid_fiber();
  const double d = 0.1 * mm, l_b = 6.7 * mm, rho = 1.114e8;
  for (auto m :
       {BridgingMechanism::breaking, BridgingMechanism::peeling, BridgingMechanism::governing}) {
    const double s = bridging_stress_exact(d, l_b, rho, f, m);
    // Linear in rho: one multiplication and one division of round-off.
    EXPECT_NEAR(bridged_density(s, d, l_b, f, m, false) / rho, 1.0, 4 * eps);
  }
  EXPECT_NEAR(bridged_density(bridging_stress_eq15(d, l_b, rho, f), d, l_b, f,
                              BridgingMechanism::governing, true) /
                  rho,
              1.0, 4 * eps);
  auto bad = f;
  bad.E_f = -1;
  EXPECT_THROW(bridging_stress_eq13(d, l_b, rho, bad), InputError);
  EXPECT_THROW(r_b_peeling(0.01, bad), InputError);
  EXPECT_THROW(r_b_breaking(-0.01, f), InputError);
  EXPECT_THROW(bridged_density(1e5, 0.0, l_b, f, BridgingMechanism::peeling, true), InputError);
  EXPECT_THROW(bridging_stress_exact(d, 0.0, rho, f, BridgingMechanism::peeling), InputError);
  EXPECT_EQ(bridging_stress_exact(0.0, l_b, rho, f, BridgingMechanism::governing), 0.0);
}
