// R without crack readings against FEM-written records with a known law (issue 31 item 3): the
// CBBM equivalent-crack plateau against G_ss = J_tip + J_c and against the FEM's own R_energy,
// for bridging zones of three lengths, and where a_eq sits between the traction-free crack and
// the tip. The beam-model twin is tests/beam/equivalent_crack_from_beam_tests.cc
// (docs/verification.md, "R without crack readings, initiation values, step-wise readings").
#include "../common/thin_dcb_case.h"
#include "fiberbridge/analysis/line_fit.h"
#include "fiberbridge/analysis/record_reduction.h"
#include "fiberbridge/analysis/synthetic_record.h"
#include "fiberbridge/core/units.h"
#include "fiberbridge/fem/dcb_simulation.h"
#include "fiberbridge/law/piecewise_linear_law.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace fiberbridge;
using namespace fiberbridge::analysis;
using units::mm;

TEST(EquivalentCrackFromFem, PlateauAgainstGssAndTheZoneLength) {
  const specimen::Specimen s = thin_dcb_case::specimen();
  const specimen::Material m = thin_dcb_case::material();
  for (double k : {0.5, 1.0, 2.0}) {
    // The case's law with openings x k and stresses / k: the same J_c, a zone growing with k.
    law::TrilinearParameters p = thin_dcb_case::bridging();
    p.d1 *= k;
    p.d2 *= k;
    p.dc *= k;
    p.s1 /= k;
    p.s2 /= k;
    const double g_ss = thin_dcb_case::j_tip + p.j1() + p.j2();
    fem::FemParameters prm;
    prm.mesh.element_size = 1.0 * mm; // as record_from_fem_tests.cc: 82 advances, Q2
    prm.steady_state.window = 1.0;
    const auto sim = thin_dcb_case::rising_part(
        fem::simulate_dcb(s, m, law::make_trilinear(p), thin_dcb_case::j_tip, prm));
    SyntheticRecordOptions so;
    so.crack_reading_interval = 0.1; // every row: the true tip, kept aside
    so.crack_reading_noise = 1e-12;
    so.seed = 5;
    TestRecord rec = make_synthetic_record(sim, so, "fem");
    const std::vector<double> tip = rec.crack_length;
    rec.crack_length.clear();
    auto sp = specimen::Specimen::unknown();
    sp.width = s.width;
    sp.height = s.height;
    sp.initial_crack = sim.rcurve.front().a;
    ReduceOptions o;
    o.large_displacement_correction = false; // the FEM is geometrically linear
    o.shear_modulus = m.G_LT;
    o.transverse_modulus = m.E_T;
    const auto r = reduce_record(rec, sp, o);
    ASSERT_EQ(r.crack, "equivalent");
    std::vector<double> x, root, zone, a_model, R_model;
    for (const auto& q : sim.rcurve) {
      x.push_back(q.load_point_opening);
      root.push_back(q.root);
      zone.push_back(q.zone_length);
      a_model.push_back(q.a);
      R_model.push_back(q.R_energy);
    }
    // The truth over the same rows as the plateau: the FEM's R_energy at the true tip of each
    // row in the last third of the equivalent extension.
    double truth = 0, n = 0;
    for (std::size_t j = 0; j < r.a.size(); ++j)
      if (r.da[j] >= (1 - o.plateau_fraction) * r.da.back()) {
        truth += interpolate_linear(a_model, R_model, tip[r.rows[j]]);
        ++n;
      }
    truth /= n;
    const std::size_t last = r.a.size() - 1;
    const double op = r.opening[last];
    const double tip_end = tip[r.rows[last]], root_end = interpolate_linear(x, root, op);
    const double zone_end = interpolate_linear(x, zone, op);
    const double behind = tip_end - r.a[last];
    std::printf("FEM k %.1f: zone %.1f mm at the end (tip %.1f mm); CBBM plateau %.0f J/m^2: "
                "%+.1f %% vs G_ss %.0f, %+.1f %% vs the FEM's R_energy over the same rows %.0f; "
                "direct energy vs a_eq %.0f (%+.1f %% vs G_ss); a_eq %.2f mm behind the tip = "
                "%.2f of the zone; E_f %.2f GPa, |Delta| %.2f mm\n",
                k, zone_end / mm, tip_end / mm, r.cbbm.plateau, 100 * (r.cbbm.plateau / g_ss - 1),
                g_ss, 100 * (r.cbbm.plateau / truth - 1), truth, r.energy.plateau,
                100 * (r.energy.plateau / g_ss - 1), behind / mm, behind / zone_end,
                r.flexural_modulus / 1e9, r.cbbm_delta / mm);
    // Measured (docs/verification.md): a_eq 1.7, 2.9, 4.4 mm behind the tip for zones of 18.7,
    // 28.1, 41.8 mm (0.09-0.11 of the zone: it includes ~90 % of the zone); the CBBM plateau
    // -0.8, -0.6, -0.2 % against G_ss and +0.8, +0.6, +0.3 % against the FEM's own R_energy over
    // the same rows. Bounds: a_eq within the front fifth of the zone (twice the measured share),
    // and the plateau within 2 % of the FEM's R_energy (reduce's direct energy matches the FEM's
    // R_energy to a median 2 % row by row at 1 mm elements, record_from_fem_tests.cc: the FEM's
    // one-element advances; a mean over a third of the record averages most of that out).
    EXPECT_GT(behind / zone_end, 0.0) << "k " << k;
    EXPECT_LT(behind / zone_end, 0.2) << "k " << k;
    EXPECT_GT(r.a[last], root_end) << "k " << k;
    EXPECT_NEAR(r.cbbm.plateau / truth, 1, 0.02) << "k " << k;
  }
}
