// The one list splitter and the one trim (core/format.h; issue 30 item 5): the lists of a scene
// ("Run = beam, fem"), of a column map and of frame files all read through split_list.
#include "fiberbridge/core/format.h"

#include <gtest/gtest.h>

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
