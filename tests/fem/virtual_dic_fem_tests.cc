// The FEM's virtual test (FEM/Virtual DIC; source/fem/virtual_dic.h, result/virtual_dic.h): a
// small linear-softening DCB writes its DIC frames, machine record and truth; the frames are read
// back as published (VIC CSV; DICe in pixels with y down) and checked against the FEM's own
// solution: the prescribed load-line displacement, the truth's opening at the notch root against
// the R curve's delta_root, and the seeded noise against its stated deviation. The layouts and
// the strain fit's patch test are in tests/result/virtual_dic_tests.cc.
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/units.h"
#include "fiberbridge/fem/dcb_simulation.h"
#include "fiberbridge/law/piecewise_linear_law.h"

#include "test_cases.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

using namespace fiberbridge;
using units::kPa;
using units::mm;

namespace {

std::vector<std::string> split(const std::string& line, char sep) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  for (std::string cell; std::getline(ss, cell, sep);)
    out.push_back(cell);
  return out;
}

/// The numeric rows of a frame or CSV file: lines that are not comments ('#', '***') and not the
/// header (the first such line).
std::vector<std::vector<double>> rows_of(const std::string& path, std::string* header = nullptr) {
  std::ifstream in(path);
  std::vector<std::vector<double>> rows;
  bool seen_header = false;
  for (std::string l; std::getline(in, l);) {
    if (l.empty() || l[0] == '#' || l.rfind("***", 0) == 0)
      continue;
    if (!seen_header) {
      seen_header = true;
      if (header)
        *header = l;
      continue;
    }
    std::vector<double> r;
    for (const auto& c : split(l, ','))
      r.push_back(std::stod(c));
    rows.push_back(r);
  }
  return rows;
}

std::string read_all(const std::string& path) {
  std::ifstream in(path);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

/// The linear-softening case of fem_tests (about a second): the zone of ~15 elements grows and
/// its root leaves the notch within the short specimen.
struct VirtualRun {
  specimen::Specimen spec = fem_test::short_dcb();
  specimen::Material wood;
  law::PiecewiseLinearLaw law =
      law::make_linear_softening(1000 * kPa, 0.4 * mm).with_elastic_rise(0.04 * mm);
  fem::FemParameters prm;
  result::SimulationResult result;
  std::string dir;
  VirtualRun(const std::string& tag, const std::function<void(result::VirtualDicSettings&)>& set) {
    prm.mesh.element_size = 1 * mm;
    prm.steady_state.window = 8 * mm;
    auto& s = prm.virtual_dic.settings;
    s.enabled = true;
    s.crosshead_rate = 1 * mm; // 60 mm/min: one frame per 0.1 mm of opening at 10 Hz
    s.frame_rate = 10;
    s.first_frame_time = 0.05;
    // The field of view reaches past the specimen on every side (x -2..122 mm, rows at +-10.5
    // mm beyond the arms' faces at +-10 mm): those points never correlate.
    s.x_from = -2 * mm;
    s.x_to = 122 * mm;
    s.y_from = -11 * mm;
    s.y_to = 11 * mm;
    s.spacing = 1 * mm;
    s.strain_window = 3 * mm;
    set(s);
    dir = ::testing::TempDir() + "fb_vdic_fem_" + std::to_string(::getpid()) + "_" + tag;
    std::filesystem::remove_all(dir);
    result = fem::simulate_dcb(spec, wood, law, 200, prm, dir);
  }
  ~VirtualRun() { std::filesystem::remove_all(dir); }
  std::string vt() const { return dir + "/virtual_test"; }
};

} // namespace

TEST(FemVirtualDic, FramesCarryTheFemFieldOnTheMachineClock) {
  const VirtualRun run("vic", [](result::VirtualDicSettings& s) {
    s.layout = result::DicLayout::vic;
    s.noise = 0;
  });
  const auto& rc = run.result.rcurve;
  ASSERT_GE(rc.size(), 10u);
  const double rate = run.prm.virtual_dic.settings.crosshead_rate;

  // The states on the virtual clock (result::VirtualDicTest::clock's rule: time = running
  // maximum of the opening over the crosshead rate; a state below it replaces the one there).
  struct State {
    double t, opening, load, tip, front, delta_root;
  };
  std::vector<State> states{{0, 0, 0, run.spec.initial_crack, run.spec.initial_crack, 0}};
  double running_max = 0;
  for (const auto& p : rc) {
    const State s{
        p.load_point_opening / rate, p.load_point_opening, p.load, p.root, p.a, p.delta_root};
    if (p.load_point_opening > running_max) {
      running_max = p.load_point_opening;
      states.push_back(s);
    } else
      states.back() = State{states.back().t, s.opening, s.load, s.tip, s.front, s.delta_root};
  }
  const double t_end = states.back().t;
  const unsigned n_frames = unsigned(std::floor((t_end - 0.05) * 10 + 1e-9)) + 1;
  EXPECT_TRUE(std::filesystem::exists(run.vt() + "/frames/dcb_0001.csv"));
  char last[64];
  std::snprintf(last, sizeof last, "/frames/dcb_%04u.csv", n_frames);
  EXPECT_TRUE(std::filesystem::exists(run.vt() + last)) << last;
  std::snprintf(last, sizeof last, "/frames/dcb_%04u.csv", n_frames + 1);
  EXPECT_FALSE(std::filesystem::exists(run.vt() + last)) << last;

  // The truth at each frame is the R curve's states interpolated in time. The opening at the
  // notch root is sampled at (a0, 0) on each arm; the R curve's delta_root is the nodal opening
  // there (both exact nodal values) until the root moves (then it is delta_c at the new root):
  // compared only between states whose root has not moved. 1e-7 relative: the file's 10 digits.
  const auto truth = rows_of(run.vt() + "/virtual_test_truth.csv");
  ASSERT_EQ(truth.size(), n_frames);
  unsigned n_root_checked = 0;
  for (const auto& r : truth) {
    const double t = r[1];
    std::size_t i = 1;
    while (i + 1 < states.size() && states[i].t < t)
      ++i;
    const State &A = states[i - 1], &B = states[i];
    const double w = (t - A.t) / (B.t - A.t);
    auto mix = [&](double a, double b) { return (1 - w) * a + w * b; };
    EXPECT_NEAR(r[2], mix(A.load, B.load), 1e-7 * std::abs(r[2]) + 1e-9) << t;
    EXPECT_NEAR(r[3], mix(A.opening, B.opening) / mm, 1e-7 * r[3] + 1e-12) << t;
    EXPECT_NEAR(r[4], mix(A.tip, B.tip) / mm, 1e-6) << t;
    EXPECT_NEAR(r[5], mix(A.front, B.front) / mm, 1e-6) << t;
    EXPECT_LE(r[4], r[5] + 1e-9);
    const double unmoved = run.spec.initial_crack * (1 + 1e-9);
    if (A.tip <= unmoved && B.tip <= unmoved) {
      EXPECT_NEAR(r[6], mix(A.delta_root, B.delta_root) / mm, 1e-7 * r[6] + 1e-9) << t;
      ++n_root_checked;
    }
  }
  std::printf("virtual test: %zu advances, %u frames over %.2f s, truth root %.1f -> %.1f mm, "
              "front %.1f -> %.1f mm, delta_root %.4f mm at the end (%u frames checked before the "
              "root moved)\n",
              rc.size(), n_frames, t_end, truth.front()[4], truth.back()[4], truth.front()[5],
              truth.back()[5], truth.back()[6], n_root_checked);
  EXPECT_GT(n_root_checked, 5u);
  EXPECT_GT(truth.back()[4], run.spec.initial_crack / mm + 1); // the root moved during the test

  // Every frame: the load-line points (x = 0) carry the prescribed +-opening/2 of the FEM
  // (the whole end face of each arm), exact up to the 9 digits written; the points off the
  // specimen and only those are VIC's failed points (sigma -1).
  std::string header;
  for (unsigned f = 1; f <= n_frames; f += 3) {
    char name[64];
    std::snprintf(name, sizeof name, "/frames/dcb_%04u.csv", f);
    const auto rows = rows_of(run.vt() + name, &header);
    ASSERT_EQ(rows.size(), 125u * 22u);
    const double opening_mm = truth[f - 1][3];
    unsigned n_load_line = 0;
    for (const auto& r : rows) {
      ASSERT_EQ(r.size(), 8u);
      const bool on_body = r[0] >= -1e-9 && r[0] <= 120 + 1e-9 && std::abs(r[1]) < 10;
      EXPECT_EQ(r[7] < 0, !on_body) << r[0] << ", " << r[1];
      if (on_body && std::abs(r[0]) < 1e-9) {
        EXPECT_NEAR(r[3], (r[1] > 0 ? 0.5 : -0.5) * opening_mm, 1e-8 * opening_mm + 1e-12);
        ++n_load_line;
      }
    }
    EXPECT_EQ(n_load_line, 20u);
  }
  EXPECT_EQ(header, "\"x\", \"y\", \"u\", \"v\", \"exx\", \"eyy\", \"exy\", \"sigma\"");

  // The scene, in the frames' coordinates (mm, y up).
  const std::string scene = read_all(run.vt() + "/dic_scene.prm");
  for (const char* key :
       {"set Run = dic, reduce, extract", "set Frames                    = frames/dcb_*.csv",
        "set Format                    = vic", "set Coordinates               = mm",
        "set Y axis                    = up", "set Crack plane y             = 0",
        "set Notch root x              = 40", "set Frame rate                = 10",
        "set First frame time          = 0.05", "set Files = machine.csv", "set Initial crack = 40",
        "set Length = 120"})
    EXPECT_NE(scene.find(key), std::string::npos) << key;
  // The machine record: 10 rows per second over the test, opening = rate x time until the
  // first snap-back (none here: the opening rises monotonically in this case).
  const auto machine = rows_of(run.vt() + "/machine.csv");
  EXPECT_EQ(machine.size(), std::size_t(std::floor(t_end * 10 + 1e-9)) + 1);
  for (const auto& r : machine)
    EXPECT_NEAR(r[2], r[0] * rate / mm, 1e-7 * r[2] + 1e-12);
}

TEST(FemVirtualDic, DicePixelsYDownNoiseAndFailures) {
  // The same run twice: noise-free VIC in mm and noisy DICe in pixels with y down and 10 % of
  // the points failing at random; the DICe frames mapped back to mm differ from the VIC frames
  // by the noise alone.
  const double ps = 0.05 * mm, noise = 0.002 * mm;
  const VirtualRun clean("clean", [](result::VirtualDicSettings& s) { s.noise = 0; });
  const VirtualRun noisy("dice", [&](result::VirtualDicSettings& s) {
    s.layout = result::DicLayout::dice;
    s.pixels = true;
    s.pixel_size = ps;
    s.y_down = true;
    s.noise = noise;
    s.failed_fraction = 0.1;
    s.seed = 7;
  });
  const std::string scene = read_all(noisy.vt() + "/dic_scene.prm");
  // Pixels from one spacing outside the field of view: x_px = (x + 3 mm) / ps, y_px = (11.5 mm
  // - y) / ps, so the notch root (40 mm) is at 860 px and the crack plane at 230 px.
  for (const char* key :
       {"set Frames                    = frames/dcb_*.txt", "set Format                    = dice",
        "set Coordinates               = px", "set Pixel size                = 0.05",
        "set Y axis                    = down", "set Crack plane y             = 230",
        "set Notch root x              = 860"})
    EXPECT_NE(scene.find(key), std::string::npos) << key;

  // A frame in the middle of the test (the same time in both runs: the same FEM states).
  unsigned n_frames = 0;
  for (const auto& e : std::filesystem::directory_iterator(clean.vt() + "/frames"))
    n_frames += e.path().extension() == ".csv";
  ASSERT_GE(n_frames, 4u);
  char name[32];
  std::snprintf(name, sizeof name, "/frames/dcb_%04u", n_frames / 2);
  std::string header;
  const auto a = rows_of(clean.vt() + name + ".csv");
  const auto b = rows_of(noisy.vt() + name + ".txt", &header);
  EXPECT_EQ(header, "SUBSET_ID,COORDINATE_X,COORDINATE_Y,DISPLACEMENT_X,DISPLACEMENT_Y,SIGMA,"
                    "VSG_STRAIN_XX,VSG_STRAIN_YY,VSG_STRAIN_XY");
  ASSERT_EQ(a.size(), b.size());
  double sum = 0, sum2 = 0, worst = 0;
  std::size_t n = 0, n_on = 0, n_failed = 0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    // Same point, DICe in pixels with y down.
    EXPECT_NEAR(b[k][1] * ps / mm - 3, a[k][0], 1e-6);
    EXPECT_NEAR(11.5 - b[k][2] * ps / mm, a[k][1], 1e-6);
    if (a[k][7] < 0) { // off the specimen: failed in DICe as well
      EXPECT_EQ(b[k][5], -1.0);
      continue;
    }
    ++n_on;
    if (b[k][5] < 0) {
      ++n_failed;
      continue;
    }
    EXPECT_NEAR(b[k][5], noise / ps, 1e-12); // sigma: the noise in pixels
    const double du = b[k][3] * ps / mm - a[k][2], dv = -b[k][4] * ps / mm - a[k][3];
    for (double d : {du, dv}) {
      const double z = d / (noise / mm);
      sum += z;
      sum2 += z * z;
      worst = std::max(worst, std::abs(z));
      ++n;
    }
  }
  // ~4400 normal samples: mean within 5/sqrt(n), deviation within 5/sqrt(2n) of 1, none past 6
  // (probability 2e-9 each).
  const double mean = sum / double(n), sd = std::sqrt(sum2 / double(n) - mean * mean);
  EXPECT_LT(std::abs(mean), 5 / std::sqrt(double(n)));
  EXPECT_LT(std::abs(sd - 1), 5 / std::sqrt(2.0 * double(n)));
  EXPECT_LT(worst, 6.0);
  // Failed share: binomial, 5 standard deviations.
  const double share = double(n_failed) / double(n_on);
  EXPECT_NEAR(share, 0.1, 5 * std::sqrt(0.09 / double(n_on)));
}

namespace {
/// The InputError message of prm.validate(), or "" when it passes.
std::string validation_error(const fem::FemParameters& prm) {
  try {
    prm.validate();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}
} // namespace

TEST(FemVirtualDic, RefusesSettingsItCannotHonour) {
  fem::FemParameters prm;
  prm.virtual_dic.settings.enabled = true;
  EXPECT_EQ(validation_error(prm), "");
  prm.mesh.dimension = 3; // the sampler is 2D
  EXPECT_NE(validation_error(prm).find("FEM/Virtual DIC/Enabled"), std::string::npos);
  prm.mesh.dimension = 2;
  prm.virtual_dic.settings.strain_window = 1.5 * prm.virtual_dic.settings.spacing;
  EXPECT_NE(validation_error(prm).find("FEM/Virtual DIC/Strain window"), std::string::npos);
  prm.virtual_dic.settings.strain_window = 5 * mm;
  prm.virtual_dic.settings.layout = result::DicLayout::gom; // nodemaps are in mm
  prm.virtual_dic.settings.pixels = true;
  EXPECT_NE(validation_error(prm).find("FEM/Virtual DIC/Coordinates"), std::string::npos);
}
