// The one list splitter and the one trim (core/format.h; issue 30 item 5): the lists of a scene
// ("Run = beam, fem"), of a column map and of frame files all read through split_list.
#include "fiberbridge/core/format.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <limits>

using namespace fiberbridge;
using List = std::vector<std::string>;

TEST(Format, TrimBlanksRemovesOnlyTheBlanksAsked) {
  EXPECT_EQ(trim_blanks(" \t a b \t "), "a b");
  EXPECT_EQ(trim_blanks(" \t "), "");
  EXPECT_EQ(trim_blanks(""), "");
  EXPECT_EQ(trim_blanks("x\r"), "x\r") << "a list entry keeps a carriage return unless asked";
  EXPECT_EQ(trim_blanks(" x\r", cell_blanks), "x");
  EXPECT_EQ(trim_blanks("\nx \n", " \t\r\n"), "x");
}

TEST(Format, SplitListTrimsEachItemAndDropsEmptyOnes) {
  EXPECT_EQ(split_list("beam, fem ,mpm", ','), (List{"beam", "fem", "mpm"}));
  EXPECT_EQ(split_list(" , a,, \t,b,", ','), (List{"a", "b"}));
  EXPECT_EQ(split_list("", ','), List{});
  EXPECT_EQ(split_list(" \t ", ','), List{});
  EXPECT_EQ(split_list("one", ','), List{"one"});
  // Another separator; the other separators stay inside an item.
  EXPECT_EQ(split_list("Beam/Number of elements = 1, 2; FEM/x = 3", ';'),
            (List{"Beam/Number of elements = 1, 2", "FEM/x = 3"}));
  EXPECT_EQ(split_list("a / b/c", '/'), (List{"a", "b", "c"}));
  // Blanks given by the caller (a column map may hold line ends).
  EXPECT_EQ(split_list("x: X\r\n, y: Y", ',', " \t\r\n"), (List{"x: X", "y: Y"}));
  EXPECT_EQ(split_list("x: X\r\n, y: Y", ','), (List{"x: X\r\n", "y: Y"}));
}

// The one number formatter (issue 40 item 6): it replaced printf %.<p>g copies, whose bytes the
// outputs keep.
TEST(Format, FmtIsPrintfSignificantDigits) {
  for (const double v :
       {0.0, -0.0, 1.0, 0.0275, 26.2, 347.0, 1e6, 1.23456789e-7, -3.14159265358979, 123456789.0,
        1.0 / 3.0, 1e300, std::numeric_limits<double>::infinity(),
        -std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN()})
    for (const int p : {4, 5, 6, 7, 9}) {
      char b[64];
      std::snprintf(b, sizeof b, "%.*g", p, v);
      EXPECT_EQ(fmt(v, p), b) << v << " with " << p << " digits";
    }
  EXPECT_EQ(fmt(0.027512345), "0.02751");
  EXPECT_EQ(num(0.027512345), "0.0275123") << "num: the stream's default 6 digits";
  EXPECT_EQ(num(0.1), "0.1");
}

TEST(Format, FileNamePartKeepsLettersDigitsDashAndUnderscore) {
  EXPECT_EQ(file_name_part("PVA control"), "PVA_control");
  EXPECT_EQ(file_name_part("a-b_c/d.e:f"), "a-b_c_d_e_f");
  EXPECT_EQ(file_name_part(""), "");
  EXPECT_EQ(file_name_part("\xc3\xa9t\xc3\xa9"), "__t__") << "each byte of a UTF-8 letter";
}
