// Data preparation (docs/design.md section 1): reading measured R curves, synthetic replicates,
// averaging, and the steady-state criterion of steady_state.h.
#include "fiberbridge/analysis/rdelta_data.h"
#include "fiberbridge/analysis/steady_state.h"
#include "fiberbridge/analysis/synthetic_data.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/units.h"
#include "fiberbridge/law/piecewise_linear_law.h"
#include "fiberbridge/law/seed_laws.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <unistd.h>

using namespace fiberbridge;
using namespace fiberbridge::analysis;
using units::kPa;
using units::mm;

namespace {

law::TrilinearParameters pva_control() {
  return law::seed_control_law("PVA");
}

/// A file in the test's temporary directory, removed when the object goes.
class TempFile {
public:
  TempFile(const std::string& name, const std::string& content)
      : path_(::testing::TempDir() + "fb_" + std::to_string(::getpid()) + "_" + name) {
    std::ofstream(path_) << content;
  }
  explicit TempFile(const std::string& name)
      : path_(::testing::TempDir() + "fb_" + std::to_string(::getpid()) + "_" + name) {}
  ~TempFile() { std::remove(path_.c_str()); }
  const std::string& path() const { return path_; }

private:
  std::string path_;
};

/// Ten valid rows of one replicate, as CSV lines after a header.
std::string rows(const std::string& label, int first_time = 0) {
  std::string s;
  for (int i = 0; i < 10; ++i)
    s += label + "," + std::to_string(first_time + i) + "," + std::to_string(0.5 * i) + "," +
         std::to_string(200 + 50 * i) + "\n";
  return s;
}

/// Expects `f` to throw E with a message containing every string in `parts`.
template <class E, class F>
void expect_error(F f, const std::vector<std::string>& parts) {
  try {
    f();
    ADD_FAILURE() << "no exception; expected one mentioning " << parts.front();
  } catch (const E& e) {
    for (const auto& p : parts)
      EXPECT_NE(std::string(e.what()).find(p), std::string::npos)
          << "message '" << e.what() << "' lacks '" << p << "'";
  }
}

RDeltaCurve eq2_curve(const law::TractionLaw& law, int m, double delta_end) {
  RDeltaCurve c;
  for (int i = 0; i <= m; ++i) {
    c.delta.push_back(delta_end * i / m);
    c.R.push_back(law::r_curve_eq2(law, 200, c.delta.back()));
  }
  c.R_std.assign(c.delta.size(), 0.0);
  return c;
}

} // namespace

// ---------------------------------------------------------------- reading

TEST(RDeltaRead, SplitsReplicatesSortsByTimeAndConvertsUnits) {
  // Replicate B's rows are given out of time order: they must come back sorted by time_s.
  std::string b = rows("B", 100);
  const auto cut = b.find('\n', b.size() / 2) + 1;
  b = b.substr(cut) + b.substr(0, cut);
  TempFile f("read_ok.csv", "# comment line\nreplicate,time_s,delta_mm,R_J_m2\n" + rows("A") + b);
  const auto data = read_rdelta_csv(f.path());
  EXPECT_EQ(data.source, f.path());
  ASSERT_EQ(data.replicates.size(), 2u);
  EXPECT_EQ(data.replicates[0].label, "A");
  EXPECT_EQ(data.replicates[1].label, "B");
  const auto& r = data.replicates[1];
  ASSERT_EQ(r.delta.size(), 10u);
  for (std::size_t i = 0; i < 10; ++i) {
    EXPECT_DOUBLE_EQ(r.time_s[i], 100.0 + i);
    EXPECT_DOUBLE_EQ(r.delta[i], 0.5 * i * mm);
    EXPECT_DOUBLE_EQ(r.R[i], 200.0 + 50 * i);
  }
  // Line numbers point at the file: line 1 comment, 2 header, A on 3..12, B on 13..22.
  EXPECT_EQ(data.replicates[0].line.front(), 3u);
  EXPECT_TRUE(r.a.empty());
}

TEST(RDeltaRead, WithoutReplicateOrTimeColumnsReadsOneReplicateInFileOrder) {
  std::string text = "a_mm,delta_mm,R_J_m2\n";
  for (int i = 0; i < 8; ++i)
    text += std::to_string(100 + i) + "," + std::to_string(0.1 * i) + ",300\n";
  TempFile f("one.csv", text);
  const auto data = read_rdelta_csv(f.path());
  ASSERT_EQ(data.replicates.size(), 1u);
  EXPECT_EQ(data.replicates[0].label, "1");
  EXPECT_TRUE(data.replicates[0].time_s.empty());
  EXPECT_DOUBLE_EQ(data.replicates[0].a[7], 107 * mm);
}

TEST(RDeltaRead, BadInputNamesFileAndLine) {
  const std::string header = "replicate,time_s,delta_mm,R_J_m2\n";
  const auto check = [&](const std::string& name, const std::string& text,
                         const std::vector<std::string>& parts) {
    TempFile f(name, text);
    std::vector<std::string> all = parts;
    all.insert(all.begin(), f.path());
    expect_error<InputError>([&] { read_rdelta_csv(f.path()); }, all);
  };
  // Missing required column.
  check("missing.csv", "replicate,time_s,delta_mm\n1,0,0.1\n", {"missing", "R_J_m2"});
  // Non-number and NaN: header on line 1, so row i of replicate A is on line 2 + i.
  std::string t = rows("A");
  check("nonnumber.csv", header + t.substr(0, t.find('\n') + 1) + "A,1,abc,250\n" + rows("B"),
        {":3:", "delta_mm", "abc"});
  check("nan.csv", header + t.substr(0, t.find('\n') + 1) + "A,1,0.5,nan\n" + rows("B"),
        {":3:", "R_J_m2"});
  check("negdelta.csv", header + "A,0,-0.1,200\n" + rows("B"), {":2:", "negative", "delta_mm"});
  check("negR.csv", header + "A,0,0.1,-5\n" + rows("B"), {":2:", "negative", "R_J_m2"});
  // delta decreasing in time order: the row with time 3 (line 5) opens less than time 2.
  std::string dec = header;
  for (int i = 0; i < 10; ++i)
    dec += "A," + std::to_string(i) + "," +
           (i == 3 ? std::string("0.1") : std::to_string(0.5 * i)) + ",300\n";
  check("decreasing.csv", dec, {":5:", "must not decrease", "line 4"});
  // Too few rows in one replicate.
  check("few.csv", header + rows("A") + "B,0,0.1,200\nB,1,0.2,210\n", {"'B'", "2 rows", "8"});
  check("emptylabel.csv", header + rows("A") + ",0,0.1,200\n", {":12:", "replicate"});
  expect_error<InputError>([] { read_rdelta_csv("/nonexistent/dir/x.csv"); },
                           {"/nonexistent/dir/x.csv"});
}

// ---------------------------------------------------------------- synthetic data

TEST(SyntheticData, IsReproducibleMonotoneAndSurvivesAFileRoundTrip) {
  const auto law = law::make_trilinear(pva_control());
  const auto a = make_synthetic_rdelta(law, 200, 3, 50, 10, 8 * mm, 42);
  const auto b = make_synthetic_rdelta(law, 200, 3, 50, 10, 8 * mm, 42);
  const auto c = make_synthetic_rdelta(law, 200, 3, 50, 10, 8 * mm, 43);
  ASSERT_EQ(a.replicates.size(), 3u);
  EXPECT_EQ(a.replicates[2].R, b.replicates[2].R) << "same seed, same data";
  EXPECT_NE(a.replicates[2].R, c.replicates[2].R) << "another seed, other data";
  for (const auto& r : a.replicates) {
    ASSERT_EQ(r.delta.size(), 50u);
    EXPECT_EQ(r.delta.front(), 0.0);
    // The shortest possible replicate reaches 0.95 delta_max (see synthetic_data.h).
    EXPECT_GE(r.delta.back(), 0.95 * 8 * mm);
    EXPECT_LE(r.delta.back(), 8 * mm);
    for (std::size_t i = 1; i < r.delta.size(); ++i) {
      EXPECT_GT(r.delta[i], r.delta[i - 1]);
      EXPECT_GT(r.time_s[i], r.time_s[i - 1]);
    }
  }
  TempFile f("synthetic.csv");
  const auto comments = describe_synthetic_rdelta(law, 200, 3, 50, 10, 8 * mm, 42);
  ASSERT_FALSE(comments.empty());
  EXPECT_NE(comments[0].find("SYNTHETIC"), std::string::npos) << comments[0];
  EXPECT_NE(comments[0].find("0.1:661"), std::string::npos) << comments[0];
  EXPECT_NE(comments.back().find("seed 42"), std::string::npos) << comments.back();
  write_rdelta_csv(f.path(), a, comments);
  const auto back = read_rdelta_csv(f.path());
  ASSERT_EQ(back.replicates.size(), 3u);
  for (std::size_t r = 0; r < 3; ++r) {
    EXPECT_EQ(back.replicates[r].label, a.replicates[r].label);
    ASSERT_EQ(back.replicates[r].R.size(), a.replicates[r].R.size());
    for (std::size_t i = 0; i < a.replicates[r].R.size(); ++i) {
      // 12 significant digits are written: relative 1e-11 covers the last-digit rounding.
      EXPECT_NEAR(back.replicates[r].R[i], a.replicates[r].R[i], 1e-11 * a.replicates[r].R[i]);
      EXPECT_NEAR(back.replicates[r].delta[i], a.replicates[r].delta[i], 1e-11 * 8 * mm);
    }
  }
  std::ifstream in(f.path());
  std::string first;
  std::getline(in, first);
  EXPECT_EQ(first, "# " + comments[0]);
}

TEST(SyntheticData, RejectsARangeWithoutPlateau) {
  const auto law = law::make_trilinear(pva_control());
  EXPECT_THROW(make_synthetic_rdelta(law, 200, 3, 50, 10, 6 * mm, 1), InputError);
  EXPECT_THROW(make_synthetic_rdelta(law, 200, 0, 50, 10, 8 * mm, 1), InputError);
  EXPECT_THROW(make_synthetic_rdelta(law, 200, 3, 7, 10, 8 * mm, 1), InputError);
  EXPECT_THROW(make_synthetic_rdelta(law, 200, 3, 50, -1, 8 * mm, 1), InputError);
}

// ---------------------------------------------------------------- averaging

TEST(AverageReplicates, MeanAndSampleStdOfLinearReplicatesAreExact) {
  // Two replicates R = 200 + 100 x and R = 300 + 100 x (x in mm), sampled at different openings:
  // linear interpolation is exact, so the mean is 250 + 100 x and the sample std 50 sqrt(2)
  // everywhere above both first openings (round-off tolerance 1e-9 J/m^2).
  RDeltaData data;
  data.source = "memory";
  for (int r = 0; r < 2; ++r) {
    Replicate rep;
    rep.label = std::to_string(r + 1);
    const double end = r == 0 ? 5.0 : 4.0, first = r == 0 ? 0.0 : 0.3;
    for (int i = 0; i <= 9; ++i) {
      const double x = first + (end - first) * i / 9;
      rep.delta.push_back(x * mm);
      rep.R.push_back(200 + 100 * r + 100 * x);
    }
    data.replicates.push_back(rep);
  }
  const auto c = average_replicates(data, 41);
  EXPECT_EQ(c.n_replicates, 2);
  ASSERT_EQ(c.delta.size(), 41u);
  EXPECT_DOUBLE_EQ(c.delta.back(), 4 * mm) << "the grid ends at the smallest largest delta";
  for (std::size_t i = 0; i < c.delta.size(); ++i) {
    const double x = c.delta[i] / mm;
    // Below replicate 2's first opening (0.3 mm) it is held at its first R = 330.
    const double r2 = x < 0.3 ? 330 : 300 + 100 * x;
    EXPECT_NEAR(c.R[i], 0.5 * (200 + 100 * x + r2), 1e-9) << "x " << x;
    EXPECT_NEAR(c.R_std[i], std::abs(r2 - 200 - 100 * x) / std::sqrt(2.0), 1e-9) << "x " << x;
  }
  EXPECT_NE(c.report.find("2 replicate"), std::string::npos) << c.report;
}

TEST(AverageReplicates, RepeatedOpeningsAreMergedIntoTheirMeanR) {
  // A notch root that does not open while R is recorded (repeated delta) must not make the
  // polyline multivalued: the repeated openings count with their mean R (exact arithmetic).
  RDeltaData data;
  data.source = "memory";
  Replicate rep;
  rep.label = "1";
  rep.delta = {0, 0, 0, 1 * mm, 2 * mm, 2 * mm, 3 * mm, 4 * mm};
  rep.R = {200, 210, 220, 300, 390, 410, 500, 600};
  data.replicates.push_back(rep);
  const auto c = average_replicates(data, 9); // grid step 0.5 mm
  EXPECT_DOUBLE_EQ(c.R[0], 210);
  EXPECT_DOUBLE_EQ(c.R[1], 255);
  EXPECT_DOUBLE_EQ(c.R[4], 400);
  EXPECT_DOUBLE_EQ(c.R[5], 450);
  EXPECT_DOUBLE_EQ(c.R[8], 600);
}

// ---------------------------------------------------------------- steady state

TEST(SteadyState, CleanPvaCurveGivesExactGssAndDeltaC) {
  // Eq. 2 of the PVA control law to 8 mm on 401 points. G_ss = J_tip + J_c exactly (the tail is
  // the plateau); delta_c: R is linear on (d2, dc), so the branch line fitted between
  // G_ss - 20 % and G_ss - 5 % G_B (R from 906 to 1038 J/m^2, all on that segment) extended to
  // G_ss is exact up to round-off (tolerance 1e-9 mm).
  const auto law = law::make_trilinear(pva_control());
  const auto c = eq2_curve(law, 400, 8 * mm);
  const auto ss = find_steady_state(c, {}, "clean.csv");
  EXPECT_NEAR(ss.G_ss, 200 + law.area(), 1e-9);
  EXPECT_NEAR(ss.delta_c, 6 * mm, 1e-9 * mm);
  EXPECT_TRUE(ss.delta_c_automatic);
  EXPECT_TRUE(ss.j_tip_automatic);
  // J_tip: R is flat (= 200) up to d1 = 0.1 mm and linear from there to d2 = 1 mm, so the hinge
  // fit over the first 5 % of the range (0.4 mm) is exact up to round-off. (The earlier criterion,
  // the mean over 2 % of the range, read 202.68 here: it averaged rising points past d1.)
  EXPECT_NEAR(ss.j_tip, 200, 1e-9);
  EXPECT_NE(ss.criterion.find("delta_c = 6 mm"), std::string::npos) << ss.criterion;
}

TEST(SteadyState, NoisyReplicatesRecoverJtipGssDeltaC) {
  // 6 replicates of 400 points, noise 20 J/m^2 on R, 2 % J_tip scatter between replicates,
  // averaged on 401 points. Monte Carlo over 200 seeds (this chain, PVA control law):
  //   J_tip 199.17 +- 4.22 (hinge fit over 5 % of the range: bias -0.8; the spread: J_tip
  //   scatter 200*0.02/sqrt(6) = 1.6 and the noise on the few flat points plus the fitted rise),
  //   G_ss 1082.14 +- 1.87 (truth 1082.15), delta_c 6.011 +- 0.029 mm.
  // Tolerances: |bias| + 5 sigma, so a failure means a real change, not bad luck:
  //   J_tip 0.8 + 21.1 = 22 J/m^2, G_ss 9.5 J/m^2, delta_c 0.011 + 0.15 = 0.16 mm (2.7 %).
  const auto law = law::make_trilinear(pva_control());
  for (unsigned seed = 1; seed <= 10; ++seed) {
    const auto data = make_synthetic_rdelta(law, 200, 6, 400, 20, 8 * mm, seed);
    const auto ss = find_steady_state(average_replicates(data), {}, data.source);
    EXPECT_NEAR(ss.j_tip, 200, 22) << "seed " << seed;
    EXPECT_NEAR(ss.G_ss, 200 + law.area(), 9.5) << "seed " << seed;
    EXPECT_NEAR(ss.delta_c, 6 * mm, 0.16 * mm) << "seed " << seed;
  }
}

TEST(SteadyState, AutomaticJtipHasNoWindowBias) {
  // The flat start of Eq. 2 is 0.1 mm (d1) whatever the range measured: on a 20 mm record the
  // old 2 % mean (0.4 mm) averaged R up to 107 J/m^2 above J_tip. The hinge fit stays exact.
  const auto pva = law::make_trilinear(pva_control());
  const auto wide = eq2_curve(pva, 1000, 20 * mm);
  EXPECT_NEAR(find_steady_state(wide, {}, "wide.csv").j_tip, 200, 1e-9);
  // A rigid law has no flat start (R rises from delta = 0 at s_c/2): the hinge sits on the first
  // point and the line through the rise, extrapolated to delta = 0, gives J_tip exactly.
  const auto linear = law::make_linear_softening(1000 * kPa, 2 * mm);
  const auto c = eq2_curve(linear, 400, 4 * mm);
  EXPECT_NEAR(find_steady_state(c, {}, "rigid.csv").j_tip, 200, 1e-9);
}

TEST(SteadyState, UserValuesOverrideAndAreChecked) {
  const auto law = law::make_trilinear(pva_control());
  const auto c = eq2_curve(law, 400, 8 * mm);
  SteadyStateOptions o;
  o.delta_c = 5.5 * mm;
  o.j_tip = 190;
  const auto ss = find_steady_state(c, o, "user.csv");
  EXPECT_EQ(ss.delta_c, 5.5 * mm);
  EXPECT_EQ(ss.j_tip, 190);
  EXPECT_FALSE(ss.delta_c_automatic);
  EXPECT_FALSE(ss.j_tip_automatic);
  EXPECT_NEAR(ss.G_ss, 200 + law.area(), 1e-9) << "the flat tail still gives G_ss";

  o = {};
  o.delta_c = 9 * mm;
  expect_error<InputError>([&] { find_steady_state(c, o, "user.csv"); },
                           {"user.csv", "outside the data"});
  o = {};
  o.j_tip = 1100; // above G_ss = 1082
  expect_error<InputError>([&] { find_steady_state(c, o, "user.csv"); }, {"user.csv", "J_tip"});
}

TEST(SteadyState, RisingTailIsNoSteadyState) {
  // Data stopping at 5 mm, before delta_c = 6 mm: the tail still rises at 112 J/m^2 per mm,
  // 0.2 * 5 mm * 112 = 112 J/m^2 over the tail against a band of 2 % G_B ~ 11 J/m^2.
  const auto law = law::make_trilinear(pva_control());
  const auto c = eq2_curve(law, 400, 5 * mm);
  expect_error<ComputationError>([&] { find_steady_state(c, {}, "short.csv"); },
                                 {"no steady state", "short.csv"});
  // A user delta_c inside the data still works: G_ss is then R(delta_c) (stated).
  SteadyStateOptions o;
  o.delta_c = 4.5 * mm;
  const auto ss = find_steady_state(c, o, "short.csv");
  EXPECT_NEAR(ss.G_ss, law::r_curve_eq2(law, 200, 4.5 * mm), 1e-9);
  EXPECT_NE(ss.criterion.find("not flat"), std::string::npos) << ss.criterion;
  // ... unless R(delta_c) exceeds J_tip: delta_c = 0.05 mm is below d1, where R = 200 J/m^2
  // equals the automatic J_tip (exact here: the 2 % window, 0.1 mm, lies below d1).
  o.delta_c = 0.05 * mm;
  expect_error<InputError>([&] { find_steady_state(c, o, "short.csv"); },
                           {"short.csv", "R(delta_c)"});
}

TEST(SteadyState, FallingTailIsTheSpecimensEndEffect) {
  // The clean PVA curve to 8 mm, then R falling by 60 J/m^2 per mm over its last 1.2 mm (a zone
  // meeting the specimen's far end: the tip reading runs ahead of the work done; seed Eq. 2
  // never falls). The fall is 72 J/m^2 over the last 20 % (1.6 mm) against a band of 2 % G_B
  // (~18 J/m^2): the tail is moved back to the last flat stretch, G_ss is read there, and the
  // flag says so (Fit/Model correction = auto then takes a model that holds the far end).
  const auto law = law::make_trilinear(pva_control());
  auto c = eq2_curve(law, 400, 8 * mm);
  for (std::size_t i = 0; i < c.delta.size(); ++i)
    if (c.delta[i] > 6.8 * mm)
      c.R[i] -= 60 * (c.delta[i] - 6.8 * mm) / mm;
  const auto ss = find_steady_state(c, {}, "falling.csv");
  EXPECT_TRUE(ss.end_effect);
  EXPECT_NE(ss.criterion.find("end effect"), std::string::npos) << ss.criterion;
  // The last flat stretch holds part of the fall (the same width as the tail, moved back until
  // its fitted change is inside the band), so G_ss reads a little low: bounded by the fall over
  // the stretch's overlap with it, 60 J/m^2 per mm over at most 0.5 mm.
  EXPECT_LE(ss.G_ss, 200 + law.area() + 1e-9);
  EXPECT_GT(ss.G_ss, 200 + law.area() - 30);
  // The clean curve is no end effect.
  EXPECT_FALSE(find_steady_state(eq2_curve(law, 400, 8 * mm), {}, "clean.csv").end_effect);
}
