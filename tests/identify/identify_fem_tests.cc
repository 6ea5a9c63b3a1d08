// Identification from synthetic records written by the FEM (issue 12 verification): a known
// trilinear law in the deal.II FEM of the shared records' specimen, the FEM's load-opening and
// crack-length-opening path sampled like a test machine by analysis::make_synthetic_record (rows
// every 0.083 mm of opening = 1 Hz at 5 mm/min, load noise, crack readings that stay stale for
// several rows then jump, with tracking noise), then identified with the beam model. The FEM and
// the beam are different discretizations of different continua (2D orthotropic solid against
// Timoshenko arms on a CBT-calibrated foundation), so the recovery is not circular.
#include "fiberbridge/analysis/law_routes.h"
#include "fiberbridge/analysis/record_reduction.h"
#include "fiberbridge/analysis/steady_state.h"
#include "fiberbridge/analysis/synthetic_record.h"
#include "fiberbridge/core/units.h"
#include "fiberbridge/fem/dcb_simulation.h"
#include "fiberbridge/identify/identify.h"
#include "record_specimen.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <unistd.h>

using namespace fiberbridge;
using identify::testing::record_material;
using identify::testing::record_specimen;
using units::kPa;
using units::mm;

TEST(IdentifyFromFem, RecoversTheLawsToughnessAndStresses) {
  // A law shaped like those identified on the shared records (docs/verification.md): J_c =
  // (s1 d2 + s2 (dc - d1))/2 = 722.5 J/m^2, G_ss = 1122.5 J/m^2.
  const law::TrilinearParameters truth{0.05 * mm, 700 * kPa, 1.5 * mm, 100 * kPa, 4 * mm};
  const double j_tip = 400;
  fem::FemParameters fp;
  fp.mesh.element_size = 0.5 * mm; // 5.4 elements per arm thickness; G_ss within 0.2 % of the law
  fp.nonlinear.max_opening_increment = 0.2 * mm;
  const auto run = fem::simulate_dcb(record_specimen(), record_material(25e9),
                                     law::make_trilinear(truth), j_tip, fp);
  ASSERT_TRUE(run.reached_steady_state);
  analysis::SyntheticRecordOptions ro;
  ro.sampling_rate_hz = 1;         // the shared records' rate: one row per 0.083 mm
  ro.load_noise = 0.5;             // N, 0.5 % of the 96 N peak
  ro.crack_reading_interval = 8;   // s: readings stale for 8 rows, then a jump
  ro.crack_reading_noise = 0.3e-3; // m
  ro.seed = 12;
  const auto rec = analysis::make_synthetic_record(run, ro, "fem_synthetic");

  identify::IdentifySettings s;
  // The FEM is geometrically linear: the large-rotation factor F must not be applied to it.
  s.large_displacement = false;
  s.load_scatter = 0.005;
  s.crack_scatter = 0.3 * mm;
  // The quoted modulus is wrong on purpose: the calibration from the initial compliance must
  // find the FEM's.
  const auto id = identify::identify_law({rec}, record_specimen(), record_material(19.3e9), s);
  std::printf("E_L %.4g GPa; d1 %.4g mm s1 %.4g kPa d2 %.4g mm s2 %.4g kPa dc %.4g mm J_tip %.4g; "
              "J_c %.4g (true %.4g); load rms %.3g %%, crack rms %.3g mm; %d evaluations, %d "
              "runs, %.3g s\n",
              id.records[0].E_L * 1e-9, id.law.d1 / mm, id.law.s1 / kPa, id.law.d2 / mm,
              id.law.s2 / kPa, id.law.dc / mm, id.j_tip, id.law.area(), truth.area(),
              100 * id.load_rms_rel, id.crack_rms / mm, id.evaluations, id.forward_runs,
              id.wall_time_s);
  for (const auto& n : id.notes)
    std::printf("  note: %s\n", n.c_str());
  // Issue 12's targets: J_c within 3 %, s1 and s2 within 10 %.
  EXPECT_NEAR(id.law.area() / truth.area(), 1.0, 0.03);
  EXPECT_NEAR(id.law.s1 / truth.s1, 1.0, 0.10);
  EXPECT_NEAR(id.law.s2 / truth.s2, 1.0, 0.10);
  // The FEM's initial compliance is that of a 2D orthotropic solid, which CBT (and the beam)
  // reproduces to a few per cent: the calibrated modulus lands within 5 % of the FEM's.
  EXPECT_NEAR(id.records[0].E_L / 25e9, 1.0, 0.05);
  // The fit reaches the noise: load RMS within 2x the 0.5 % noise.
  EXPECT_LT(id.load_rms_rel, 0.01);
}

// Issue 12, part 3, last paragraph: with a measured notch-root opening the three routes run on
// the same FEM-written record and are compared with the law the FEM was given: Eq. 5/6 and the
// old sigma = dR/d delta from R_energy(delta_root) (reduce -> R(delta_root) -> extract), and the
// identification from load, opening and crack readings only. The paper predicts Eq. 5/6 close
// to the law and dR/d delta off by the factor of seed Eq. 4, (sigma - delta sigma')/2 over
// sigma: 0.515 at this law's peak. Both extractions are also run on the FEM's own rows (no
// record, no smoothing in a), which separates the method from the record's noise.
TEST(IdentifyFromFem, ThreeRoutesWithDeltaRoot) {
  const law::TrilinearParameters truth{0.05 * mm, 700 * kPa, 1.5 * mm, 100 * kPa, 4 * mm};
  const auto truth_law = law::make_trilinear(truth);
  const double j_tip = 400;
  fem::FemParameters fp;
  fp.mesh.element_size = 0.5 * mm; // as above
  fp.nonlinear.max_opening_increment = 0.2 * mm;
  fp.steady_state.window = 30 * mm; // on past the onset: a long plateau in R(a)
  const auto run =
      fem::simulate_dcb(record_specimen(), record_material(25e9), truth_law, j_tip, fp);
  ASSERT_TRUE(run.reached_steady_state);
  analysis::SyntheticRecordOptions ro;
  ro.sampling_rate_hz = 1;
  ro.load_noise = 0.5;
  ro.crack_reading_interval = 8;
  ro.crack_reading_noise = 0.3e-3;
  ro.with_delta_root = true;
  ro.delta_root_noise = 1e-6; // a clip gauge's 1 um
  ro.seed = 21;
  // Through the file and the reader, as a user's record (the reader holds crack readings that
  // fall back within the tracking tolerance at their maximum).
  const std::string path =
      ::testing::TempDir() + "fb_" + std::to_string(::getpid()) + "_fem_delta_root.csv";
  analysis::write_test_record_csv(path, analysis::make_synthetic_record(run, ro, "fem_delta_root"),
                                  analysis::describe_synthetic_record(run, ro));
  const auto rec = analysis::read_test_records(path).at(0);
  std::remove(path.c_str());

  // The FEM reports delta_root at the initial notch root, which reads on past delta_c once the
  // root has failed, as a clip gauge does; delta_c is given as the law's (until session 31 the
  // FEM's delta_root stopped at delta_c and the data ended there; the averaging grid now spans
  // the plateau too, re-measured in docs/verification.md), and
  // G_ss is R(delta_c) (analysis/steady_state.h). Slopes over +-10 grid intervals (+-0.4 mm): the
  // record's R(delta_root) carries the direct energy's scatter, and the default +-3 (+-0.12 mm)
  // differentiates it (measured with k = 3: Eq. 6 RMS 9.4 % of the law's peak, dR/d delta's
  // peak 1.22 x the law's instead of about half).
  const int k = 10;
  auto extract = [&](const analysis::RDeltaData& data, int half_width) {
    const auto curve = analysis::average_replicates(data, 401);
    analysis::SteadyStateOptions so;
    // delta_c given, the law's (the routes are compared on the law's own range): the FEM's
    // notch-root opening runs past it once the root has failed, as a clip gauge's does.
    so.delta_c = std::min(curve.delta.back(), truth.dc);
    const auto steady = analysis::find_steady_state(curve, so, data.source);
    std::printf("%s: J_tip %.4g, G_ss %.5g (law %.5g), delta_c %.4g mm\n", data.source.c_str(),
                steady.j_tip, steady.G_ss, j_tip + truth.area(), steady.delta_c / mm);
    return analysis::extract_cohesive_laws(curve, steady.delta_c, 100, half_width);
  };
  auto print = [](const char* what, const analysis::LawRoutes& routes) {
    for (const auto& r : routes.routes)
      std::printf("%s %-10s peak %7.1f kPa at %.3f mm, area %6.1f J/m^2; against the input law: "
                  "peak x%.3f, area x%.3f, RMS %.3f of its peak\n",
                  what, r.name.c_str(), r.peak / kPa, r.delta_at_peak / mm, r.area, r.peak_ratio,
                  r.area_ratio, r.rms_rel);
  };

  // The FEM's own R_energy(delta_root) rows: the method without the record.
  analysis::RDeltaData own;
  own.source = "FEM rows";
  own.replicates.emplace_back();
  for (const auto& q : run.rcurve)
    if (std::isfinite(q.R_energy) &&
        q.delta_root > (own.replicates[0].delta.empty() ? 0.0 : own.replicates[0].delta.back())) {
      own.replicates[0].delta.push_back(q.delta_root);
      own.replicates[0].R.push_back(q.R_energy);
      own.replicates[0].a.push_back(q.a);
      own.replicates[0].line.push_back(own.replicates[0].delta.size());
    }
  const auto own_routes = analysis::compare_law_routes(extract(own, 3), truth_law, &truth_law);
  print("FEM rows", own_routes);

  // The record: direct-energy R(a) at the scene's default window, paired with delta_root.
  auto ts = specimen::Specimen::unknown();
  ts.width = record_specimen().width;
  ts.height = record_specimen().height;
  const auto reduced = analysis::reduce_record(rec, ts);
  for (const auto& note : reduced.notes) // what the start of R_energy rests on
    if (note.rfind("R at initiation", 0) == 0)
      std::printf("%s\n", note.c_str());
  const auto laws = extract(analysis::to_rdelta({reduced}, "record"), k);
  // Route 3: the identification, which does not see delta_root. One start (the test above
  // checks the identification's accuracy with the default two); here it is one of the routes.
  identify::IdentifySettings s;
  s.large_displacement = false; // the FEM is geometrically linear
  s.load_scatter = 0.005;
  s.crack_scatter = 0.3 * mm;
  s.starts = 1;
  const auto id = identify::identify_law({rec}, record_specimen(), record_material(19.3e9), s);
  std::printf("identified: E_L %.4g GPa d1 %.4g mm s1 %.4g kPa d2 %.4g mm s2 %.4g kPa dc %.4g mm "
              "J_tip %.4g; load rms %.3g %%, crack rms %.3g mm; %d evaluations, %.3g s\n",
              id.records[0].E_L * 1e-9, id.law.d1 / mm, id.law.s1 / kPa, id.law.d2 / mm,
              id.law.s2 / kPa, id.law.dc / mm, id.j_tip, 100 * id.load_rms_rel, id.crack_rms / mm,
              id.evaluations, id.wall_time_s);
  const auto routes = analysis::compare_law_routes(laws, law::make_trilinear(id.law), &truth_law);
  print("record", routes);
  std::printf("Eq. 4 predicts the old route's peak at x%.3f of the law's\n",
              routes.dRdd_peak_ratio_eq4);

  ASSERT_EQ(routes.reference, "input");
  std::map<std::string, analysis::RouteLaw> rec_route, own_route;
  for (const auto& r : routes.routes)
    rec_route[r.name] = r;
  for (const auto& r : own_routes.routes)
    own_route[r.name] = r;
  // Eq. 4 on this law: (s1 + d1 (s1 - s2)/(d2 - d1))/2 / s1 = 0.515 (exact, a check of
  // compare_law_routes).
  EXPECT_NEAR(routes.dRdd_peak_ratio_eq4, 0.5 * (1 + 0.05 * 600 / (1.45 * 700)), 1e-3);
  // TOLERANCES: measured values in docs/verification.md ("Three routes").
  // FEM rows: the paper's prediction. Measured (session 31, delta_c given): Eq. 6 RMS 1.8 % of
  // the peak (its peak 0.97 x: the d1 = 0.05 mm corner is one grid interval wide); dR/d delta
  // peak 0.544 x (Eq. 4: 0.515), RMS 16.6 %. Bounds: Eq. 6 within 4 %, dR/d delta's peak within
  // 0.05 of Eq. 4's factor.
  EXPECT_LT(own_route["eq6"].rms_rel, 0.04);
  EXPECT_NEAR(own_route["dRdd"].peak_ratio, routes.dRdd_peak_ratio_eq4, 0.05);
  EXPECT_GT(own_route["dRdd"].rms_rel, 3 * own_route["eq6"].rms_rel);
  // The record. Measured (k = 10, session 31): Eq. 6 RMS 4.9 %, peak 0.81 x (the wider slopes
  // round the peak); dR/d delta peak 0.60 x, RMS 20.3 %; identified RMS 0.8 %, J_c -1.3 %. Bounds:
  // Eq. 6 and identified RMS under 8 % (the record's scatter doubles Eq. 6's error against the FEM
  // rows), dR/d delta's peak within 0.15 of Eq. 4's factor and its RMS at least twice Eq. 6's,
  // the identified J_c within issue 12's 3 %.
  EXPECT_LT(rec_route["eq6"].rms_rel, 0.08);
  EXPECT_NEAR(rec_route["dRdd"].peak_ratio, routes.dRdd_peak_ratio_eq4, 0.15);
  EXPECT_GT(rec_route["dRdd"].rms_rel, 2 * rec_route["eq6"].rms_rel);
  EXPECT_LT(rec_route["identified"].rms_rel, 0.08);
  EXPECT_NEAR(rec_route["identified"].area_ratio, 1.0, 0.03);
}
