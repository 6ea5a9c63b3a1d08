// `reduce` against a known answer: a record written from a beam-model run with a known law
// (make_synthetic_record: a testing machine's sampling, noise and step-wise crack readings),
// read back through the record reader and reduced; the direct-energy R(a) must recover the
// model's own R_energy(a). The beam model runs in well under a second and advances by 0.5 mm; the
// FEM-written twin is tests/fem/record_from_fem_tests.cc (docs/verification.md, "Test records").
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
#include <cstdlib>
#include <string>
#include <unistd.h>

using namespace fiberbridge;
using namespace fiberbridge::analysis;
using units::mm;

using thin_dcb_case::bridging;
using thin_dcb_case::rising_part;
const auto thin_dcb = thin_dcb_case::specimen;
const auto glass_composite = thin_dcb_case::material;

TEST(RecordFromBeam, ReduceRecoversTheModelsEnergyRCurve) {
  const double j_tip = thin_dcb_case::j_tip;
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

    auto sp = specimen::Specimen::unknown();
    sp.width = 25 * mm;
    sp.height = 2 * 2.7 * mm; // both arms
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
    // The band (record_reduction.h) should hold the truth at most readings; its rate over many
    // seeds is checked in EnergyBandCoversTheKnownCurve below.
    EXPECT_GT(static_cast<double>(inside) / n, 0.7);
    if (root) {
      const auto data = to_rdelta({r}, "synthetic");
      ASSERT_EQ(data.replicates.size(), 1u);
      EXPECT_EQ(data.replicates[0].delta.size(), r.a.size());
    }
  }
}

// tests/app/data/records/beam_delta_root.csv is this generator's output (the app tests run reduce
// and extract on it through the executable, which cannot link the beam model). Regenerate with
// FIBERBRIDGE_REGENERATE=1 build/tests/beam/record_from_beam_tests; otherwise the file must match.
TEST(RecordFromBeam, BundledDeltaRootRecordIsThisGeneratorsOutput) {
  beam::BeamParameters bp;
  bp.n_elements = 200;
  bp.steady_state_window = 1.0;
  const auto sim = rising_part(beam::simulate_dcb(
      thin_dcb(), glass_composite(), law::make_trilinear(bridging()), thin_dcb_case::j_tip, bp));
  SyntheticRecordOptions so;
  so.crack_reading_interval = 2;
  so.with_delta_root = true;
  so.seed = 11;
  const TestRecord made = make_synthetic_record(sim, so, "beam");
  auto comments = describe_synthetic_record(sim, so);
  comments.insert(comments.begin(),
                  "SYNTHETIC RECORD, not a measurement: tests/beam/record_from_beam_tests.cc "
                  "(BundledDeltaRootRecordIsThisGeneratorsOutput) wrote it from a beam run, "
                  "25 x 5.4 x 123 mm DCB, a0 35 mm, trilinear 0.02:1000, 0.5:250 kPa, dc 4 mm, "
                  "J_tip 250 J/m^2");
  const std::string bundled =
      std::string(FIBERBRIDGE_SOURCE_DIR) + "/tests/app/data/records/beam_delta_root.csv";
  if (std::getenv("FIBERBRIDGE_REGENERATE"))
    write_test_record_csv(bundled, made, comments);
  const auto rec = read_test_records(bundled).at(0);
  ASSERT_EQ(rec.opening.size(), made.opening.size());
  for (std::size_t i = 0; i < rec.opening.size(); i += 97) {
    // The CSV keeps 10 significant digits (core/csv.cc); the reader sets the negative loads of
    // the noise before the test started to 0.
    const double load = std::max(0.0, made.load[i]);
    EXPECT_NEAR(rec.load[i], load, 1e-6 * (1 + load));
    EXPECT_NEAR(rec.delta_root[i], made.delta_root[i], 1e-9);
  }
}

// The direct-energy band against the known R(a) (issue 12 verification; docs/verification.md,
// "Test records"): over many seeds, the share of readings (two-sided windows) whose band holds
// the model's R_energy. Two kinds of crack readings: independent noise only (0.1 mm, as above),
// and in addition a tracking drift (0.3 mm, correlated over 5 or 12 mm of growth) like the
// shared records', where the crack readings run ahead and fall back over millimetres and the
// direct energy swings about the true curve with periods of several mm (DCB-01 beyond
// a = 62 mm). The band is +-2 x (larger of the slope's standard error and the scatter of
// neighbouring estimates): its nominal rate is 95 %.
TEST(RecordFromBeam, EnergyBandCoversTheKnownCurve) {
  beam::BeamParameters bp;
  bp.n_elements = 200;
  bp.steady_state_window = 1.0;
  const auto sim = rising_part(beam::simulate_dcb(
      thin_dcb(), glass_composite(), law::make_trilinear(bridging()), thin_dcb_case::j_tip, bp));
  std::vector<double> model_a, model_R;
  for (const auto& q : sim.rcurve) {
    model_a.push_back(q.a);
    model_R.push_back(q.R_energy);
  }
  auto sp = specimen::Specimen::unknown();
  sp.width = 25 * mm;
  sp.height = 2 * 2.7 * mm; // both arms
  const std::pair<double, double> cases[] = {
      {0.0, 5 * mm}, {0.3 * mm, 5 * mm}, {0.3 * mm, 12 * mm}};
  for (const auto& [drift, correlation] : cases) {
    std::size_t inside = 0, n = 0;
    double rel_half_width = 0;
    for (unsigned seed = 100; seed < 116; ++seed) {
      SyntheticRecordOptions so;
      so.crack_reading_interval = 2;
      so.crack_tracking_drift = drift;
      so.crack_tracking_correlation = correlation;
      so.seed = seed;
      TestRecord rec = make_synthetic_record(sim, so, "beam");
      // The reader's cleaning: readings that fall back (the drift does) held at the maximum.
      for (std::size_t i = 1; i < rec.crack_length.size(); ++i)
        rec.crack_length[i] = std::max(rec.crack_length[i], rec.crack_length[i - 1]);
      const auto r = reduce_record(rec, sp);
      for (std::size_t i = 0; i < r.a.size(); ++i) {
        if (r.a[i] - r.a0 < r.window / 2 || r.a.back() - r.a[i] < r.window / 2)
          continue;
        const double truth = interpolate_linear(model_a, model_R, r.a[i]);
        inside += r.R_energy_lo[i] <= truth && truth <= r.R_energy_hi[i];
        rel_half_width += 0.5 * (r.R_energy_hi[i] - r.R_energy_lo[i]) / truth;
        ++n;
      }
    }
    ASSERT_GT(n, 1000u);
    const double rate = static_cast<double>(inside) / n;
    std::printf(
        "tracking drift %.1f mm over %.0f mm: the band holds the model at %.1f %% of %zu readings "
        "(16 seeds), mean half-width %.1f %% of R\n",
        drift / mm, correlation / mm, 100 * rate, n, 100 * rel_half_width / n);
    // Measured (docs/verification.md, "Test records"), with the fixed 10.8 mm window: 99.2 %
    // without drift (the band is conservative there: the 2 w comparison also sees the R curve's
    // curvature), 94.5 % with drift correlated over 5 mm (errors correlated over less than the
    // window: the nominal 95 %), 90.3 % over 12 mm (errors correlated beyond the window are
    // partly common to the w and 2 w slopes, so the band sees less of them). The old +-2 s.e.
    // band held the model at 88.6 % and 38.5 % in the first two cases. With the windows chosen
    // from the data (median about 8 mm here, issue 39 item 2): 98.7 %, 91.9 % and 88.9 %: the
    // narrower windows come closer to the drift's correlation length, and the band loses 1.5-2.6
    // points of coverage there (docs/verification.md, "The chain on virtual tests: after"). The
    // 16 seeds give the rates a sampling scatter of about 1.5 % (some 10 independent windows per
    // record); the bounds are the measured rates less 2.5 %, the nominal rate where it is
    // reached.
    const double bound = drift == 0 ? 0.95 : correlation < 10 * mm ? 0.89 : 0.86;
    EXPECT_GT(rate, bound) << "drift " << drift / mm << " mm over " << correlation / mm << " mm";
  }
}
