// CsvTable on the text real files bring (core/csv.h): quoted cells, CRLF line ends, a byte-order
// mark, blank and comment lines, missing and non-numeric cells, each bad case with an error that
// names the file and line.
#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using fiberbridge::CsvTable;
using fiberbridge::InputError;

namespace {

/// The message of the InputError that parsing `text` (as "t.csv") throws; "" if none.
std::string parse_error(const std::string& text) {
  try {
    CsvTable::parse(text, "t.csv");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

/// Reading column `name` of `text`: the InputError message, "" if none.
std::string numeric_error(const std::string& text, const std::string& name) {
  try {
    CsvTable::parse(text, "t.csv").numeric(name);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

bool contains(const std::string& s, const std::string& part) {
  return s.find(part) != std::string::npos;
}

} // namespace

TEST(CsvTable, PlainTableWithSpacesAroundCells) {
  const auto t = CsvTable::parse("delta_mm, R_J_m2\n0, 200\n 0.5 ,  350.25\n", "t.csv");
  ASSERT_EQ(t.header(), (std::vector<std::string>{"delta_mm", "R_J_m2"}));
  EXPECT_EQ(t.n_rows(), 2u);
  EXPECT_EQ(t.numeric("R_J_m2"), (std::vector<double>{200, 350.25}));
  EXPECT_EQ(t.line_of_row(1), 3u);
}

TEST(CsvTable, CrlfLineEnds) {
  const auto t = CsvTable::parse("a_mm,load_N\r\n1,2\r\n3,4\r\n", "t.csv");
  EXPECT_EQ(t.header().back(), "load_N");
  EXPECT_EQ(t.numeric("load_N"), (std::vector<double>{2, 4}));
}

TEST(CsvTable, ByteOrderMarkIsNotPartOfTheFirstName) {
  const auto t = CsvTable::parse("\xEF\xBB\xBF"
                                 "delta_mm,R_J_m2\n0,200\n",
                                 "t.csv");
  EXPECT_TRUE(t.has_column("delta_mm"));
  EXPECT_EQ(t.numeric("delta_mm"), (std::vector<double>{0}));
}

TEST(CsvTable, BlankAndCommentLinesAreSkippedButCounted) {
  const auto t = CsvTable::parse(
      "# provenance\n\ndelta_mm,R_J_m2\n\n  # mid-table note\n1,2\n   \n3,4\n", "t.csv");
  EXPECT_EQ(t.n_rows(), 2u);
  // Line numbers are those of the file, for error messages.
  EXPECT_EQ(t.line_of_row(0), 6u);
  EXPECT_EQ(t.line_of_row(1), 8u);
}

TEST(CsvTable, QuotedCellsHoldCommasAndQuotes) {
  const auto t = CsvTable::parse(
      "\"Time (s)\",\"Load, N\",label\n1,\"2.5\",\"say \"\"hi\"\", then go\"\n", "t.csv");
  ASSERT_EQ(t.header(), (std::vector<std::string>{"Time (s)", "Load, N", "label"}));
  EXPECT_EQ(t.numeric("Load, N"), (std::vector<double>{2.5}));
  EXPECT_EQ(t.text("label")[0], "say \"hi\", then go");
  // An empty quoted cell is an empty cell.
  EXPECT_EQ(CsvTable::parse("a,b\n\"\",1\n", "t.csv").text("a")[0], "");
}

TEST(CsvTable, BrokenQuotesNameTheLine) {
  EXPECT_TRUE(contains(parse_error("a,b\n\"1,2\n"), "t.csv:2: a quoted cell has no closing quote"));
  EXPECT_TRUE(contains(parse_error("a,b\n\"1\"x,2\n"), "t.csv:2: text after the closing quote"));
}

TEST(CsvTable, MissingAndExtraCellsNameTheLine) {
  EXPECT_TRUE(contains(parse_error("a,b,c\n1,2,3\n4,5\n"), "t.csv:3: expected 3"));
  EXPECT_TRUE(contains(parse_error("a,b\n1,2,3\n"), "found 3"));
  // A trailing comma is one more (empty) cell.
  EXPECT_TRUE(contains(parse_error("a,b\n1,2,\n"), "found 3"));
  // An empty cell inside a row parses, but is not a number.
  EXPECT_TRUE(contains(numeric_error("a,b\n1,2\n3,\n", "b"), "t.csv:3: column 'b' holds ''"));
  EXPECT_EQ(numeric_error("a,b\n1,2\n3,\n", "a"), "");
}

TEST(CsvTable, NonNumbersAndNonFiniteValuesAreRejected) {
  for (const std::string bad : {"abc", "1.5x", "nan", "inf", "1e999"})
    EXPECT_TRUE(contains(numeric_error("a\n" + bad + "\n", "a"), "t.csv:2: column 'a' holds"))
        << bad;
}

TEST(CsvTable, HeaderProblems) {
  EXPECT_TRUE(contains(parse_error(""), "empty file"));
  EXPECT_TRUE(contains(parse_error("# only a comment\n\n"), "empty file"));
  EXPECT_TRUE(contains(parse_error("a,b\n"), "no data rows"));
  EXPECT_TRUE(contains(parse_error("a,,b\n1,2,3\n"), "header column 2 has no name"));
  EXPECT_TRUE(contains(parse_error("a,b,a\n1,2,3\n"), "duplicate column 'a'"));
  try {
    CsvTable::parse("a,b\n1,2\n", "t.csv").numeric("c");
    FAIL() << "a missing column was not reported";
  } catch (const InputError& e) {
    EXPECT_TRUE(contains(e.what(), "missing column 'c' (columns present: a, b)")) << e.what();
  }
}

TEST(CsvTable, MissingFileNamesThePath) {
  try {
    CsvTable::read("/nonexistent/dir/table.csv");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_TRUE(contains(e.what(), "/nonexistent/dir/table.csv: cannot open")) << e.what();
  }
}
