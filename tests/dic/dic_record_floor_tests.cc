// match_to_machine (dic_analysis.h) and a delta_root below zero: the FEM's virtual test with 2 um
// displacement noise gave -0.7 um before the root opened, which the record reader (reduce)
// refuses; within 3 standard deviations it is a zero opening (with a note), beyond that it is
// kept for the reader to refuse (a wrong Y axis or crack plane must not pass as noise).
#include "fiberbridge/dic/dic_analysis.h"

#include <gtest/gtest.h>

using namespace fiberbridge::dic;

TEST(DicRecord, NegativeRootOpeningWithinNoiseIsZero) {
  DicAnalysis a;
  a.spacing = 0.5e-3;
  const double opening[] = {-0.5e-6, -5e-6, 2e-6};
  for (int i = 0; i < 3; ++i) {
    FrameResult f;
    f.used = true;
    f.time = i;
    f.s_tip = 0;
    f.s_tip_sd = 1e-4;
    f.extensometer.ok = true;
    f.extensometer.opening = opening[i];
    f.extensometer.sd = 0.3e-6;
    a.frames.push_back(f);
  }
  MachineRecord m;
  m.time = {0, 10};
  m.opening = {0, 1e-3};
  m.load = {0, 100};
  std::vector<std::string> notes;
  const auto rows = match_to_machine(a, m, 0.04, notes);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0].delta_root, 0.0);   // -0.5 um, sd 0.3 um: within 3 sd
  EXPECT_EQ(rows[1].delta_root, -5e-6); // -5 um: beyond, kept for the reader to refuse
  EXPECT_EQ(rows[2].delta_root, 2e-6);  // positive: untouched
  EXPECT_DOUBLE_EQ(rows[0].delta_root_sd, 0.3e-6);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("1 frame(s) with delta_root below zero"), std::string::npos) << notes[0];
}
