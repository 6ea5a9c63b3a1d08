// DIC frames to crack length and delta_root (dic/dic_analysis.h) on frames synthesized from an
// analytic DCB field with a known tip (dic_synthetic.h), written in every layout, in pixels with y
// down and with failed points; bad frames; the record handed to reduce.
#include "dic_synthetic.h"
#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/dic/dic_analysis.h"
#include "support/scratch_dirs.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using namespace fiberbridge;
using namespace fiberbridge::dic;
using fiberbridge::test::Out;
using fiberbridge::test::ScratchDirs;
using fiberbridge::test::SyntheticDcb;
namespace fs = std::filesystem;

namespace {

/// The test's history: the model tip (front of the bridging zone) at the notch root while the
/// load factor rises over 8 frames, then advancing 0.5 mm per frame at full load.
struct History {
  int frames = 40;
  double s_m(int k) const { return k < 8 ? 0.0 : 0.5e-3 * (k - 7); }
  double lambda(int k) const { return k < 8 ? (k + 1) / 8.0 : 1.0; }
};

struct Case {
  Out out;
  bool pixels, y_down;
  int growth_sign;
  std::string name_pattern; // printf pattern with the image number
};

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::path(::testing::TempDir()) / ("fb_dic_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  ScratchDirs::remove_when_passed(d);
  return d;
}

/// Writes the history's frames; returns their paths (in a scrambled order: order_frames sorts).
std::vector<std::string> write_history(const fs::path& dir, const SyntheticDcb& dcb,
                                       const History& h, const FrameGeometry& g, const Case& c) {
  std::vector<std::string> paths;
  for (int k = h.frames - 1; k >= 0; --k) {
    char name[128];
    std::snprintf(name, sizeof name, c.name_pattern.c_str(), k);
    const std::string p = (dir / name).string();
    test::write_frame(p, dcb.frame(h.s_m(k), h.lambda(k), 1000u + k), g, c.out);
    paths.push_back(p);
  }
  return paths;
}

DicOptions options_for(const FrameGeometry& g) {
  DicOptions o;
  o.geometry = g;
  o.read.pixel_coordinates = g.pixels;
  o.gauge_length = 2e-3;
  return o;
}

FrameGeometry geometry_for(const Case& c) {
  FrameGeometry g;
  g.pixels = c.pixels;
  g.pixel_size = 0.05e-3; // 20 px per mm: the grid step h = 0.5 mm is 10 px
  g.y_down = c.y_down;
  g.growth_sign = c.growth_sign;
  // Somewhere in an image (px) or a specimen coordinate system (mm).
  g.crack_plane_y = c.pixels ? 512 : 17.5;
  g.notch_root_x = c.pixels ? 1200 : 100;
  return g;
}

class DicLayouts : public ::testing::TestWithParam<Case> {};

std::string case_name(const ::testing::TestParamInfo<Case>& i) {
  const char* names[] = {"vic", "dice", "dice_space", "gom", "plain"};
  return std::string(names[static_cast<int>(i.param.out)]) + (i.param.pixels ? "_px" : "_mm") +
         (i.param.y_down ? "_ydown" : "_yup") + (i.param.growth_sign > 0 ? "_plusx" : "_minusx");
}

} // namespace

// Each layout, with pixels, y down, -x growth and failed points where the layout allows: the rule's
// tip against the DIC strain of the exact field (the crossing of plane_strain), delta_root against
// the exact opening of the material points.
TEST_P(DicLayouts, TipAndDeltaRootFromSyntheticFrames) {
  const Case c = GetParam();
  SyntheticDcb dcb;
  dcb.noise_v = 1e-6;       // 1 um: 0.02 px at 0.05 mm/px, a typical DIC displacement noise
  dcb.fail_fraction = 0.02; // 2 % of the points did not correlate
  const History hist;
  const FrameGeometry g = geometry_for(c);
  const fs::path dir = fresh_dir(std::to_string(static_cast<int>(c.out)) + "_" +
                                 std::to_string(c.pixels) + std::to_string(c.y_down));
  const auto paths = write_history(dir, dcb, hist, g, c);
  const DicOptions o = options_for(g);
  const DicAnalysis a = analyse_frames(order_frames(paths, "test"), o);
  ASSERT_EQ(a.frames.size(), static_cast<std::size_t>(hist.frames));
  // The grid step is found from the points (10 px or 0.5 mm, both 0.5 mm).
  EXPECT_NEAR(a.spacing, dcb.h, 1e-9);
  EXPECT_EQ(a.frames_used, a.frames.size());
  double s_prev = 0;
  for (int k = 0; k < hist.frames; ++k) {
    const FrameResult& f = a.frames[k];
    ASSERT_TRUE(f.used) << k << ": " << (f.notes.empty() ? "" : f.notes.front());
    const double expect = dcb.expected_rule_tip(o.tip.threshold, hist.s_m(k), hist.lambda(k));
    // Tolerance: the crossing is interpolated linearly between stations one spacing apart on a
    // curved profile (at most a fifth of a spacing for this field, whose strain is quadratic in s
    // over a few spacings), plus three of the reading's own standard deviations (noise and
    // spacing; the reading says sd, the test holds it to it).
    const double tol = 0.2 * dcb.h + 3 * f.tip.sd;
    EXPECT_NEAR(f.tip.s, expect, tol) << "frame " << k;
    EXPECT_LT(f.tip.sd, dcb.h) << "frame " << k; // a reading finer than the grid step
    EXPECT_GE(f.s_tip, s_prev) << "frame " << k; // never heals
    s_prev = f.s_tip;
    // delta_root: the two local fits of 9 noisy points each: 4 of their standard deviations,
    // plus the curvature of the exact field over the fits' 3 x 3 block (lambda A h^2 ~ 0.3 um).
    const double d_true = dcb.delta_root(o.gauge_length, hist.s_m(k), hist.lambda(k));
    const double dtol = 4 * f.extensometer.sd + dcb.A * dcb.h * dcb.h;
    EXPECT_NEAR(f.extensometer.opening, d_true, dtol) << "frame " << k;
    EXPECT_GT(f.extensometer.sd, 0);
    EXPECT_LT(f.extensometer.sd, 2e-6); // a few tenths of the 1 um noise after 9-point fits
  }
  // The rule lags the model tip (the bridging zone's front) once the crack runs: the opening at
  // the rule's tip is about threshold x effective window (docs/dic_tip_rule.md).
  const int last = hist.frames - 1;
  EXPECT_LT(a.frames[last].tip.s, hist.s_m(last));
  EXPECT_GT(a.points_failed, 0u);
}

INSTANTIATE_TEST_SUITE_P(
    Layouts, DicLayouts,
    ::testing::Values(Case{Out::vic, true, true, +1, "dcb_%04d_0.csv"},
                      Case{Out::vic, false, false, -1, "vic3d_%04d_0.csv"},
                      Case{Out::dice, true, true, +1, "DICe_solution_%d.txt"},
                      Case{Out::dice_space, true, true, -1, "DICe_solution_%03d.txt"},
                      Case{Out::gom, false, false, +1, "p_sp_123_dic_results_0_%d.txt"},
                      Case{Out::plain, false, true, +1, "frame_%d.csv"}),
    case_name);

// The plane on a row of points (no interpolation between rows) and a wider strain window: the
// rule's tip lags the model tip more, by the opening threshold x window (docs/dic_tip_rule.md).
TEST(DicTip, WiderWindowLagsMoreAndPlaneOnARow) {
  SyntheticDcb narrow, wide;
  narrow.plane_on_row = wide.plane_on_row = true;
  narrow.window = 2;
  wide.window = 5;
  const double s_m = 20e-3, lambda = 1;
  FrameGeometry g;
  DicOptions o;
  o.geometry = g;
  double tip[2];
  int i = 0;
  for (const SyntheticDcb* d : {&narrow, &wide}) {
    const fs::path dir = fresh_dir("window" + std::to_string(i));
    const std::string p = (dir / "f_1.csv").string();
    test::write_frame(p, d->frame(s_m, lambda, 7), g, Out::plain);
    const DicAnalysis a = analyse_frames(order_frames({p}, "test"), o);
    ASSERT_TRUE(a.frames[0].used);
    tip[i] = a.frames[0].tip.s;
    // Noise-free: the interpolation error alone (a fifth of a spacing, as above).
    EXPECT_NEAR(tip[i], d->expected_rule_tip(0.01, s_m, lambda), 0.2 * d->h);
    ++i;
  }
  EXPECT_LT(tip[1], tip[0] - 2 * narrow.h);
}

// Bad frames: no valid point on the plane, points moved off the plane, and an unloading whose
// threshold point falls back: notes, frames left out or the tip held, never a jump.
TEST(DicTip, BadFramesAreNotedNeverAJump) {
  SyntheticDcb dcb;
  dcb.noise_v = 0.5e-6;
  FrameGeometry g;
  DicOptions o;
  o.geometry = g;
  const fs::path dir = fresh_dir("bad");
  std::vector<std::string> paths;
  for (int k = 0; k < 6; ++k) {
    dic::PlaneFrame f = dcb.frame(10e-3 + 1e-3 * k, 1.0, 50u + k);
    if (k == 2) // every point near the plane failed
      for (std::size_t i = 0; i < f.n.size(); ++i)
        if (std::abs(f.n[i]) < 2 * dcb.h)
          f.valid[i] = 0;
    if (k == 3) // the export moved: coordinates shifted by 0.7 spacings across the plane
      for (auto& n : f.n)
        n += 0.7 * dcb.h;
    if (k == 5) // unloading: the opening falls, the threshold point moves back
      f = dcb.frame(14e-3, 0.3, 55u);
    const std::string p = (dir / ("f_" + std::to_string(k) + ".csv")).string();
    test::write_frame(p, f, g, Out::plain);
    paths.push_back(p);
  }
  const DicAnalysis a = analyse_frames(order_frames(paths, "test"), o);
  ASSERT_EQ(a.frames.size(), 6u);
  EXPECT_FALSE(a.frames[2].used);
  ASSERT_FALSE(a.frames[2].notes.empty());
  EXPECT_NE(a.frames[2].notes[0].find("no valid point on the crack plane"), std::string::npos)
      << a.frames[2].notes[0];
  EXPECT_FALSE(a.frames[3].used);
  ASSERT_FALSE(a.frames[3].notes.empty());
  EXPECT_NE(a.frames[3].notes[0].find("points moved off the crack plane"), std::string::npos)
      << a.frames[3].notes[0];
  EXPECT_TRUE(a.frames[5].used);
  EXPECT_DOUBLE_EQ(a.frames[5].s_tip, a.frames[4].s_tip); // held
  ASSERT_FALSE(a.frames[5].notes.empty());
  EXPECT_NE(a.frames[5].notes[0].find("fell back"), std::string::npos) << a.frames[5].notes[0];
  EXPECT_EQ(a.frames_used, 4u);
}

TEST(DicTip, FrameWithoutPointsNearThePlaneIsNoted) {
  SyntheticDcb dcb;
  FrameGeometry g;
  DicOptions o;
  o.geometry = g;
  const fs::path dir = fresh_dir("offplane");
  std::vector<std::string> paths;
  for (int k = 0; k < 2; ++k) {
    dic::PlaneFrame f = dcb.frame(10e-3, 1.0, 3u), cropped;
    for (std::size_t i = 0; i < f.n.size(); ++i)
      if (k == 0 || std::abs(f.n[i]) > 3e-3) {
        cropped.s.push_back(f.s[i]);
        cropped.n.push_back(f.n[i]);
        cropped.us.push_back(f.us[i]);
        cropped.vn.push_back(f.vn[i]);
        cropped.eyy.push_back(f.eyy[i]);
        cropped.valid.push_back(1);
      }
    const std::string p = (dir / ("f_" + std::to_string(k) + ".csv")).string();
    test::write_frame(p, cropped, g, Out::plain);
    paths.push_back(p);
  }
  const DicAnalysis a = analyse_frames(order_frames(paths, "test"), o);
  EXPECT_FALSE(a.frames[1].used);
  ASSERT_FALSE(a.frames[1].notes.empty());
  EXPECT_NE(a.frames[1].notes[0].find("none within 1.5 point spacings"), std::string::npos)
      << a.frames[1].notes[0];
}

TEST(DicTip, WrongCrackPlaneOrMissingColumnIsAnError) {
  SyntheticDcb dcb;
  FrameGeometry g;
  const fs::path dir = fresh_dir("wrongplane");
  const std::string p = (dir / "f_1.csv").string();
  test::write_frame(p, dcb.frame(10e-3, 1.0, 3u), g, Out::plain);
  DicOptions o;
  o.geometry = g;
  o.geometry.crack_plane_y = 30; // mm: beyond the field of view (+-8 mm)
  EXPECT_THROW(analyse_frames(order_frames({p}, "test"), o), InputError);
  const std::string q = (dir / "f_2.csv").string();
  std::ofstream(q) << "x,y,u,v\n1,2,3,4\n";
  o.geometry.crack_plane_y = 0;
  try {
    analyse_frames(order_frames({p, q}, "test"), o);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("f_2.csv:1: missing column 'eyy'"), std::string::npos)
        << e.what();
  }
}

// The hand-over: frames matched to the machine record by time, one row per frame inside its span.
TEST(DicRecord, FramesMatchedToTheMachineRecordByTime) {
  SyntheticDcb dcb;
  const History hist;
  FrameGeometry g;
  const fs::path dir = fresh_dir("record");
  std::vector<std::string> paths;
  for (int k = 0; k < 12; ++k) {
    const std::string p = (dir / ("img_" + std::to_string(k) + ".csv")).string();
    test::write_frame(p, dcb.frame(hist.s_m(k), hist.lambda(k), 9u + k), g, Out::plain);
    paths.push_back(p);
  }
  // The machine: 10 Hz from t = 0 to 9.5 s, opening 0.1 mm/s, load 10 N/s (read from files by the
  // app, as `reduce` reads records: tests/app/dic_machine_record_tests.cc).
  MachineRecord rec;
  for (int i = 0; i <= 95; ++i) {
    rec.time.push_back(0.1 * i);
    rec.opening.push_back(0.01 * i * 1e-3);
    rec.load.push_back(1.0 * i);
  }
  DicOptions o;
  o.geometry = g;
  o.clock.frame_rate = 1;
  o.clock.first_frame_time = 0.25; // the first image 0.25 s after the machine started
  const DicAnalysis a = analyse_frames(order_frames(paths, "test"), o);
  std::vector<std::string> notes;
  const auto rows = match_to_machine(a, rec, 0.1, notes);
  ASSERT_EQ(rows.size(), 10u); // frames at 0.25 ... 9.25 s; 10.25 and 11.25 s are past the record
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("2 used frame(s) outside"), std::string::npos) << notes[0];
  EXPECT_DOUBLE_EQ(rows[3].time, 3.25);
  EXPECT_NEAR(rows[3].opening, 0.1 * 3.25 * 1e-3, 1e-12);
  EXPECT_NEAR(rows[3].load, 32.5, 1e-9);
  EXPECT_DOUBLE_EQ(rows[9].a, 0.1 + a.frames[9].s_tip);
  const std::string out = (dir / "dic_record.csv").string();
  write_dic_record(out, rows, {"test"});
  const CsvTable t = CsvTable::read(out);
  EXPECT_EQ(t.n_rows(), 10u);
  EXPECT_NEAR(t.numeric("a_mm")[9], (0.1 + a.frames[9].s_tip) * 1e3, 1e-6);
  EXPECT_TRUE(t.has_column("delta_root_sd_mm"));
  // A record that ends before the first image is a clear error.
  o.clock.first_frame_time = 100;
  const DicAnalysis late = analyse_frames(order_frames(paths, "test"), o);
  EXPECT_THROW(match_to_machine(late, rec, 0.1, notes), InputError);
}

// How the rule's tip relates to the cohesive model's tip (the front of the bridging zone) and how
// that depends on the threshold and the strain window: the lag s_m - s_rule, measured on one
// noise-free frame per case, printed as the table docs/dic_tip_rule.md quotes. The physics it
// checks: the rule's tip sits where the opening is about (threshold - elastic strain) x the
// window's effective height, so the lag grows with both; with delta = lambda A d^2 behind the
// model tip, d = sqrt(opening / (lambda A)).
TEST(DicTip, RuleTipLagsTheModelTipByThresholdTimesWindow) {
  const double s_m = 25e-3, lambda = 1;
  FrameGeometry g;
  std::printf("threshold  window_points  window_mm  lag_mm  opening_at_rule_tip_um\n");
  double previous_lag_by_window[3] = {0, 0, 0};
  int t = 0;
  for (const double thr : {0.005, 0.01, 0.02}) {
    double previous = 0;
    int w = 0;
    for (const int k : {2, 4, 7}) {
      SyntheticDcb d;
      d.window = k;
      DicOptions o;
      o.geometry = g;
      o.tip.threshold = thr;
      const fs::path dir = fresh_dir("lag_" + std::to_string(t) + "_" + std::to_string(k));
      const std::string p = (dir / "f_1.csv").string();
      test::write_frame(p, d.frame(s_m, lambda, 1), g, Out::plain);
      const DicAnalysis a = analyse_frames(order_frames({p}, "test"), o);
      ASSERT_TRUE(a.frames[0].used);
      const double lag = s_m - a.frames[0].tip.s;
      const double opening = d.opening(a.frames[0].tip.s, s_m, lambda);
      std::printf("%9.3f  %13d  %9.2f  %6.3f  %22.2f\n", thr, 2 * k + 1, (2 * k + 1) * d.h * 1e3,
                  lag * 1e3, opening * 1e6);
      EXPECT_GT(lag, previous) << "a wider window lags more";
      EXPECT_GT(lag, previous_lag_by_window[w]) << "a higher threshold lags more";
      // The opening at the rule's tip is below threshold x window height (the least-squares slope
      // of a step over a window of height W is 1.5 delta / W, minus the elastic part) and above
      // a third of it.
      const double W = (2 * k + 1) * d.h;
      EXPECT_LT(opening, thr * W);
      EXPECT_GT(opening, thr * W / 3);
      previous = lag;
      previous_lag_by_window[w++] = lag;
    }
    ++t;
  }
}

// Frames are read and analysed in parallel; the tracking is sequential: one or two threads give the
// same readings, bit for bit.
TEST(DicTip, ThreadsDoNotChangeTheReadings) {
  SyntheticDcb dcb;
  dcb.noise_v = 1e-6;
  dcb.fail_fraction = 0.02;
  const History hist;
  FrameGeometry g;
  const fs::path dir = fresh_dir("threads");
  const auto paths =
      write_history(dir, dcb, hist, g, Case{Out::plain, false, false, 1, "f_%d.csv"});
  DicOptions o;
  o.geometry = g;
  o.threads = 1;
  const DicAnalysis one = analyse_frames(order_frames(paths, "test"), o);
  o.threads = 2;
  const DicAnalysis two = analyse_frames(order_frames(paths, "test"), o);
  ASSERT_EQ(one.frames.size(), two.frames.size());
  for (std::size_t k = 0; k < one.frames.size(); ++k) {
    EXPECT_EQ(one.frames[k].s_tip, two.frames[k].s_tip) << k;
    EXPECT_EQ(one.frames[k].extensometer.opening, two.frames[k].extensometer.opening) << k;
  }
}

// A specimen 3 degrees off level in the image (pixels, y down): the crack plane from two marked
// points gives the level plane's readings; the frames' eyy is taken as the crack-normal strain
// (here it is exactly: the synthetic writer rotates the coordinates and displacements only).
TEST(DicTip, TiltedCrackPlaneFromTwoMarkedPoints) {
  SyntheticDcb dcb;
  dcb.noise_v = 0.5e-6;
  FrameGeometry level;
  level.pixels = true;
  level.pixel_size = 0.05e-3;
  level.y_down = true;
  level.crack_plane_y = 500;
  level.notch_root_x = 300;
  FrameGeometry tilted = level;
  tilted.tilt = 3 * M_PI / 180;
  const fs::path dir = fresh_dir("tilted");
  const dic::PlaneFrame f = dcb.frame(20e-3, 1.0, 5);
  const std::string p = (dir / "tilted_1.csv").string(), q = (dir / "level_1.csv").string();
  test::write_frame(p, f, tilted, Out::plain);
  test::write_frame(q, f, level, Out::plain);
  DicOptions o = options_for(level);
  const DicAnalysis ref = analyse_frames(order_frames({q}, "test"), o);
  // The marked points: the root and a point 40 mm ahead on the plane, in image pixels.
  o.geometry.set_from_points(tilted.frame_x(0), tilted.frame_y(0), tilted.frame_x(40e-3),
                             tilted.frame_y(0, 40e-3), "test");
  EXPECT_NEAR(o.geometry.tilt, tilted.tilt, 1e-9);
  const DicAnalysis a = analyse_frames(order_frames({p}, "test"), o);
  ASSERT_TRUE(a.frames[0].used);
  // Same points, same values: only rounding of the written coordinates (%.8g) differs for the
  // tip; the extensometer's nearest 9 points may break distance ties differently (points at equal
  // distance from the material point), so its fits may use other points: within its own sd.
  EXPECT_NEAR(a.frames[0].tip.s, ref.frames[0].tip.s, 1e-6);
  EXPECT_NEAR(a.frames[0].extensometer.opening, ref.frames[0].extensometer.opening,
              ref.frames[0].extensometer.sd);
  // Without the marked points the plane is lost 40 mm from the root (2 mm off the assumed row).
  o.geometry = level;
  const DicAnalysis lost = analyse_frames(order_frames({p}, "test"), o);
  EXPECT_GT(std::abs(lost.frames[0].tip.s - ref.frames[0].tip.s), dcb.h);
  FrameGeometry steep;
  EXPECT_THROW(steep.set_from_points(0, 0, 10, 5, "DIC/Crack plane points"), InputError);
}

// DICe frames in pixels read without Coordinates = px (issue 42): the header's coordinates are
// taken, with the pixel size given; without it the message says the frames are in px.
TEST(DicLayoutsStated, DicePixelsWithoutTheCoordinatesOption) {
  const Case c{Out::dice, true, true, +1, "DICe_solution_%d.txt"};
  SyntheticDcb dcb;
  dcb.noise_v = 1e-6;
  const History hist;
  const FrameGeometry g = geometry_for(c);
  const fs::path dir = fresh_dir("dice_stated");
  const auto paths = write_history(dir, dcb, hist, g, c);
  DicOptions told = options_for(g);
  DicOptions untold = told;
  untold.geometry.pixels = false;
  untold.read.pixel_coordinates = false;
  const DicAnalysis a = analyse_frames(order_frames(paths, "test"), told);
  const DicAnalysis b = analyse_frames(order_frames(paths, "test"), untold);
  ASSERT_EQ(a.frames.size(), b.frames.size());
  EXPECT_NEAR(b.spacing, dcb.h, 1e-9);
  for (std::size_t k = 0; k < a.frames.size(); ++k)
    EXPECT_EQ(a.frames[k].tip.s, b.frames[k].tip.s) << k;
  untold.geometry.pixel_size = 0;
  try {
    analyse_frames(order_frames(paths, "test"), untold);
    ADD_FAILURE() << "pixels without a pixel size were read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("in px"), std::string::npos) << e.what();
  }
}
