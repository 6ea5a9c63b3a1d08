// `reduce` against a known answer: a record written from a beam-model run with a known law
// (make_synthetic_record: a testing machine's sampling, noise and step-wise crack readings),
// read back through the record reader and reduced; the direct-energy R(a) must recover the
// model's own R_energy(a). The beam model is the generator here because it runs in well under a
// second; the FEM variant is not done (docs/verification.md, "Test records").
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
#include <string>
#include <unistd.h>

using namespace fiberbridge;
using namespace fiberbridge::analysis;
using units::mm;

namespace {

/// A thin glass-fibre DCB like the shared records (data/dcb_records/README.md): B 25 mm, arms
/// 2.7 mm, length 123 mm, a0 35 mm.
law::Specimen thin_dcb() {
  law::Specimen s;
  s.length = 123 * mm;
  s.width = 25 * mm;
  s.height = 5.4 * mm;
  s.initial_crack = 35 * mm;
  return s;
}

law::Material glass_composite() {
  law::Material m;
  m.E_L = 19.3e9;
  m.E_T = 6.11e9;
  m.G_LT = 2.29e9;
  m.nu_LT = 0.3;
  return m;
}

/// Bridging of 750 J/m^2 over 4 mm on a 250 J/m^2 tip: an R curve rising over tens of mm.
law::TrilinearParameters bridging() {
  law::TrilinearParameters p;
  p.d1 = 0.02 * mm;
  p.s1 = 1.0e6;
  p.d2 = 0.5 * mm;
  p.s2 = 0.25e6;
  p.dc = 4 * mm;
  return p;
}

/// The rows up to the first fall of the load-point opening (snap-back near the far end cannot be
/// sampled at constant crosshead rate).
law::SimulationResult rising_part(law::SimulationResult r) {
  std::size_t n = 1;
  while (n < r.rcurve.size() && r.rcurve[n].load_point_opening > r.rcurve[n - 1].load_point_opening)
    ++n;
  r.rcurve.resize(n);
  return r;
}

} // namespace

TEST(RecordFromBeam, ReduceRecoversTheModelsEnergyRCurve) {
  const double j_tip = 250;
  beam::BeamParameters bp;
  bp.n_elements = 200;
  bp.steady_state_window = 1.0; // run to the end of the ligament
  const auto sim = rising_part(beam::simulate_dcb(thin_dcb(), glass_composite(),
                                                  law::make_trilinear(bridging()), j_tip, bp));
  ASSERT_GT(sim.rcurve.size(), 50u);

  for (bool root : {false, true}) {
    SyntheticRecordOptions so;
    so.crack_reading_interval =
        2; // a reading every 2 s: 0.2-0.5 mm apart, as in the shared records
    so.with_delta_root = root;
    so.seed = root ? 7 : 3;
    const TestRecord made = make_synthetic_record(sim, so, "beam");
    const std::string path = ::testing::TempDir() + "fb_" + std::to_string(::getpid()) +
                             (root ? "_root" : "") + "_beam_record.csv";
    write_test_record_csv(path, made, describe_synthetic_record(sim, so));
    const auto rec = read_test_records(path).at(0);
    std::remove(path.c_str());
    EXPECT_EQ(rec.delta_root.empty(), !root);

    TestSpecimen sp;
    sp.width = 25 * mm;
    sp.arm_thickness = 2.7 * mm;
    const auto r = reduce_record(rec, sp);
    std::vector<double> model_a, model_R;
    for (const auto& q : sim.rcurve) {
      model_a.push_back(q.a);
      model_R.push_back(q.R_energy);
    }
    std::vector<double> rel;
    std::size_t inside = 0, n = 0;
    for (std::size_t i = 0; i < r.a.size(); ++i) {
      // Two-sided windows only: at the ends the local line is one-sided and lags a curve that
      // still rises.
      if (r.a[i] - r.a0 < r.window / 2 || r.a.back() - r.a[i] < r.window / 2)
        continue;
      const double truth = interpolate_linear(model_a, model_R, r.a[i]);
      rel.push_back(std::abs(r.R_energy[i] / truth - 1));
      inside += r.R_energy_lo[i] <= truth && truth <= r.R_energy_hi[i];
      ++n;
    }
    ASSERT_GT(n, 50u);
    std::sort(rel.begin(), rel.end());
    const double median = rel[rel.size() / 2], p90 = rel[9 * rel.size() / 10];
    std::printf("%s: %zu readings, window %.1f mm, |R_energy/model - 1| median %.4f, 90th %.4f; "
                "model inside the band at %.0f %% of the readings\n",
                root ? "with delta_root" : "load-line only", n, r.window / mm, median, p90,
                100.0 * inside / n);
    // Stated band: median error below 1.5 % and 90 % of the readings below 4 %. Measured (seeds
    // 3 and 7): median 0.4-0.5 %, 90th percentile 1.4-1.6 %; the record's noise (0.05 N on
    // 60-100 N, 1 um on the opening, 0.1 mm on the readings) gives the local slope over the
    // 10.8 mm window a standard error of about 1 %, so other seeds move these figures by that
    // much; the bounds are the measured values plus that spread, not more.
    EXPECT_LT(median, 0.015);
    EXPECT_LT(p90, 0.04);
    // The band is +-2 standard errors: it should hold the truth at most readings, though not
    // at all (the noise on a reading is correlated over the window through the step-wise
    // readings).
    EXPECT_GT(static_cast<double>(inside) / n, 0.7);
    if (root) {
      const auto data = to_rdelta({r}, "synthetic");
      ASSERT_EQ(data.replicates.size(), 1u);
      EXPECT_EQ(data.replicates[0].delta.size(), r.a.size());
    }
  }
}
