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
#include "fiberbridge/law/exponential_law.h"
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

namespace {
/// The FEM run as a raw test record (the crack read at every second row, noise seed 5), written
/// to a file and read back as `reduce` reads a testing machine's.
TestRecord fem_record(const result::SimulationResult& sim, const std::string& tag) {
  SyntheticRecordOptions so;
  so.crack_reading_interval = 2;
  so.seed = 5;
  const std::string path =
      ::testing::TempDir() + "fb_" + std::to_string(::getpid()) + "_" + tag + ".csv";
  write_test_record_csv(path, make_synthetic_record(sim, so, "fem"),
                        describe_synthetic_record(sim, so));
  auto rec = read_test_records(path).at(0);
  std::remove(path.c_str());
  return rec;
}
} // namespace

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
  const auto rec = fem_record(sim, "fem");
  auto sp = specimen::Specimen::unknown();
  sp.width = s.width;
  sp.height = s.height;
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

// End blocks (mesh/dcb_specimen.geo, 12.7 x 10 mm rounded to 13.6 mm, of the arm's material) on
// an LEFM composite at J_tip 500: the record of the blocked FEM, reduced. R by direct energy,
// dD/(B da), needs no block correction (the blocks store no energy that changes with a), so it
// must recover J_tip as on plain arms. ASTM D5528's N assumes rigid blocks; these are not (they
// take 57 % of a rigid block's compliance, docs/verification.md "Specimen meshes from Gmsh"), so
// MBT with N reads high near the notch (printed; docs/verification.md).
TEST(RecordFromFem, EndBlocksNeedNoCorrectionForDirectEnergy) {
  const specimen::Specimen s = thin_dcb_case::specimen();
  fem::FemParameters prm;
  prm.steady_state.window = 1.0; // the whole ligament
  prm.mesh.file = std::string(FIBERBRIDGE_SOURCE_DIR) + "/mesh/dcb_specimen.geo";
  prm.mesh.file_parameters = "block_length: 12.7, block_height: 10";
  constexpr double j_tip = 500;
  auto sim = fem::simulate_dcb(s, thin_dcb_case::material(), law::NoBridgingLaw(), j_tip, prm);
  sim.rcurve.resize(thin_dcb_case::rising_part(sim).rcurve.size());
  const auto rec = fem_record(sim, "blk");
  auto sp = specimen::Specimen::unknown();
  sp.width = s.width;
  sp.height = s.height;
  const auto plain = reduce_record(rec, sp);
  sp.pin_to_block_edge = 7 * s.initial_crack / 18; // l2: the block's 7 elements of a0 / 18
  sp.pin_to_arm_midplane = 1e-6; // the load acts on the end face, not on a pin above the arm
  const auto with_n = reduce_record(rec, sp);
  std::vector<double> rel;
  std::printf("  a_mm R_energy R_MBT R_MBT_with_N\n");
  for (std::size_t i = 0; i < plain.a.size(); ++i) {
    if (plain.a[i] - plain.a0 < plain.window / 2 || plain.a.back() - plain.a[i] < plain.window / 2)
      continue;
    rel.push_back(std::abs(plain.R_energy[i] / j_tip - 1));
    if (i % 5 == 0)
      std::printf("  %.1f %.1f %.1f %.1f\n", plain.a[i] / mm, plain.R_energy[i], plain.R_MBT[i],
                  with_n.R_MBT[i]);
  }
  ASSERT_GT(rel.size(), 30u);
  std::sort(rel.begin(), rel.end());
  // The plain-arm twin above measures median 2.05 % at 1 mm elements and 3.1 % at 1.5 mm, from
  // the FEM's one-element advances; here (1.94 mm, LEFM) median 0.4 %, max 1.6 %. Bounds: the
  // plain twin's at 1.5 mm (3 %, and its 90th percentile 6 % for the largest row).
  std::printf("direct energy vs J_tip: median %.4f, max %.4f\n", rel[rel.size() / 2], rel.back());
  EXPECT_LT(rel[rel.size() / 2], 0.03);
  EXPECT_LT(rel.back(), 0.06);
}
