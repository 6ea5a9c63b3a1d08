// R without crack readings (CBBM equivalent crack) and the direct energy on step-wise, lagging
// crack readings, against beam-model records with a known law (docs/verification.md, "R without
// crack readings and step-wise readings"). The records are written as in record_from_beam_tests.cc.
#include "../common/thin_dcb_case.h"
#include "fiberbridge/analysis/line_fit.h"
#include "fiberbridge/analysis/record_reduction.h"
#include "fiberbridge/analysis/synthetic_record.h"
#include "fiberbridge/beam/dcb_beam.h"
#include "fiberbridge/core/units.h"
#include "fiberbridge/law/piecewise_linear_law.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

using namespace fiberbridge;
using namespace fiberbridge::analysis;
using units::mm;

namespace {

/// The thin case's law with its openings x k and stresses / k: the same J_c, a bridging zone
/// that grows with k.
law::TrilinearParameters scaled_law(double k) {
  auto p = thin_dcb_case::bridging();
  p.d1 *= k;
  p.d2 *= k;
  p.dc *= k;
  p.s1 /= k;
  p.s2 /= k;
  return p;
}

result::SimulationResult run(const specimen::Specimen& s, const law::TrilinearParameters& p) {
  beam::BeamParameters bp;
  bp.n_elements = 300;
  bp.steady_state_window = 1.0; // to the end of the ligament
  return thin_dcb_case::rising_part(beam::simulate_dcb(s, thin_dcb_case::material(),
                                                       law::make_trilinear(p),
                                                       thin_dcb_case::j_tip, bp));
}

/// A record whose crack column is the true tip at every row (no reading noise to speak of).
TestRecord true_crack_record(const result::SimulationResult& sim, unsigned seed) {
  SyntheticRecordOptions so;
  so.crack_reading_interval = 0.1; // every row
  so.crack_reading_noise = 1e-12;
  so.seed = seed;
  return make_synthetic_record(sim, so, "beam");
}

ReduceOptions cbbm_options() {
  ReduceOptions o;
  // The beam model is geometrically linear: no F/N to undo.
  o.large_displacement_correction = false;
  o.shear_modulus = thin_dcb_case::material().G_LT;
  o.transverse_modulus = thin_dcb_case::material().E_T;
  return o;
}

} // namespace

// The equivalent-crack R plateau against G_ss = J_tip + J_c, for bridging zones of growing length
// (the law scaled in opening by k and in stress by 1/k), on a 300 mm long specimen so that the
// largest zone reaches steady state. Also where a_eq sits between the traction-free crack (the
// zone's trailing end, `root`) and the tip. Figures: docs/verification.md.
TEST(EquivalentCrackFromBeam, PlateauAgainstGssAndTheZoneLength) {
  auto s = thin_dcb_case::specimen();
  s.length = 300 * mm;
  for (double k : {0.5, 1.0, 2.0}) {
    const auto p = scaled_law(k);
    const double g_ss = thin_dcb_case::j_tip + p.j1() + p.j2();
    const auto sim = run(s, p);
    TestRecord rec = true_crack_record(sim, 5);
    const std::vector<double> tip = rec.crack_length;
    rec.crack_length.clear();
    TestSpecimen sp;
    sp.width = s.width;
    sp.arm_thickness = s.arm_thickness();
    sp.initial_crack = sim.rcurve.front().a;
    const auto r = reduce_record(rec, sp, cbbm_options());
    ASSERT_EQ(r.crack, "equivalent");
    // Truth along the record: tip, root and zone length at each row's opening.
    std::vector<double> x, root, zone;
    for (const auto& q : sim.rcurve) {
      x.push_back(q.load_point_opening);
      root.push_back(q.root);
      zone.push_back(q.zone_length);
    }
    const std::size_t last = r.a.size() - 1;
    const double op = r.opening[last];
    const double tip_end = tip[r.rows[last]], root_end = interpolate_linear(x, root, op);
    const double zone_end = interpolate_linear(x, zone, op);
    const double behind_tip = tip_end - r.a[last];
    std::printf("k %.1f: zone %.1f mm at the end (tip %.1f mm); G_ss %.0f J/m^2; CBBM plateau "
                "%.0f (%+.1f %%), direct energy vs a_eq %.0f (%+.1f %%), model R_energy at the "
                "end %.0f; a_eq %.2f mm behind the tip = %.2f of the zone; E_f %.2f GPa, "
                "|Delta| %.2f mm\n",
                k, zone_end / mm, tip_end / mm, g_ss, r.cbbm.plateau,
                100 * (r.cbbm.plateau / g_ss - 1), r.energy.plateau,
                100 * (r.energy.plateau / g_ss - 1), sim.rcurve.back().R_energy,
                behind_tip / mm, behind_tip / zone_end, r.flexural_modulus / 1e9,
                r.cbbm_delta / mm);
    // a_eq sits at the tip, not at the traction-free crack: it includes the whole zone
    // (measured: -0.04, 0.00, +0.04 of the zone behind the tip for k = 0.5, 1, 2; the tip-side
    // spread of about 1 mm at a = 290 mm is CBBM's Timoshenko compliance against the model's
    // beam calibrated once at a0). The bounds: that spread, doubled.
    EXPECT_GT(behind_tip / zone_end, -0.1) << "k " << k;
    EXPECT_LT(behind_tip / zone_end, 0.1) << "k " << k;
    EXPECT_GT(r.a[last] - root_end, 0.9 * zone_end) << "k " << k;
    // Plateau (mean over the last third of the equivalent extension) against G_ss: measured
    // -0.7, -1.5, -1.6 % by CBBM and +0.1, -0.7, -0.8 % by direct energy against a_eq (k = 0.5,
    // 1, 2). The curve is still rising at the start of the last third for k = 2 (the model's own
    // R_energy is 2 % below G_ss at the end), which is part of those figures; 3 % is the measured
    // worst plus that rise's share, not more.
    EXPECT_NEAR(r.cbbm.plateau / g_ss, 1, 0.03) << "k " << k;
    EXPECT_NEAR(r.energy.plateau / g_ss, 1, 0.03) << "k " << k;
  }
}
