// Identification of the bridging law from test records (include/fiberbridge/identify/identify.h).
#include "../common/elastica.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/units.h"
#include "fiberbridge/identify/identify.h"
// The private job codec (source/identify/jobs.h), for its round trip.
#include "../../source/identify/jobs.h"
#include "record_specimen.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

using namespace fiberbridge;
using namespace fiberbridge::identify;
using identify::testing::record_material;
using identify::testing::record_specimen;
using units::mm;

namespace {

analysis::TestRecord shared_record(const std::string& name) {
  analysis::RecordReadOptions o;
  o.columns = analysis::RecordColumnMap::parse(
      "time_s: Time, opening_mm: Disp, load_N: Force, a_mm: CrackExt", "test");
  return analysis::read_test_records(
             std::string(FIBERBRIDGE_DATA_DIR) + "/dcb_records/" + name + "_Toughness.csv", o)
      .at(0);
}

} // namespace

// One test per shared record, so that ctest -j runs them side by side (each is 10-40 s with the
// default settings; as one test the four took ~200 s in ctest).
class IdentifySharedRecord : public ::testing::TestWithParam<const char*> {};

TEST_P(IdentifySharedRecord, ReproducesTheLoadCurve) {
  const char* name = GetParam();
  const auto rec = shared_record(name);
  IdentifySettings s;
  const auto id = identify_law({rec}, record_specimen(), record_material(19.3e9), s,
                               [](const std::string& l) { std::printf("%s\n", l.c_str()); });
  std::printf("%s: E_L %.4g GPa, d1 %.4g mm s1 %.4g kPa d2 %.4g mm s2 %.4g kPa dc %.4g mm "
              "J_tip %.4g G_ss %.4g | load rms %.4g %% crack rms %.4g mm | %d evals, %d runs, "
              "%.3g s (forward %.3g s)\n",
              name, id.records[0].E_L * 1e-9, id.law.d1 / mm, id.law.s1 / 1e3, id.law.d2 / mm,
              id.law.s2 / 1e3, id.law.dc / mm, id.j_tip, id.g_ss, 100 * id.load_rms_rel,
              id.crack_rms / mm, id.evaluations, id.forward_runs, id.wall_time_s,
              id.forward_time_s);
  for (const auto& p : id.parameters)
    std::printf("  %s = %.4g +- %.3g\n", p.name.c_str(), p.value, p.std_error);
  for (const auto& n : id.notes)
    std::printf("  note: %s\n", n.c_str());
  // "Reproduces the measured load-opening curve": the RMS load misfit stays under 4 % of the
  // peak (measured 1.3-3.1 %, docs/verification.md), well below the 9 % spread of the four
  // replicates' peak loads (91-100 N), so the law describes each record better than the
  // replicates describe each other.
  EXPECT_LT(id.load_rms_rel, 0.04) << name;
  // Crack readings: optical tracking steps of 1-5 mm (DCB-03's readings lag by up to ~10 mm
  // at the end); RMS under 6 mm.
  EXPECT_LT(id.crack_rms, 6 * mm) << name;
  // The identified law must carry most of the toughness rise the records show (G_I column
  // about 1 kJ/m^2 at the end): G_ss between 700 and 1500 J/m^2.
  EXPECT_GT(id.g_ss, 700) << name;
  EXPECT_LT(id.g_ss, 1500) << name;
}

INSTANTIATE_TEST_SUITE_P(Identify, IdentifySharedRecord,
                         ::testing::Values("DCB-01", "DCB-02", "DCB-03", "DCB-05"),
                         [](const ::testing::TestParamInfo<const char*>& info) {
                           std::string n = info.param;
                           n.erase(std::remove(n.begin(), n.end(), '-'), n.end());
                           return n;
                         });

TEST(Identify, BadSettingsNameTheKey) {
  auto message = [](IdentifySettings s) {
    try {
      s.validate("Identify");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  IdentifySettings s;
  s.delta_c_max = s.delta_c_min / 2;
  EXPECT_NE(message(s).find("Identify/Delta c range"), std::string::npos) << message(s);
  s = {};
  s.algorithm = "newton";
  EXPECT_NE(message(s).find("Identify/Algorithm"), std::string::npos) << message(s);
  s = {};
  s.load_scatter = 0;
  EXPECT_NE(message(s).find("Identify/Load scatter"), std::string::npos) << message(s);
  s = {};
  s.compliance_high = 0.05;
  EXPECT_NE(message(s).find("Identify/Compliance window"), std::string::npos) << message(s);
}

TEST(Identify, ModulusFromComplianceInvertsCbt) {
  // The calibration inverts corrected beam theory, which the beam model reproduces: the beam's
  // initiation state has the CBT compliance of the calibrated modulus to 0.5 % (measured 0.15 %
  // here; the beam's tip lumping is O(h_e^2), 0.23 % at 400 elements, include/.../dcb_beam.h).
  auto s = record_specimen();
  const auto m = record_material(19.3e9);
  const double c = 0.037 * mm; // DCB-01's initial compliance, m/N
  specimen::Material cal = m;
  cal.E_L = modulus_for_compliance(s, m, c);
  EXPECT_NEAR(specimen::cbt_opening(s, cal, 1.0, s.initial_crack) / c, 1.0, 1e-9);
  const auto law = law::make_trilinear({0.05 * mm, 700e3, 1.5 * mm, 100e3, 4 * mm});
  beam::BeamParameters bp;
  bp.final_crack_length = s.initial_crack + 2 * mm;
  const auto run = beam::simulate_dcb(s, cal, law, 400, bp);
  const auto& first = run.rcurve.front();
  EXPECT_NEAR(first.load_point_opening / first.load / c, 1.0, 5e-3);
}

TEST(Identify, LargeDisplacementMappingMatchesTheElastica) {
  // identify's forward beam is geometrically linear; with_large_displacements maps each of its
  // states onto arms that rotate far (the same G at the same crack length). Checked against the
  // exact elastica DCB (tests/common/elastica.h), loaded on the mid-plane (l1 -> 0: an arm
  // thickness of 1 nm passed to the mapping; the stiffness EI below is the real arm's): states
  // of a linear LEFM DCB at R = 1000 J/m^2 from a = 40 to 120 mm (delta/a up to 0.44) should
  // land on the elastica's P and delta at the same a. F and N are right to O((delta/a)^4):
  // measured worst 0.03 %; 0.5 % bounds it with room for other loadings, and the unmapped
  // linear states are 3.0 % off at delta/a = 0.44 (checked to be out of the bound).
  const double B = 25 * mm, h = 2.7 * mm, E = 19.3e9, EI = E * B * h * h * h / 12, R = 1000;
  result::SimulationResult run;
  for (double a = 40 * mm; a <= 120 * mm + 1e-9; a += 5 * mm) {
    result::RCurvePoint p;
    p.a = a;
    p.load = std::sqrt(R * B * EI) / a; // linear DCB: G = P^2 a^2 / (B EI)
    p.load_point_opening = 2 * p.load * a * a * a / (3 * EI);
    run.rcurve.push_back(p);
  }
  const result::SimulationResult linear = run;
  with_large_displacements(run, 1e-9);
  double worst = 0, worst_linear = 0, largest = 0;
  for (std::size_t i = 0; i < run.rcurve.size(); ++i) {
    const double a = run.rcurve[i].a;
    const auto e = exact::elastica_at_G(R, EI, a, B);
    const double P = e.p * EI / (a * a), d = 2 * e.deflection * a;
    largest = std::max(largest, d / a);
    worst = std::max({worst, std::abs(run.rcurve[i].load / P - 1),
                      std::abs(run.rcurve[i].load_point_opening / d - 1)});
    worst_linear = std::max({worst_linear, std::abs(linear.rcurve[i].load / P - 1),
                             std::abs(linear.rcurve[i].load_point_opening / d - 1)});
  }
  std::printf("mapped linear DCB against the elastica to delta/a = %.3f: worst %.5f (unmapped "
              "%.4f)\n",
              largest, worst, worst_linear);
  EXPECT_GT(largest, 0.4);
  EXPECT_LT(worst, 0.005);
  EXPECT_GT(worst_linear, 0.02) << "the case must reach large displacements";
}

// The job runner (issue 16 section 2): the app runs identify's independent jobs on any rank in
// any order; the identification must not depend on it. A runner that runs each batch backwards
// (and records the batches) gives the serial result bit for bit.
TEST(Identify, JobRunnerOrderDoesNotChangeTheResult) {
  const auto rec = shared_record("DCB-05");
  IdentifySettings s;
  s.starts = 3;
  s.max_evaluations = 20;
  s.relative_tolerance = 1e-2;
  s.beam.n_elements = 40;
  s.beam.tip_advance = 2 * mm;
  const auto serial = identify_law({rec}, record_specimen(), record_material(19.3e9), s);
  std::vector<std::pair<std::string, std::size_t>> batches;
  const IdentifyJobRunner backwards = [&](const std::string& what, std::size_t n,
                                          const IdentifyJob& job) {
    batches.emplace_back(what, n);
    std::vector<std::string> out(n);
    for (std::size_t i = n; i-- > 0;)
      out[i] = job(i);
    return out;
  };
  const auto other =
      identify_law({rec}, record_specimen(), record_material(19.3e9), s, {}, backwards);
  ASSERT_GE(batches.size(), 3u);
  EXPECT_EQ(batches.front(), std::make_pair(std::string("starts"), std::size_t(3)));
  EXPECT_EQ(batches.back(), std::make_pair(std::string("jacobian"), std::size_t(13)));
  for (std::size_t b = 1; b + 1 < batches.size(); ++b)
    EXPECT_EQ(batches[b], std::make_pair(std::string("polish"), std::size_t(1)));
  // Bit for bit: the same doubles (memcmp, so NaN compares too), counts and notes.
  auto same = [](double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; };
  auto same_all = [](const std::vector<double>& a, const std::vector<double>& b) {
    return a.size() == b.size() &&
           (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
  };
  EXPECT_TRUE(same(serial.law.d1, other.law.d1) && same(serial.law.s1, other.law.s1) &&
              same(serial.law.d2, other.law.d2) && same(serial.law.s2, other.law.s2) &&
              same(serial.law.dc, other.law.dc) && same(serial.j_tip, other.j_tip));
  EXPECT_TRUE(same(serial.chi2, other.chi2));
  EXPECT_TRUE(same(serial.j_c_std_error, other.j_c_std_error));
  EXPECT_EQ(serial.evaluations, other.evaluations);
  EXPECT_EQ(serial.forward_runs, other.forward_runs);
  EXPECT_EQ(serial.notes, other.notes);
  ASSERT_EQ(serial.parameters.size(), other.parameters.size());
  for (std::size_t j = 0; j < serial.parameters.size(); ++j)
    EXPECT_TRUE(same(serial.parameters[j].value, other.parameters[j].value) &&
                same(serial.parameters[j].std_error, other.parameters[j].std_error))
        << serial.parameters[j].name;
  ASSERT_EQ(serial.records.size(), 1u);
  ASSERT_EQ(other.records.size(), 1u);
  EXPECT_TRUE(same_all(serial.records[0].model_load, other.records[0].model_load));
  EXPECT_TRUE(same_all(serial.records[0].model_crack_length, other.records[0].model_crack_length));
  EXPECT_TRUE(same(serial.records[0].min_F, other.records[0].min_F));
  EXPECT_TRUE(same_all(serial.band_lo, other.band_lo));
  EXPECT_TRUE(same_all(serial.band_hi, other.band_hi));
}

// identify on load and opening alone (issue 31 item 3): DCB-01 with its crack column dropped
// (a0 = its first reading, from the Specimen) against the same record with it. The load misfit
// carries the whole fit; the bound on it is the shared-record test's (4 % of the peak). Without
// readings the crack is seen only through the compliance, which trades J_tip against the law's
// rising part, while the plateau load holds G_ss. Measured (docs/verification.md, "R without
// crack readings, initiation values, step-wise readings"): G_ss 1089 against 1037 J/m^2 with
// readings (+5.0 %), J_tip 395 against 387, load RMS 1.38 % against 2.70 % (the crack no longer
// pulls the fit off the load curve). The bound of 10 % on G_ss is twice the measured difference:
// the optimizer's two starts end within a few per cent of each other on these records.
TEST(Identify, LoadAndOpeningAlone) {
  const auto rec = shared_record("DCB-01");
  analysis::TestRecord bare = rec;
  bare.crack_length.clear();
  auto sp = record_specimen();
  sp.initial_crack = rec.crack_length.front();
  IdentifySettings s;
  const auto with = identify_law({rec}, sp, record_material(19.3e9), s);
  const auto without = identify_law({bare}, sp, record_material(19.3e9), s);
  std::printf("DCB-01 with readings: J_tip %.0f G_ss %.0f J/m^2, load rms %.2f %%; without: J_tip "
              "%.0f G_ss %.0f J/m^2, load rms %.2f %%, %d evaluations, %.1f s\n",
              with.j_tip, with.g_ss, 100 * with.load_rms_rel, without.j_tip, without.g_ss,
              100 * without.load_rms_rel, without.evaluations, without.wall_time_s);
  EXPECT_EQ(without.crack_rms, 0);
  EXPECT_LT(without.load_rms_rel, 0.04);
  EXPECT_NEAR(without.g_ss / with.g_ss, 1, 0.10);
}

// identify's job results on core/binary_archive (issue 30 item 4): a record's fit and a job's run
// counts through the bytes and back, every double bit for bit (NaN crack rows included), and a
// cut result an error rather than a wrong answer.
TEST(Identify, JobBytesRoundTrip) {
  using namespace fiberbridge::identify::detail;
  RecordFit f;
  f.name = "DCB-01 (a record)";
  f.initial_crack = 35.1 * mm;
  f.initial_compliance = 0.037 * mm;
  f.E_L = 19.3e9;
  f.peak_load = 96.5;
  f.load_rms_rel = 0.0123;
  f.crack_rms = 1.7 * mm;
  f.max_opening_over_a = 0.41;
  f.min_F = 0.93;
  f.opening = {0, 0.1 * mm, 1.0 / 3.0};
  f.load = {0, 12.5, -0.0};
  f.crack_length = {35 * mm, NAN, 36 * mm};
  f.model_load = {1e-300, 5e-324, 3.0};
  f.model_crack_length = {};
  const std::vector<PreparedRecord> prepared;
  IdentifySettings settings;
  const ForwardModel forward;
  Misfit m(prepared, settings, forward);
  m.forward_runs = 17;
  m.forward_time_s = 0.1 + 0.2;
  m.last_failure = "FEM forward run: steady_state_status zone_unresolved";
  ByteWriter w;
  write_fit(w, f);
  RunCounts::write(w, m, 42);
  const std::string bytes = w.bytes();

  ByteReader r(bytes);
  const RecordFit g = read_fit(r);
  RunCounts counts;
  counts.evaluations = 1;
  counts.add(r);
  r.expect_end();
  auto same_all = [](const std::vector<double>& a, const std::vector<double>& b) {
    return a.size() == b.size() &&
           (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
  };
  EXPECT_EQ(g.name, f.name);
  for (auto [a, b] : {std::pair{g.initial_crack, f.initial_crack},
                      {g.initial_compliance, f.initial_compliance},
                      {g.E_L, f.E_L},
                      {g.peak_load, f.peak_load},
                      {g.load_rms_rel, f.load_rms_rel},
                      {g.crack_rms, f.crack_rms},
                      {g.max_opening_over_a, f.max_opening_over_a},
                      {g.min_F, f.min_F}})
    EXPECT_EQ(std::memcmp(&a, &b, sizeof a), 0);
  EXPECT_TRUE(same_all(g.opening, f.opening));
  EXPECT_TRUE(same_all(g.load, f.load)); // -0.0 keeps its sign bit
  EXPECT_TRUE(same_all(g.crack_length, f.crack_length));
  EXPECT_TRUE(same_all(g.model_load, f.model_load));
  EXPECT_TRUE(same_all(g.model_crack_length, f.model_crack_length));
  EXPECT_EQ(counts.evaluations, 43);
  EXPECT_EQ(counts.forward_runs, 17);
  EXPECT_EQ(counts.forward_time_s, m.forward_time_s);
  EXPECT_EQ(counts.last_failure, m.last_failure);

  // Cut short or damaged: an error naming the job result, never a silent value.
  EXPECT_THROW(ByteReader(bytes.substr(0, bytes.size() - 9)), InputError);
  std::string damaged = bytes;
  damaged[damaged.size() / 2] ^= 0x10;
  EXPECT_THROW(ByteReader{damaged}, InputError);
}
