// The virtual test's DIC side (result/virtual_dic.h): the strain fit against an affine field (the
// patch test: exact), the three layouts parsed back as published (header, columns, the failed
// point's marker, pixel scale and y down), the frame clock and the seeded noise.
#include "fiberbridge/core/units.h"
#include "fiberbridge/result/virtual_dic.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

using namespace fiberbridge;
using namespace fiberbridge::result;
using units::mm;

namespace {

std::vector<std::string> lines_of(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::string> out;
  for (std::string l; std::getline(in, l);)
    out.push_back(l);
  return out;
}

std::vector<std::string> split(const std::string& line, char sep) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  for (std::string cell; std::getline(ss, cell, sep);) {
    const auto b = cell.find_first_not_of(' '), e = cell.find_last_not_of(' ');
    out.push_back(b == std::string::npos ? "" : cell.substr(b, e - b + 1));
  }
  return out;
}

std::string temp_dir(const std::string& tag) {
  const std::string d = ::testing::TempDir() + "fb_vdic_" + std::to_string(::getpid()) + "_" + tag;
  std::filesystem::create_directories(d);
  return d;
}

/// An affine displacement u = H (x, y) + c on `g` [m].
struct Affine {
  double ux = 0.012, uy = -0.004, vx = 0.007, vy = 0.021, cu = 3e-5, cv = -2e-5;
  double u(double x, double y) const { return cu + ux * x + uy * y; }
  double v(double x, double y) const { return cv + vx * x + vy * y; }
};

DicGrid small_grid() {
  DicGrid g;
  g.x0 = 10 * mm;
  g.y0 = -5.5 * mm;
  g.spacing = 1 * mm;
  g.nx = 21;
  g.ny = 12;
  return g;
}

} // namespace

TEST(VirtualDic, StrainFitIsExactForAnAffineField) {
  // Patch test: a plane fit reproduces a linear field exactly, whatever points of the window are
  // missing (edges, failed points), as long as three of them are not collinear. Tolerance: the
  // fit sums ~25 products of O(1e-2) values in grid units; round-off is ~1e-15, 1e-12 is a
  // thousand times that and a million times below the strains.
  const DicGrid g = small_grid();
  const Affine a;
  std::vector<double> u(g.size()), v(g.size());
  std::vector<char> valid(g.size(), 1);
  for (std::size_t k = 0; k < g.size(); ++k) {
    u[k] = a.u(g.x(k), g.y(k));
    v[k] = a.v(g.x(k), g.y(k));
    if (k % 7 == 3) // scattered failed points
      valid[k] = 0;
  }
  for (const bool lagrange : {false, true}) {
    const auto e = fit_dic_strains(g, u, v, valid, 5 * mm, lagrange);
    double exx = a.ux, eyy = a.vy, exy = 0.5 * (a.uy + a.vx);
    if (lagrange) {
      exx += 0.5 * (a.ux * a.ux + a.vx * a.vx);
      eyy += 0.5 * (a.uy * a.uy + a.vy * a.vy);
      exy += 0.5 * (a.ux * a.uy + a.vx * a.vy);
    }
    std::size_t n_ok = 0;
    for (std::size_t k = 0; k < g.size(); ++k) {
      EXPECT_EQ(bool(e.ok[k]), bool(valid[k])) << k; // every valid point has a full-rank window
      if (!e.ok[k])
        continue;
      ++n_ok;
      EXPECT_NEAR(e.exx[k], exx, 1e-12) << k;
      EXPECT_NEAR(e.eyy[k], eyy, 1e-12) << k;
      EXPECT_NEAR(e.exy[k], exy, 1e-12) << k;
    }
    EXPECT_GT(n_ok, g.size() * 8 / 10);
  }
}

TEST(VirtualDic, StrainFitRefusesACollinearWindow) {
  // One row of points: no gradient across it, so no point may claim a strain.
  DicGrid g = small_grid();
  g.ny = 1;
  std::vector<double> u(g.size(), 0.0), v(g.size(), 0.0);
  std::vector<char> valid(g.size(), 1);
  const auto e = fit_dic_strains(g, u, v, valid, 5 * mm, false);
  for (std::size_t k = 0; k < g.size(); ++k)
    EXPECT_FALSE(e.ok[k]);
}

TEST(VirtualDic, GridRowsAvoidTheCrackPlane) {
  VirtualDicSettings s;
  s.spacing = 0.5 * mm;
  s.y_from = -2 * mm;
  s.y_to = 2 * mm;
  const DicGrid g = make_dic_grid(s, 100 * mm, 10 * mm);
  EXPECT_EQ(g.nx, 201u); // x over the specimen's length: 0, 0.5, ..., 100 mm
  EXPECT_EQ(g.ny, 8u);   // y = -1.75 ... 1.75 mm
  EXPECT_NEAR(g.y0, -1.75 * mm, 1e-15);
  for (unsigned j = 0; j < g.ny; ++j)
    EXPECT_GT(std::abs(g.y(std::size_t(j) * g.nx)), 0.2 * mm);
}

namespace {
/// One frame of the affine field with the points of column 2 failed.
DicFrameData affine_frame(const DicGrid& g) {
  const Affine a;
  DicFrameData f;
  f.number = 7;
  f.time = 6;
  f.load = 123;
  f.opening = 4 * mm;
  f.u.resize(g.size());
  f.v.resize(g.size());
  std::vector<char> valid(g.size(), 1);
  for (std::size_t k = 0; k < g.size(); ++k) {
    f.u[k] = a.u(g.x(k), g.y(k));
    f.v[k] = a.v(g.x(k), g.y(k));
    valid[k] = k % g.nx != 2;
  }
  f.strains = fit_dic_strains(g, f.u, f.v, valid, 3 * mm, false);
  return f;
}
} // namespace

TEST(VirtualDic, VicLayoutInPixelsWithYDown) {
  const DicGrid g = small_grid();
  VirtualDicSettings s;
  s.layout = DicLayout::vic;
  s.pixels = true;
  s.pixel_size = 0.05 * mm;
  s.y_down = true;
  s.noise = 0.001 * mm;
  const auto f = affine_frame(g);
  const std::string path = temp_dir("vic") + "/dcb_0007.csv";
  write_dic_frame(path, s, g, f);
  const auto lines = lines_of(path);
  ASSERT_EQ(lines.size(), g.size() + 1);
  EXPECT_EQ(lines[0], "\"x\", \"y\", \"u\", \"v\", \"exx\", \"eyy\", \"exy\", \"sigma\"");
  const Affine a;
  const double top = g.y0 + (g.ny - 1) * g.spacing + g.spacing; // one spacing above the top row
  for (std::size_t k = 0; k < g.size(); ++k) {
    const auto c = split(lines[k + 1], ',');
    ASSERT_EQ(c.size(), 8u) << lines[k + 1];
    std::vector<double> d;
    for (const auto& cell : c)
      d.push_back(std::stod(cell));
    // 9 significant digits are written: relative tolerance 1e-8.
    EXPECT_NEAR(d[0], (g.x(k) - (g.x0 - g.spacing)) / s.pixel_size, 1e-6) << k;
    EXPECT_NEAR(d[1], (top - g.y(k)) / s.pixel_size, 1e-6) << k;
    if (k % g.nx == 2) { // failed: VIC's marker
      EXPECT_EQ(d[7], -1.0);
      continue;
    }
    EXPECT_NEAR(d[7], 0.02, 1e-12); // sigma: the noise in pixels
    EXPECT_NEAR(d[2], a.u(g.x(k), g.y(k)) / s.pixel_size, 1e-8 * std::abs(d[2]) + 1e-9);
    EXPECT_NEAR(d[3], -a.v(g.x(k), g.y(k)) / s.pixel_size, 1e-8 * std::abs(d[3]) + 1e-9);
    EXPECT_NEAR(d[4], a.ux, 1e-9);
    EXPECT_NEAR(d[5], a.vy, 1e-9);
    EXPECT_NEAR(d[6], -0.5 * (a.uy + a.vx), 1e-9); // y down: the shear changes sign
  }
}

TEST(VirtualDic, DiceLayoutInMm) {
  const DicGrid g = small_grid();
  VirtualDicSettings s;
  s.layout = DicLayout::dice;
  const auto f = affine_frame(g);
  const std::string path = temp_dir("dice") + "/dcb_0007.txt";
  write_dic_frame(path, s, g, f);
  const auto lines = lines_of(path);
  std::size_t h = 0;
  while (h < lines.size() && lines[h].rfind("***", 0) == 0)
    ++h;
  ASSERT_GT(h, 0u);
  ASSERT_EQ(lines.size(), h + 1 + g.size());
  EXPECT_EQ(lines[h], "SUBSET_ID,COORDINATE_X,COORDINATE_Y,DISPLACEMENT_X,DISPLACEMENT_Y,SIGMA,"
                      "VSG_STRAIN_XX,VSG_STRAIN_YY,VSG_STRAIN_XY");
  const Affine a;
  for (std::size_t k = 0; k < g.size(); ++k) {
    const auto c = split(lines[h + 1 + k], ',');
    ASSERT_EQ(c.size(), 9u);
    EXPECT_EQ(std::stoul(c[0]), k);
    EXPECT_NEAR(std::stod(c[1]), g.x(k) / mm, 1e-7);
    EXPECT_NEAR(std::stod(c[2]), g.y(k) / mm, 1e-7);
    if (k % g.nx == 2) {
      EXPECT_EQ(std::stod(c[5]), -1.0);
      continue;
    }
    EXPECT_GE(std::stod(c[5]), 0.0);
    EXPECT_NEAR(std::stod(c[4]), a.v(g.x(k), g.y(k)) / mm, 1e-9);
    EXPECT_NEAR(std::stod(c[7]), a.vy, 1e-9);
  }
}

TEST(VirtualDic, GomLayoutStrainsInPercent) {
  const DicGrid g = small_grid();
  VirtualDicSettings s;
  s.layout = DicLayout::gom;
  const auto f = affine_frame(g);
  const std::string path = temp_dir("gom") + "/dcb_0007.csv";
  write_dic_frame(path, s, g, f);
  const auto lines = lines_of(path);
  std::size_t h = 0, n_rows = 0;
  bool header = false;
  const Affine a;
  for (const auto& l : lines) {
    if (l.rfind("#", 0) == 0) {
      if (l.find("ID;") != std::string::npos) {
        header = true;
        const auto c = split(l.substr(1), ';');
        ASSERT_EQ(c.size(), 11u);
        EXPECT_EQ(c[1], "x_undef [mm]");
        EXPECT_EQ(c[8], "epsy [%]");
      }
      ++h;
      continue;
    }
    ASSERT_TRUE(header) << "data before the header";
    const auto c = split(l, ';');
    ASSERT_EQ(c.size(), 11u);
    const std::size_t k = std::stoul(c[0]) - 1;
    EXPECT_NE(k % g.nx, 2u); // failed facets are not in a nodemap
    EXPECT_NEAR(std::stod(c[1]), g.x(k) / mm, 1e-7);
    EXPECT_NEAR(std::stod(c[8]), 100 * a.vy, 1e-7);
    ++n_rows;
  }
  EXPECT_EQ(n_rows, g.size() - g.ny); // one column failed
  EXPECT_GT(h, 3u);
}

TEST(VirtualDic, ClockJumpsAtASnapBack) {
  VirtualDicSettings s;
  s.crosshead_rate = 1 * mm; // 1 mm/s
  const DicGrid g = small_grid();
  VirtualDicTest t(s, g, std::vector<char>(g.size(), 1));
  for (double o : {0.0, 1.0, 2.0, 1.5, 2.5}) {
    VirtualTestState st;
    st.opening = o * mm;
    st.u.assign(g.size(), 0.0);
    st.v.assign(g.size(), 0.0);
    t.add_state(st);
  }
  const auto c = t.clock();
  ASSERT_EQ(c.size(), 4u);
  EXPECT_EQ(c[2].second, 3u); // the state after the snap-back, at the earlier maximum's time
  EXPECT_NEAR(c[2].first, 2.0, 1e-12);
  EXPECT_NEAR(c[3].first, 2.5, 1e-12);
}

namespace {
/// Three states of the affine field scaled by the opening (0, 1, 2 mm) on a virtual machine at
/// 1 mm/s, frames at `rate` Hz.
VirtualDicTest affine_test(VirtualDicSettings& s, const DicGrid& g) {
  s.crosshead_rate = 1 * mm;
  VirtualDicTest t(s, g, std::vector<char>(g.size(), 1));
  const Affine a;
  for (double o : {0.0, 1.0, 2.0}) {
    VirtualTestState st;
    st.opening = o * mm;
    st.load = 100 * o;
    st.crack_tip = 40 * mm + o * mm;
    st.zone_front = 50 * mm + o * mm;
    st.delta_root = 0.1 * o * mm;
    for (std::size_t k = 0; k < g.size(); ++k) {
      st.u.push_back(o * a.u(g.x(k), g.y(k)));
      st.v.push_back(o * a.v(g.x(k), g.y(k)));
    }
    t.add_state(st);
  }
  return t;
}
} // namespace

TEST(VirtualDic, FramesRecordTruthAndSceneOnOneClock) {
  const DicGrid g = small_grid();
  VirtualDicSettings s;
  s.frame_rate = 2;
  s.record_rate = 10;
  s.first_frame_time = 0.25;
  s.strain_window = 3 * mm;
  const auto t = affine_test(s, g);
  const std::string dir = temp_dir("series");
  const auto files = t.write(dir, "subsection Specimen\n  set Initial crack = 40\nend\n", 40 * mm);
  // Frames at 0.25, 0.75, 1.25, 1.75 s (the last state at 2 s).
  EXPECT_EQ(files.n_frames, 4u);
  EXPECT_TRUE(std::filesystem::exists(dir + "/frames/dcb_0004.csv"));
  EXPECT_FALSE(std::filesystem::exists(dir + "/frames/dcb_0005.csv"));
  // Frame 2 at 0.75 s: the field of opening 0.75 mm (linear between the states), noise-free
  // but for the default 0 noise: exact to the 9 digits written.
  const Affine a;
  const auto lines = lines_of(dir + "/frames/dcb_0002.csv");
  for (std::size_t k = 0; k < g.size(); k += 37) {
    const auto c = split(lines[k + 1], ',');
    EXPECT_NEAR(std::stod(c[2]), 0.75 * a.u(g.x(k), g.y(k)) / mm, 1e-9);
    EXPECT_NEAR(std::stod(c[5]), 0.75 * a.vy, 1e-9);
  }
  // Truth on the same clock.
  const auto truth = lines_of(dir + "/virtual_test_truth.csv");
  std::vector<std::string> rows;
  for (const auto& l : truth)
    if (!l.empty() && l[0] != '#')
      rows.push_back(l);
  ASSERT_EQ(rows.size(), 5u); // header + 4 frames
  EXPECT_EQ(rows[0], "frame,time_s,load_N,opening_mm,crack_tip_mm,zone_front_mm,delta_root_mm");
  const auto r2 = split(rows[2], ',');
  EXPECT_NEAR(std::stod(r2[1]), 0.75, 1e-12);
  EXPECT_NEAR(std::stod(r2[2]), 75, 1e-9);
  EXPECT_NEAR(std::stod(r2[4]), 40.75, 1e-9);
  EXPECT_NEAR(std::stod(r2[6]), 0.075, 1e-12);
  // The machine: 10 rows per second from 0 to 2 s.
  std::size_t n_machine = 0;
  for (const auto& l : lines_of(dir + "/machine.csv"))
    if (!l.empty() && l[0] != '#')
      ++n_machine;
  EXPECT_EQ(n_machine, 1u + 21u);
  // The scene's Interface keys in the frames' coordinates (mm, y up here).
  std::ifstream in(files.scene);
  const std::string scene((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (const char* key :
       {"set Run = dic, reduce, extract", "set Frames                    = frames/dcb_*.csv",
        "set Format                    = vic", "set Coordinates               = mm",
        "set Y axis                    = up", "set Crack plane y             = 0",
        "set Notch root x              = 40", "set Growth direction          = +x",
        "set Frame rate                = 2", "set First frame time          = 0.25",
        "set Strain threshold          = 0.01", "set Extensometer gauge length = 2",
        "set Files = machine.csv", "set Initial crack = 40"})
    EXPECT_NE(scene.find(key), std::string::npos) << key;
  std::filesystem::remove_all(dir);
}

TEST(VirtualDic, NoiseIsGaussianWithTheStatedDeviationAndSeeded) {
  DicGrid g = small_grid();
  g.nx = 60;
  g.ny = 40; // 2400 points: the sample deviation is within 1/sqrt(2 n) = 1.4 % (1 sigma)
  VirtualDicSettings s;
  s.frame_rate = 1;
  s.noise = 0.01 * mm;
  s.seed = 11;
  const auto clean = [&] {
    VirtualDicSettings q = s;
    q.noise = 0;
    return affine_test(q, g);
  }();
  const auto noisy = affine_test(s, g);
  const std::string d0 = temp_dir("clean"), d1 = temp_dir("noisy"), d2 = temp_dir("again");
  clean.write(d0, "", 40 * mm);
  noisy.write(d1, "", 40 * mm);
  noisy.write(d2, "", 40 * mm);
  const auto l0 = lines_of(d0 + "/frames/dcb_0002.csv"), l1 = lines_of(d1 + "/frames/dcb_0002.csv");
  EXPECT_EQ(l1, lines_of(d2 + "/frames/dcb_0002.csv")); // the same seed, the same file
  double sum = 0, sum2 = 0;
  std::size_t n = 0;
  for (std::size_t k = 1; k < l0.size(); ++k) {
    const auto c0 = split(l0[k], ','), c1 = split(l1[k], ',');
    for (int col : {2, 3}) {
      const double e = (std::stod(c1[col]) - std::stod(c0[col])) / (s.noise / mm);
      sum += e;
      sum2 += e * e;
      ++n;
    }
  }
  const double mean = sum / double(n), sd = std::sqrt(sum2 / double(n) - mean * mean);
  // 5 standard errors: the mean's is 1/sqrt(n), the deviation's 1/sqrt(2 n).
  EXPECT_LT(std::abs(mean), 5 / std::sqrt(double(n)));
  EXPECT_LT(std::abs(sd - 1), 5 / std::sqrt(2.0 * double(n)));
  for (const auto& d : {d0, d1, d2})
    std::filesystem::remove_all(d);
}
