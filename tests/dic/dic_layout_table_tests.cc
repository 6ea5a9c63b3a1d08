// The table of DIC layouts (dic/layouts.h, issue 40 item 4): each entry's writer writes a frame
// that the reader detects as that layout and reads back, so the writer and the reader cannot
// drift apart; names and help texts come from the table.
#include "fiberbridge/core/error.h"
#include "fiberbridge/dic/frame.h"
#include "fiberbridge/dic/layouts.h"

#include <gtest/gtest.h>

#include <string>

using namespace fiberbridge;
using namespace fiberbridge::dic;

TEST(DicLayoutTable, EachLayoutWrittenIsDetectedAndReadBack) {
  ASSERT_EQ(layouts().size(), 4u);
  for (const LayoutEntry* e : layouts()) {
    SCOPED_TRACE(e->name);
    ASSERT_TRUE(e->write_header && e->write_point);
    FrameFileHeader h;
    h.number = 3;
    h.time = 1.5;
    h.pixels = !e->mm_only;
    std::string text;
    e->write_header(text, h);
    for (std::size_t k = 0; k < 4; ++k) {
      FramePoint p;
      p.index = k;
      p.x = 10 + 0.5 * double(k % 2);
      p.y = k < 2 ? -0.25 : 0.25;
      p.u = 0.001;
      p.v = k < 2 ? -0.002 : 0.002;
      p.eyy = 0.004 * double(k + 1);
      p.sigma = 0.01;
      p.ok = k != 3; // the last point did not correlate
      e->write_point(text, p);
    }
    const RawFrame f = parse_frame(text, std::string("frame") + e->extension, {});
    EXPECT_EQ(f.layout, e->id);
    // Failed points: written as failed (sigma -1, valid 0) or left out (GOM).
    ASSERT_GE(f.x.size(), 3u);
    for (std::size_t k = 0; k < 3; ++k) {
      EXPECT_DOUBLE_EQ(f.x[k], 10 + 0.5 * double(k % 2)) << k;
      EXPECT_NEAR(f.eyy[k], 0.004 * double(k + 1), 1e-12) << k;
      EXPECT_EQ(f.valid[k], 1) << k;
    }
    if (f.x.size() == 4)
      EXPECT_EQ(f.valid[3], 0);
    EXPECT_EQ(parse_layout(e->name, "DIC/Format"), e->id);
    EXPECT_STREQ(layout_name(e->id), e->name);
  }
}

TEST(DicLayoutTable, NamesComeFromTheTable) {
  EXPECT_EQ(layout_names("|"), "vic|dice|gom|plain");
  EXPECT_EQ(parse_layout(" AUTO ", "k"), Layout::automatic);
  try {
    parse_layout("aramis", "DIC/Format");
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("expected auto, vic, dice, gom, plain"), std::string::npos)
        << e.what();
  }
  EXPECT_NE(layout_descriptions().find("gom (GOM/ZEISS"), std::string::npos);
}
