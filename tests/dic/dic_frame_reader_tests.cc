// The DIC frame reader (dic/frame.h): each layout's preset read from a file in the layout DIC
// software writes (tests/dic/data), failed points, percent strains, and one-line file:line
// reasons for frames that cannot be read.
#include "fiberbridge/core/error.h"
#include "fiberbridge/dic/frame.h"
#include "fiberbridge/dic/frame_set.h"

#include <gtest/gtest.h>

#include <string>

using namespace fiberbridge;
using namespace fiberbridge::dic;

namespace {

std::string data(const std::string& f) {
  return std::string(FIBERBRIDGE_DIC_TEST_DATA) + "/" + f;
}

FrameReadOptions px() {
  FrameReadOptions o;
  o.pixel_coordinates = true;
  return o;
}

std::string error_of(const std::string& text, const FrameReadOptions& o = {}) {
  try {
    parse_frame(text, "frame.csv", o);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

} // namespace

TEST(DicFrameReader, VicQuotedHeaderBlankLineBetweenAoisAndNegativeSigma) {
  const RawFrame f = read_frame(data("vic2d_px_two_aoi.csv"), px());
  EXPECT_EQ(f.layout, Layout::vic);
  ASSERT_EQ(f.x.size(), 5u); // both areas of interest, the blank line skipped
  EXPECT_EQ(f.n_failed, 1u); // sigma = -1
  EXPECT_EQ(f.valid[2], 0);
  EXPECT_DOUBLE_EQ(f.y[3], 60);
  EXPECT_DOUBLE_EQ(f.v[4], 1.5);
  EXPECT_DOUBLE_EQ(f.eyy[0], 0.02); // VIC strains are fractions
  EXPECT_EQ(f.used.at("valid"), "sigma");
}

TEST(DicFrameReader, VicCoordinatesAsTheSceneStatesThem) {
  // Lower-case x, y, u, v with Coordinates = mm: read as millimetres, as stated.
  const RawFrame f = parse_frame(
      "\"x\", \"y\", \"u\", \"v\", \"eyy\", \"sigma\"\n1, 2, 0.1, 0.2, 0.01, 0\n", "vic.csv", {});
  EXPECT_EQ(f.used.at("x"), "x");
  EXPECT_DOUBLE_EQ(f.v[0], 0.2);
  // Both pairs: Coordinates picks the pair (px: x, y, u, v; mm: X, Y, U, V).
  const std::string both = "\"x\",\"y\",\"u\",\"v\",\"X\",\"Y\",\"U\",\"V\",\"eyy\",\"sigma\"\n"
                           "100,200,4,6,5,10,0.2,0.3,0.01,0\n";
  EXPECT_DOUBLE_EQ(parse_frame(both, "vic.csv", {}).x[0], 5);
  EXPECT_DOUBLE_EQ(parse_frame(both, "vic.csv", px()).x[0], 100);
}

TEST(DicFrameReader, VicHeadersWithUnitsKeepPixelAndMetricApart) {
  const std::string text =
      "\"x [pixel]\",\"y [pixel]\",\"X [mm]\",\"Y [mm]\",\"U [mm]\",\"V [mm]\","
      "\"eyy [1]\",\"sigma [pixel]\"\n10,20,1.5,2.5,0.01,0.02,0.003,0.01\n";
  const RawFrame mm = parse_frame(text, "vic3d.csv", {});
  EXPECT_DOUBLE_EQ(mm.x[0], 1.5);
  EXPECT_DOUBLE_EQ(mm.v[0], 0.02);
  EXPECT_DOUBLE_EQ(mm.eyy[0], 0.003);
  EXPECT_EQ(mm.used.at("x"), "X [mm]");
  // In pixels the pixel columns come first; the displacements only exist in mm here, and are
  // taken as the scene states its units.
  EXPECT_DOUBLE_EQ(parse_frame(text, "vic3d.csv", px()).x[0], 10);
}

TEST(DicFrameReader, DiceCommentBlockCommaDelimitedAndSigmaMinusOne) {
  const RawFrame f = read_frame(data("dice_solution_3.txt"), px());
  EXPECT_EQ(f.layout, Layout::dice);
  ASSERT_EQ(f.x.size(), 3u);
  EXPECT_EQ(f.valid[1], 0);
  EXPECT_DOUBLE_EQ(f.x[1], 110);
  EXPECT_DOUBLE_EQ(f.eyy[2], 0.021);
  EXPECT_EQ(f.used.at("eyy"), "VSG_STRAIN_YY");
}

TEST(DicFrameReader, DiceSpaceDelimited) {
  const std::string text = "***\n*** DICe\n***\nSUBSET_ID COORDINATE_X COORDINATE_Y "
                           "DISPLACEMENT_X DISPLACEMENT_Y SIGMA VSG_STRAIN_YY\n"
                           "0 1.0E+01 2.0E+01 1.0E-01 2.0E-01 1.0E-02 5.0E-03\n"
                           "1 1.1E+01 2.0E+01 1.0E-01 2.0E-01 -1.0E+00 0.0E+00\n";
  const RawFrame f = parse_frame(text, "DICe_solution_1.txt", px());
  EXPECT_EQ(f.layout, Layout::dice);
  ASSERT_EQ(f.x.size(), 2u);
  EXPECT_DOUBLE_EQ(f.v[0], 0.2);
  EXPECT_EQ(f.n_failed, 1u);
}

TEST(DicFrameReader, GomNodemapCommentedHeaderPercentStrainsAndNan) {
  const RawFrame f = read_frame(data("gom_nodemap_stage_12.txt"), {});
  EXPECT_EQ(f.layout, Layout::gom);
  ASSERT_EQ(f.x.size(), 3u);
  EXPECT_DOUBLE_EQ(f.strain_factor, 0.01);
  EXPECT_DOUBLE_EQ(f.eyy[0], 0.02); // 2 % -> 0.02
  EXPECT_EQ(f.valid[1], 0);         // nan: not correlated
  EXPECT_DOUBLE_EQ(f.y[2], 0.25);
  EXPECT_EQ(f.used.at("x"), "x_undef [mm]");
}

TEST(DicFrameReader, GomDecimalCommaAndPlainHeader) {
  const std::string text = "# GOM Correlate export\n# stage: 3\n"
                           "x [mm];y [mm];u [mm];v [mm];epsy [%]\n"
                           "1,5;0,25;0,01;0,02;1,5\n";
  const RawFrame f = parse_frame(text, "gom.csv", {});
  EXPECT_EQ(f.layout, Layout::gom);
  EXPECT_DOUBLE_EQ(f.x[0], 1.5);
  EXPECT_DOUBLE_EQ(f.eyy[0], 0.015);
}

TEST(DicFrameReader, PlainLayoutWithColumnMapAndTime) {
  FrameReadOptions o;
  o.columns = FrameColumnMap::parse("eyy: e_yy, time_s: t", "DIC/Columns");
  const RawFrame f = parse_frame("x,y,u,v,e_yy,t\n1,2,3,4,0.5,7.5\n", "a.csv", o);
  EXPECT_EQ(f.layout, Layout::plain);
  EXPECT_DOUBLE_EQ(f.eyy[0], 0.5);
  EXPECT_DOUBLE_EQ(f.time, 7.5);
}

TEST(DicFrameReader, ValidFlagAndSigmaColumns) {
  // A column headed valid is a flag (0 failed); a mapped confidence column fails below 0 only.
  const RawFrame flag = parse_frame("x,y,u,v,eyy,valid\n1,2,3,4,0,0\n1,3,3,4,0,1\n", "f.csv", {});
  EXPECT_EQ(flag.n_failed, 1u);
  EXPECT_EQ(flag.valid[0], 0);
  FrameReadOptions o;
  o.columns = FrameColumnMap::parse("valid: conf", "DIC/Columns");
  const RawFrame conf = parse_frame("x,y,u,v,eyy,conf\n1,2,3,4,0,0\n1,3,3,4,0,-1\n", "f.csv", o);
  EXPECT_EQ(conf.n_failed, 1u);
  EXPECT_EQ(conf.valid[1], 0);
}

TEST(DicFrameReader, ColumnMapErrorsNameTheKey) {
  EXPECT_THROW(FrameColumnMap::parse("eyy e_yy", "DIC/Columns"), InputError);
  EXPECT_THROW(FrameColumnMap::parse("strain: e_yy", "DIC/Columns"), InputError);
  EXPECT_THROW(FrameColumnMap::parse("eyy: a, eyy: b", "DIC/Columns"), InputError);
  EXPECT_THROW(parse_layout("aramis", "DIC/Format"), InputError);
}

TEST(DicFrameReader, BadFramesGiveOneLineReasonsWithFileAndLine) {
  // A missing column, with the columns present.
  std::string e = error_of("x,y,u,v\n1,2,3,4\n");
  EXPECT_NE(e.find("frame.csv:1: missing column 'eyy'"), std::string::npos) << e;
  EXPECT_NE(e.find("columns present: x, y, u, v"), std::string::npos) << e;
  // A short row.
  e = error_of("x,y,u,v,eyy\n1,2,3,4,5\n1,2,3\n");
  EXPECT_NE(e.find("frame.csv:3: expected 5 values"), std::string::npos) << e;
  // Text where a number belongs.
  e = error_of("x,y,u,v,eyy\n1,2,abc,4,5\n");
  EXPECT_NE(e.find("frame.csv:2: column 'u' holds 'abc'"), std::string::npos) << e;
  // No header, no data, nothing.
  EXPECT_NE(error_of("1,2,3,4,5\n").find("data before any header"), std::string::npos);
  EXPECT_NE(error_of("x,y,u,v,eyy\n").find("no data rows"), std::string::npos);
  EXPECT_NE(error_of("").find("no header line"), std::string::npos);
  // An unknown strain unit.
  EXPECT_NE(error_of("x;y;u;v;epsy [ppm]\n1;2;3;4;5\n").find("unit [ppm]"), std::string::npos);
  // Infinite values are not numbers a DIC system writes.
  EXPECT_NE(error_of("x,y,u,v,eyy\n1,2,3,4,1e999\n").find("expected a finite number"),
            std::string::npos);
}

TEST(DicFrameSet, OrderedByTheNumberThatChangesAndTimesFromIt) {
  // VIC-3D names: image number, then the camera; image 2 missing (a dropped frame).
  const auto files =
      order_frames({"d/dcb_0003_0.csv", "d/dcb_0001_0.csv", "d/dcb_0000_0.csv"}, "DIC/Frames");
  ASSERT_EQ(files.size(), 3u);
  EXPECT_EQ(files[0].number, 0);
  EXPECT_EQ(files[2].number, 3);
  FrameClock clock;
  clock.frame_rate = 2;
  clock.first_frame_time = 10;
  FrameTimeSource used;
  const auto t = frame_times(files, {NAN, NAN, NAN}, clock, used);
  EXPECT_EQ(used, FrameTimeSource::name);
  EXPECT_DOUBLE_EQ(t[0], 10);
  EXPECT_DOUBLE_EQ(t[1], 10.5);
  EXPECT_DOUBLE_EQ(t[2], 11.5); // the gap of the missing image kept
  EXPECT_THROW(order_frames({"a_1.csv", "b_1.csv", "c_2.csv"}, "DIC/Frames"), InputError);
}

TEST(DicFrameSet, FramesOutOfTimeOrderAreAnError) {
  const auto files = order_frames({"f_1.csv", "f_2.csv", "f_3.csv"}, "DIC/Frames");
  FrameClock clock;
  FrameTimeSource used;
  try {
    frame_times(files, {0.0, 2.0, 1.5}, clock, used);
    FAIL() << "expected an error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("frames out of time order: f_3.csv"), std::string::npos)
        << e.what();
  }
}

// GOM Correlate / ZEISS Inspect native CSV (issue 42): the stage block above the point table
// (its relative_time is the frame's time) and the units line under the header (strains in %).
TEST(DicFrameReader, GomNativeStageBlockAndUnitsLine) {
  const RawFrame f = read_frame(data("gom_correlate_native_stage_7.csv"), {});
  EXPECT_EQ(f.layout, Layout::gom);
  ASSERT_EQ(f.x.size(), 3u);
  EXPECT_DOUBLE_EQ(f.time, 3.5);
  EXPECT_DOUBLE_EQ(f.strain_factor, 0.01);
  EXPECT_DOUBLE_EQ(f.eyy[0], 0.02);
  EXPECT_DOUBLE_EQ(f.y[2], 0.25);
  EXPECT_EQ(f.used.at("x"), "x_undef");
  // As `--format gom` forces it.
  FrameReadOptions gom;
  gom.layout = Layout::gom;
  EXPECT_EQ(read_frame(data("gom_correlate_native_stage_7.csv"), gom).x.size(), 3u);
}

TEST(DicFrameReader, UnitsLineWithAStrainUnitWeCannotReadIsRefused) {
  const std::string e = error_of("stage;index;relative_time;date\n1;1;0.5;x\n"
                                 "id;x_undef;y_undef;u;v;epsy\n;mm;mm;mm;mm;ppm\n1;1;2;3;4;5\n");
  EXPECT_NE(e.find("frame.csv:4"), std::string::npos) << e;
  EXPECT_NE(e.find("ppm"), std::string::npos) << e;
}

// DICe states its coordinates in its comment block: image coordinates are pixels.
TEST(DicFrameReader, DiceStatesItsCoordinates) {
  const RawFrame f = read_frame(data("dice_solution_3.txt"), {});
  EXPECT_EQ(f.stated_coordinates, "px");
  EXPECT_EQ(f.stated_line, 10u);
  const RawFrame m = parse_frame("***\n*** Coordinates: mm, y up\n***\nSUBSET_ID,COORDINATE_X,"
                                 "COORDINATE_Y,DISPLACEMENT_X,DISPLACEMENT_Y,SIGMA,VSG_STRAIN_YY\n"
                                 "0,1,2,0,0,0.01,0.001\n",
                                 "DICe_solution_1.txt", {});
  EXPECT_EQ(m.stated_coordinates, "mm");
}

// A point given twice with other values (issue 42: the tip jumped 22 mm) is refused, naming
// both lines; the same point repeated with the same values is kept.
TEST(DicFrameReader, DuplicatedPointWithConflictingStrainIsRefused) {
  const std::string e = error_of("x,y,u,v,eyy\n1,2,0,0,0.001\n1.5,2,0,0,0.001\n1,2,0,0,0.3\n");
  EXPECT_NE(e.find("frame.csv:4"), std::string::npos) << e;
  EXPECT_NE(e.find("line 2"), std::string::npos) << e;
  const RawFrame same = parse_frame("x,y,u,v,eyy\n1,2,0,0,0.001\n1,2,0,0,0.001\n", "f.csv", {});
  EXPECT_EQ(same.x.size(), 2u);
}
