// What the core writers leave on disk (core/csv.h, summary.h, plot.h, output_guard.h): complete
// files under their real names or nothing, NaN as "not available", and nothing at all on a
// process whose output is switched off (MPI ranks other than 0).
#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/output_guard.h"
#include "fiberbridge/core/plot.h"
#include "fiberbridge/core/summary.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace fs = std::filesystem;
using namespace fiberbridge;

namespace {

/// A fresh, empty directory for one test.
fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::path(FIBERBRIDGE_WORK_DIR) / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Every file in `dir`, by name.
std::vector<std::string> files_in(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir))
    names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

/// Output switched off for the lifetime of the object (and back on after, whatever happens).
struct OutputOff {
  OutputOff() { set_output_enabled(false); }
  ~OutputOff() { set_output_enabled(true); }
};

} // namespace

TEST(CsvWriter, WritesHeaderCommentsLabelsAndNaNAsEmpty) {
  const auto dir = fresh_dir("csv_writer");
  const std::string path = (dir / "t.csv").string();
  CsvWriter w(path, {"material", "delta_mm", "sigma_kPa"}, {"made by a test"});
  w.row({"PVA"}, {0.1, 661});
  w.row({"PF"}, {1.0 / 3.0, NAN});
  // Nothing under the real name before close().
  EXPECT_FALSE(fs::exists(path));
  w.close();
  EXPECT_EQ(slurp(path), "# made by a test\nmaterial,delta_mm,sigma_kPa\nPVA,0.1,661\n"
                         "PF,0.3333333333,\n");
  EXPECT_EQ(files_in(dir), (std::vector<std::string>{"t.csv"})); // no .partial left
  // Read back: the empty cell is text "", the numbers round-trip to 10 digits.
  const auto t = CsvTable::read(path);
  EXPECT_EQ(t.text("sigma_kPa")[1], "");
  EXPECT_NEAR(t.numeric("delta_mm")[1], 1.0 / 3.0, 1e-10); // 10 significant digits written
}

TEST(CsvWriter, MisuseIsAProgrammingError) {
  const auto dir = fresh_dir("csv_writer_misuse");
  CsvWriter w((dir / "t.csv").string(), {"a", "b"});
  EXPECT_THROW(w.row({1.0}), std::logic_error);
  EXPECT_THROW(w.row({"x"}, {1.0, 2.0}), std::logic_error);
  EXPECT_THROW(w.row({"x,y"}, {1.0}), std::logic_error); // a comma would shift the columns
}

TEST(CsvWriter, AnUnclosedWriterLeavesNoFile) {
  const auto dir = fresh_dir("csv_writer_unclosed");
  {
    CsvWriter w((dir / "t.csv").string(), {"a"});
    w.row({1.0});
  }
  EXPECT_TRUE(files_in(dir).empty());
}

TEST(SummaryJson, NumbersNullsOrderAndAtomicWrite) {
  EXPECT_EQ(json_number(1.5), Json(1.5));
  EXPECT_TRUE(json_number(NAN).is_null());
  EXPECT_TRUE(json_number(INFINITY).is_null());
  EXPECT_TRUE(json_number(-INFINITY).is_null());

  const auto dir = fresh_dir("summary_json");
  Json j = Json::object();
  j["scene"] = "s.prm";
  j["beam"]["G_ss_J_m2"] = json_number(1082.5);
  j["beam"]["rdelta_rel_error_vs_eq2"] = json_number(NAN);
  j["a_last"] = 1;
  const std::string path = (dir / "summary.json").string();
  write_json_atomically(path, j);
  EXPECT_EQ(files_in(dir), (std::vector<std::string>{"summary.json"}));
  const std::string text = slurp(path);
  // Keys stay in insertion order (the summary reads top-down in the order items ran).
  EXPECT_LT(text.find("\"scene\""), text.find("\"beam\""));
  EXPECT_LT(text.find("\"beam\""), text.find("\"a_last\""));
  EXPECT_EQ(text.back(), '\n');
  const Json back = Json::parse(text);
  EXPECT_EQ(back, j);
  EXPECT_TRUE(back["beam"]["rdelta_rel_error_vs_eq2"].is_null());
}

TEST(SummaryJson, AnUnwritablePathIsAnInputError) {
  EXPECT_THROW(write_json_atomically("/nonexistent/dir/summary.json", Json::object()), InputError);
}

TEST(OutputGuard, NothingIsWrittenWhileOutputIsOff) {
  const auto dir = fresh_dir("output_guard");
  EXPECT_TRUE(output_enabled()); // a serial program writes
  {
    OutputOff off;
    EXPECT_FALSE(output_enabled());
    write_file_atomically((dir / "a.txt").string(), "x");
    write_json_atomically((dir / "s.json").string(), Json::object());
    CsvWriter w((dir / "t.csv").string(), {"a"});
    w.row({1.0});
    w.close();
    EXPECT_FALSE(run_gnuplot(dir.string(), gnuplot_png_preamble("p.png") + "plot x\n"));
  }
  EXPECT_TRUE(files_in(dir).empty());
  EXPECT_TRUE(output_enabled());
  write_file_atomically((dir / "a.txt").string(), "x");
  EXPECT_EQ(slurp(dir / "a.txt"), "x");
}

TEST(Plot, PreambleWritesUnderAPartialName) {
  const std::string p = gnuplot_png_preamble("r_curve.png", 1000, 650);
  EXPECT_NE(p.find("set terminal pngcairo size 1000,650"), std::string::npos) << p;
  EXPECT_NE(p.find("set output 'r_curve.png.partial'"), std::string::npos) << p;
  EXPECT_NE(p.find("set datafile separator ','"), std::string::npos) << p;
}

TEST(Plot, GnuplotResultIsRenamedIntoPlaceOrRemoved) {
  if (std::system("command -v gnuplot >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "gnuplot not installed: run_gnuplot returns false and the CSV files stand";
  const auto dir = fresh_dir("plot");
  EXPECT_TRUE(run_gnuplot(dir.string(), gnuplot_png_preamble("ok.png") + "plot x*x\n"));
  EXPECT_EQ(files_in(dir), (std::vector<std::string>{"ok.png"})); // no script, no .partial
  EXPECT_GT(fs::file_size(dir / "ok.png"), 0u);
  // A script gnuplot rejects: false, and neither the PNG nor its partial file stays.
  EXPECT_FALSE(run_gnuplot(dir.string(), gnuplot_png_preamble("bad.png") + "plot (\n"));
  EXPECT_EQ(files_in(dir), (std::vector<std::string>{"ok.png"}));
}
