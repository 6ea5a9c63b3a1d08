// Every frame is checked against the first frame's reference points (dic_analysis.cc): point by
// point, so that a layout that leaves failed points out of its files (GOM/ZEISS) keeps its frames,
// while a frame whose coordinates moved (another image origin, an export in the deformed
// configuration) is left out with a note. Found on the FEM's virtual test in GOM's layout with
// 2 % failed facets, which lost 6 of 31 frames to a check on the grid means
// (tests/fem/dic_end_to_end_tests.cc).
#include "dic_synthetic.h"
#include "fiberbridge/dic/dic_analysis.h"

#include <gtest/gtest.h>

#include <filesystem>

using namespace fiberbridge;
using namespace fiberbridge::dic;
using fiberbridge::test::Out;
using fiberbridge::test::SyntheticDcb;
namespace fs = std::filesystem;

TEST(DicReferencePoints, AbsentFailedPointsKeepTheFrameMovedPointsDoNot) {
  SyntheticDcb dcb;
  dcb.noise_v = 0.5e-6;
  dcb.fail_fraction = 0.03; // 3 % of the points fail, at random; GOM leaves them out
  const fs::path dir = fs::path(::testing::TempDir()) / "fb_dic_reference_points";
  fs::remove_all(dir);
  fs::create_directories(dir);
  FrameGeometry g;
  std::vector<std::string> paths;
  for (int k = 0; k < 8; ++k) {
    const dic::PlaneFrame all = dcb.frame(10e-3 + 1e-3 * k, 1.0, 70u + k);
    dic::PlaneFrame f; // the valid points only, as GOM exports them
    for (std::size_t i = 0; i < all.s.size(); ++i)
      if (all.valid[i]) {
        f.s.push_back(all.s[i]);
        f.n.push_back(all.n[i]);
        f.us.push_back(all.us[i]);
        f.vn.push_back(all.vn[i]);
        f.eyy.push_back(all.eyy[i]);
        f.valid.push_back(1);
      }
    if (k == 6) // the image origin moved by 0.4 spacings along the plane
      for (auto& s : f.s)
        s += 0.4 * dcb.h;
    const std::string p = (dir / ("f_" + std::to_string(k) + ".csv")).string();
    test::write_frame(p, f, g, Out::gom);
    paths.push_back(p);
  }
  DicOptions o;
  o.geometry = g;
  const DicAnalysis a = analyse_frames(order_frames(paths, "test"), o);
  ASSERT_EQ(a.frames.size(), 8u);
  for (int k = 0; k < 8; ++k) {
    const auto& f = a.frames[k];
    if (k == 6) {
      EXPECT_FALSE(f.used);
      ASSERT_FALSE(f.notes.empty());
      EXPECT_NE(f.notes[0].find("points moved off the crack plane"), std::string::npos)
          << f.notes[0];
    } else {
      EXPECT_TRUE(f.used) << k << ": " << (f.notes.empty() ? "" : f.notes[0]);
    }
  }
  // The frames hold different numbers of points (the absent ones differ per frame).
  EXPECT_NE(a.frames[0].n_points, a.frames[1].n_points);
  fs::remove_all(dir);
}
