// `reduce` against the FEM (issue 12 verification): a record written from a coarse FEM run with
// a known law (make_synthetic_record) and reduced; the direct-energy R(a) must recover the FEM's
// own R_energy(a). The beam-model twin (tests/beam/record_from_beam_tests.cc) checks the band
// on a finer curve; this one checks that nothing in the chain is beam-specific.
#include "../common/thin_dcb_case.h"
#include "fiberbridge/analysis/line_fit.h"
#include "fiberbridge/analysis/record_reduction.h"
#include "fiberbridge/analysis/synthetic_record.h"
#include "fiberbridge/core/units.h"
#include "fiberbridge/fem/dcb_simulation.h"
#include "fiberbridge/law/piecewise_linear_law.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <unistd.h>

using namespace fiberbridge;
using namespace fiberbridge::analysis;
using units::mm;

TEST(RecordFromFem, ReduceRecoversTheFemEnergyRCurve) {
  const specimen::Specimen s = thin_dcb_case::specimen();
  const specimen::Material m = thin_dcb_case::material();
  const law::TrilinearParameters p = thin_dcb_case::bridging();
  fem::FemParameters prm;
  prm.mesh.element_size = 1.0 * mm; // 82 advances over 81 mm; Q2 by auto (9.5 s CPU)

  prm.steady_state.window = 1.0;
  const auto t0 = std::chrono::steady_clock::now();
  auto sim = fem::simulate_dcb(s, m, law::make_trilinear(p), thin_dcb_case::j_tip, prm);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const std::size_t n = thin_dcb_case::rising_part(sim).rcurve.size();
  std::printf("FEM: %zu rows (%zu rising) in %.1f s, a %.1f-%.1f mm, R_energy %.0f-%.0f\n",
              sim.rcurve.size(), n, wall, sim.rcurve.front().a / mm, sim.rcurve[n - 1].a / mm,
              sim.rcurve.front().R_energy, sim.rcurve[n - 1].R_energy);
  sim.rcurve.resize(n);
  SyntheticRecordOptions so;
  so.crack_reading_interval = 2;
  so.seed = 5;
  const std::string path = ::testing::TempDir() + "fb_" + std::to_string(::getpid()) + "_fem.csv";
  write_test_record_csv(path, make_synthetic_record(sim, so, "fem"),
                        describe_synthetic_record(sim, so));
  const auto rec = read_test_records(path).at(0);
  std::remove(path.c_str());
  TestSpecimen sp;
  sp.width = s.width;
  sp.arm_thickness = s.arm_thickness();
  const auto r = reduce_record(rec, sp);
  std::vector<double> fa, fR, rel;
  for (const auto& q : sim.rcurve) {
    fa.push_back(q.a);
    fR.push_back(q.R_energy);
  }
  // The FEM's R_energy is (dW - dU)/(B da) over one element advance: it jumps as the tip passes
  // element by element (the per-row scatter is several per cent at this mesh). The reference is
  // therefore the FEM's own energy over the reduction's window: the da-weighted mean of its
  // R_energy rows within window/2, i.e. the dissipated energy across the window per area.
  auto fem_window_mean = [&](double a) {
    double sum = 0, len = 0;
    for (std::size_t j = 1; j < fa.size(); ++j) {
      const double lo = std::max(fa[j - 1], a - r.window / 2),
                   hi = std::min(fa[j], a + r.window / 2);
      if (hi > lo && std::isfinite(fR[j])) {
        sum += fR[j] * (hi - lo);
        len += hi - lo;
      }
    }
    return sum / len;
  };
  for (std::size_t i = 0; i < r.a.size(); ++i)
    if (r.a[i] - r.a0 >= r.window / 2 && r.a.back() - r.a[i] >= r.window / 2)
      rel.push_back(std::abs(r.R_energy[i] / fem_window_mean(r.a[i]) - 1));
  ASSERT_GT(rel.size(), 30u);
  std::sort(rel.begin(), rel.end());
  const double median = rel[rel.size() / 2], p90 = rel[9 * rel.size() / 10];
  std::printf("reduce vs FEM R_energy: %zu readings, median %.4f, 90th %.4f\n", rel.size(), median,
              p90);
  // Measured: median 2.05 %, 90th percentile 4.6 % at 1 mm elements; 3.1 % and 6.7 % at 1.5 mm.
  // The difference falls linearly with the element size: it comes from the FEM's one-element
  // advances (most likely: the record interpolates load and opening linearly between the critical
  // states, where the FEM's own dW follows the load-unload saw tooth), not the reduction, which
  // recovers the beam model's 0.5 mm-advance curve to 0.4 % (tests/beam/record_from_beam_tests.cc).
  // The bounds are the measured values plus half the 1 mm -> 1.5 mm change.
  EXPECT_LT(median, 0.03);
  EXPECT_LT(p90, 0.06);
}
