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
  return thin_dcb_case::rising_part(beam::simulate_dcb(
      s, thin_dcb_case::material(), law::make_trilinear(p), thin_dcb_case::j_tip, bp));
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
    auto sp = specimen::Specimen::unknown();
    sp.width = s.width;
    sp.height = s.height;
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
                100 * (r.energy.plateau / g_ss - 1), sim.rcurve.back().R_energy, behind_tip / mm,
                behind_tip / zone_end, r.flexural_modulus / 1e9, r.cbbm_delta / mm);
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

namespace {

/// Step-wise, lagging crack readings as an operator makes them: a new reading at irregular
/// intervals (uniform in [1, `max_interval`] s), each the true tip of `lag` seconds earlier (lag
/// uniform in [0, `max_lag`] s), rounded down to `quantum` (a scale read to the half millimetre),
/// plus 0.1 mm of noise; held at the running maximum as the reader does. The rows in between
/// repeat the last reading.
TestRecord lagging_readings(const TestRecord& truth, unsigned seed, double max_interval,
                            double max_lag, double quantum) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> interval(1.0, max_interval), lag(0.0, max_lag);
  std::normal_distribution<double> noise(0.0, 0.1 * mm);
  TestRecord r = truth;
  double next = 0, reading = truth.crack_length.front();
  for (std::size_t i = 0; i < r.time.size(); ++i) {
    if (r.time[i] >= next) {
      const double t = r.time[i] - lag(rng);
      const double a =
          interpolate_linear(truth.time, truth.crack_length, std::max(t, truth.time.front()));
      reading = std::max(reading, quantum * std::floor(a / quantum) + noise(rng));
      next = r.time[i] + interval(rng);
    }
    r.crack_length[i] = reading;
  }
  return r;
}

struct Coverage {
  double inside = 0, n = 0, abs_err = 0, half = 0;
  void add(double lo, double R, double hi, double truth) {
    if (!std::isfinite(R))
      return;
    inside += lo <= truth && truth <= hi;
    abs_err += std::abs(R / truth - 1);
    half += 0.5 * (hi - lo) / truth;
    ++n;
  }
};

} // namespace

// Direct energy on step-wise, lagging readings (issue 31 item 5): the estimate against the
// readings as read, against the monotone smooth crack, and against the CBBM equivalent crack,
// each judged by whether its band covers the model's R_energy at the crack length it reports (two-
// sided windows), over 12 seeds of each of two reading styles. Figures: docs/verification.md.
TEST(EquivalentCrackFromBeam, DirectEnergyOnStepwiseLaggingReadings) {
  const auto sim = run(thin_dcb_case::specimen(), thin_dcb_case::bridging());
  std::vector<double> model_a, model_R;
  for (const auto& q : sim.rcurve) {
    model_a.push_back(q.a);
    model_R.push_back(q.R_energy);
  }
  auto sp = specimen::Specimen::unknown();
  sp.width = 25 * mm;
  sp.height = 2 * 2.7 * mm; // both arms
  struct Style {
    double max_interval, max_lag, quantum;
  };
  for (const Style st : {Style{6, 3, 0.5 * mm}, Style{12, 6, 1 * mm}, Style{30, 15, 2 * mm}}) {
    Coverage read, mono, eq;
    for (unsigned seed = 200; seed < 212; ++seed) {
      const TestRecord truth = true_crack_record(sim, seed);
      const TestRecord rec = lagging_readings(truth, seed, st.max_interval, st.max_lag, st.quantum);
      ReduceOptions o = cbbm_options();
      o.energy_crack = "readings";
      const auto r = reduce_record(rec, sp, o);
      o.energy_crack = "monotone";
      const auto m = reduce_record(rec, sp, o);
      ASSERT_EQ(r.a.size(), m.a.size());
      for (std::size_t j = 0; j < r.a.size(); ++j) {
        if (r.a[j] - r.a0 < r.window / 2 || r.a.back() - r.a[j] < r.window / 2)
          continue;
        const double at_a = interpolate_linear(model_a, model_R, r.a[j]);
        read.add(r.R_energy_lo[j], r.R_energy[j], r.R_energy_hi[j], at_a);
        mono.add(m.R_energy_lo[j], m.R_energy[j], m.R_energy_hi[j], at_a);
        // Against a_eq the estimate belongs to a_eq: judged there.
        const double at_eq = interpolate_linear(model_a, model_R, r.a_eq[j]);
        eq.add(r.R_energy_eq_lo[j], r.R_energy_eq[j], r.R_energy_eq_hi[j], at_eq);
      }
    }
    auto line = [](const char* what, const Coverage& c) {
      std::printf("  %-22s covers the model at %5.1f %% of %4.0f readings, mean |error| %4.1f %%, "
                  "mean half-width %4.1f %%\n",
                  what, 100 * c.inside / c.n, c.n, 100 * c.abs_err / c.n, 100 * c.half / c.n);
    };
    std::printf("readings every 1-%.0f s, lag 0-%.0f s, rounded down to %.1f mm (12 seeds):\n",
                st.max_interval, st.max_lag, st.quantum / mm);
    line("as read", read);
    line("monotone smooth a(t)", mono);
    line("against a_eq (CBBM)", eq);
    ASSERT_GT(read.n, 200);
    // Measured (docs/verification.md): coverage as read 98.8 / 97.5 / 99.6 %, monotone 98.4 /
    // 97.1 / 99.6 %, against a_eq 46.9 / 24.5 / 74.1 %; mean |error| as read 1.8 / 3.7 / 5.0 %,
    // monotone 1.7 / 3.3 / 4.4 %, half-width 6.3 / 10.4 / 15.3 % against 6.0 / 8.5 / 13.2 %.
    // Why monotone is the default: as honest (coverage within the sampling scatter of 12 seeds,
    // about 2 %, of the as-read band) and closer to the truth with a narrower band; the estimate
    // against a_eq is off the truth by 7 % where the zone grows (dD/da_eq is not R(a_tip) while
    // a_eq - a_tip changes) and its band does not see that bias. The bounds: the nominal 95 %, and
    // the ordering that the choice rests on.
    EXPECT_GT(mono.inside / mono.n, 0.95);
    EXPECT_LT(mono.abs_err, read.abs_err);
    EXPECT_LT(eq.inside / eq.n, mono.inside / mono.n);
  }
}
