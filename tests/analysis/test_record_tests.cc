// The raw test-record reader (test_record.h): column maps, the cleaning of what real machines
// write, and a one-line file:line reason for every record that cannot be used.
#include "fiberbridge/analysis/test_record.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/units.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>
#include <unistd.h>

using namespace fiberbridge;
using namespace fiberbridge::analysis;
using units::mm;

namespace {

class TempFile {
public:
  TempFile(const std::string& name, const std::string& content)
      : path_(::testing::TempDir() + "fb_" + std::to_string(::getpid()) + "_" + name) {
    std::ofstream(path_) << content;
  }
  ~TempFile() { std::remove(path_.c_str()); }
  const std::string& path() const { return path_; }

private:
  std::string path_;
};

/// A clean record in our column names: 20 rows at 1 Hz, opening 0.5 mm per second, load rising
/// then falling, crack reading 30 mm until row 8, then 1 mm per reading every second row.
/// Rows start on line 2 (the header is line 1).
std::string clean_rows(int n = 20) {
  std::string s;
  for (int i = 0; i < n; ++i) {
    const double a = i < 8 ? 30 : 30 + (i - 6) / 2;
    const double load = i < 8 ? 10.0 * i : 80.0 - 2.0 * (i - 8);
    s += std::to_string(i) + "," + std::to_string(0.5 * i) + "," + std::to_string(load) + "," +
         std::to_string(a) + "\n";
  }
  return s;
}
const std::string header = "time_s,opening_mm,load_N,a_mm\n";

std::string message_of(const std::string& path, const RecordReadOptions& o = {}) {
  try {
    read_test_records(path, o);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

bool contains(const std::string& s, const std::string& part) {
  return s.find(part) != std::string::npos;
}

} // namespace

TEST(TestRecordReader, OurNamesAndUnits) {
  TempFile f("plain.csv", header + clean_rows());
  const auto records = read_test_records(f.path());
  ASSERT_EQ(records.size(), 1u);
  const TestRecord& r = records[0];
  EXPECT_EQ(r.name, r.source.substr(r.source.find_last_of('/') + 1, r.name.size()));
  ASSERT_EQ(r.opening.size(), 20u);
  EXPECT_DOUBLE_EQ(r.opening[4], 2.0 * mm);
  EXPECT_DOUBLE_EQ(r.load[4], 40.0);
  EXPECT_DOUBLE_EQ(r.crack_length[0], 30 * mm);
  EXPECT_DOUBLE_EQ(r.time[3], 3.0);
  EXPECT_EQ(r.line[0], 2u);
  EXPECT_TRUE(r.delta_root.empty());
  // Readings change on rows 0, 8, 10, 12, ... 18: the rows between repeat a stale reading.
  const auto readings = crack_reading_rows(r);
  ASSERT_EQ(readings.size(), 7u);
  EXPECT_EQ(readings[1], 8u);
  ASSERT_EQ(r.cleaning.size(), 1u);
  EXPECT_TRUE(contains(r.cleaning[0], "13 of 20 rows repeat the crack reading"));
}

TEST(TestRecordReader, MachineHeadersThroughTheColumnMap) {
  std::string body = "Time (s),Extension (mm),Load (N),Crack length (mm),Clip gauge (mm),G_I\n";
  int i = 0;
  std::string rows = clean_rows();
  std::size_t p = 0;
  while ((p = rows.find('\n')) != std::string::npos) {
    body += rows.substr(0, p) + "," + std::to_string(0.1 * i++) + ",0\n";
    rows.erase(0, p + 1);
  }
  TempFile f("machine.csv", body);
  RecordReadOptions o;
  o.columns = RecordColumnMap::parse("time_s: Time (s), opening_mm: Extension (mm), load_N: Load "
                                     "(N), a_mm: Crack length (mm), delta_root_mm: Clip gauge (mm)",
                                     "test");
  const auto r = read_test_records(f.path(), o).at(0);
  ASSERT_EQ(r.delta_root.size(), 20u);
  EXPECT_DOUBLE_EQ(r.delta_root[5], 0.5 * mm);
  EXPECT_DOUBLE_EQ(r.opening[5], 2.5 * mm);
  // Without the map the reader names the header it looked for and the columns it found.
  const std::string m = message_of(f.path());
  EXPECT_TRUE(contains(m, ":1: no column 'opening_mm' for opening_mm (headers found: #1 'Time "
                          "(s)', #2 'Extension (mm)'"))
      << m;
  // It lists what it found and proposes no header of its own choosing (it used to suggest
  // 'opening_mm: Time (s)', the first header, which is wrong).
  EXPECT_FALSE(contains(m, "opening_mm: Time")) << m;
  EXPECT_TRUE(contains(m, "'opening_mm: <header>'")) << m;
}

TEST(TestRecordReader, ColumnMapErrors) {
  EXPECT_THROW(RecordColumnMap::parse("load: Force", "Test/Columns"), InputError);
  EXPECT_THROW(RecordColumnMap::parse("load_N Force", "Test/Columns"), InputError);
  EXPECT_THROW(RecordColumnMap::parse("load_N: Force, load_N: F", "Test/Columns"), InputError);
  EXPECT_THROW(RecordColumnMap::parse("load_N:", "Test/Columns"), InputError);
  EXPECT_TRUE(RecordColumnMap::parse("  ", "Test/Columns").file_header.empty());
}

TEST(TestRecordReader, RecordColumnSplitsReplicates) {
  std::string body = "record,time_s,opening_mm,load_N,a_mm\n";
  for (const char* label : {"A", "B"}) {
    std::string rows = clean_rows();
    std::size_t p = 0;
    while ((p = rows.find('\n')) != std::string::npos) {
      body += std::string(label) + "," + rows.substr(0, p) + "\n";
      rows.erase(0, p + 1);
    }
  }
  TempFile f("two.csv", body);
  const auto records = read_test_records(f.path());
  ASSERT_EQ(records.size(), 2u);
  EXPECT_EQ(records[1].name, "B");
  EXPECT_EQ(records[1].line[0], 22u);
}

TEST(TestRecordReader, CleansWhatRealMachinesWrite) {
  // Negative loads at the start, a duplicated time, an unload/reload segment, a small crack
  // step back and rows after the final drop, all in one record.
  std::string s = header;
  s += "0,0,-0.4,30\n";        // line 2: load-cell offset
  s += "1,0.1,-0.1,30\n";      // line 3
  s += "2,0.5,5,30\n";         // line 4
  s += "2,0.5,5,30\n";         // line 5: duplicated time
  for (int i = 3; i < 10; ++i) // lines 6-12
    s += std::to_string(i) + "," + std::to_string(0.5 * i) + "," + std::to_string(10.0 * i) + "," +
         std::to_string(i < 6 ? 30.0 : 30.0 + i - 5) + "\n";
  s += "10,3.0,30,34\n";   // line 13: unloading
  s += "11,1.0,10,34\n";   // line 14
  s += "12,4.4,85,34\n";   // line 15: reloading, still below the opening 4.5 of line 12
  s += "13,5.0,90,35\n";   // line 16: beyond: back on the envelope
  s += "14,5.5,88,34.8\n"; // line 17: crack reads 0.2 mm back (tracking noise)
  s += "15,6.0,86,36\n";   // line 18
  s += "16,6.5,10,36\n";   // line 19: final drop
  s += "17,6.6,2,36\n";    // line 20
  TempFile f("messy.csv", s);
  const auto r = read_test_records(f.path()).at(0);
  std::string all;
  for (const auto& c : r.cleaning)
    all += c + "\n";
  EXPECT_TRUE(contains(all, "2 row(s) with a negative load before the load first reached 0.05 of "
                            "its peak (lowest -0.4 N"))
      << all;
  EXPECT_TRUE(contains(all, "2 row(s) after the final drop (lines 19-20")) << all;
  EXPECT_TRUE(contains(all, "1 row(s) repeating the time of the row before dropped (first on "
                            "line 5"))
      << all;
  EXPECT_TRUE(contains(all, "1 unload/reload segment(s) dropped (first: lines 13-15)")) << all;
  EXPECT_TRUE(contains(all, "1 crack reading(s) stepping back (at most 0.2 mm")) << all;
  EXPECT_DOUBLE_EQ(r.load[0], 0.0);
  EXPECT_DOUBLE_EQ(r.load[1], 0.0);
  const std::vector<std::size_t> lines = {2, 3, 4, 6, 7, 8, 9, 10, 11, 12, 16, 17, 18};
  EXPECT_EQ(r.line, lines);
  EXPECT_DOUBLE_EQ(r.crack_length[11], 35 * mm); // the step back held at the longest reading
  for (std::size_t i = 1; i < r.opening.size(); ++i)
    EXPECT_GT(r.opening[i], r.opening[i - 1]) << "line " << r.line[i];
}

TEST(TestRecordReader, CrosheadStopAtTheEndIsDropped) {
  std::string s = header + clean_rows();
  s += "20,9.0,40,37\n21,9.2,39,37.5\n"; // lines 22-23: opening below 9.5 and never recovers
  TempFile f("stop.csv", s);
  const auto r = read_test_records(f.path()).at(0);
  EXPECT_EQ(r.line.back(), 21u);
  EXPECT_TRUE(contains(r.cleaning[0], "2 row(s) at the end where the opening never again exceeds "
                                      "its largest value (lines 22-23"))
      << r.cleaning[0];
  // A fall of less than 1 % of the opening is reading noise: kept.
  std::string jitter = header + clean_rows() + "20,9.46,40,37\n21,10,39,37.5\n";
  TempFile g("jitter.csv", jitter);
  const auto q = read_test_records(g.path()).at(0);
  EXPECT_EQ(q.line.back(), 23u);
  EXPECT_TRUE(contains(q.cleaning[0], "1 row(s) where the opening fell back by less than 0.01"))
      << q.cleaning[0];
}

// Every record that cannot be used: one line naming file:line and the reason.
TEST(TestRecordReader, DecreasingTime) {
  std::string s = header + clean_rows();
  s.replace(s.find("\n5,"), 3, "\n3,"); // line 7 goes back to t = 3 after t = 4
  TempFile f("time.csv", s);
  const std::string m = message_of(f.path());
  EXPECT_TRUE(contains(m, "time.csv:7: time_s = 3 is earlier than 4 on line 6")) << m;
}

TEST(TestRecordReader, CrackLengthGoingBack) {
  std::string s = header + clean_rows() + "20,10,40,33\n"; // line 22: 3 mm back of 36
  TempFile f("back.csv", s);
  const std::string m = message_of(f.path());
  EXPECT_TRUE(contains(m, "back.csv:22: a_mm = 33 is 3 mm shorter than the longest reading")) << m;
  // A larger tracking tolerance turns it into cleaning.
  RecordReadOptions o;
  o.crack_back_tolerance = 4 * mm;
  EXPECT_EQ(message_of(f.path(), o), "no error");
}

TEST(TestRecordReader, MissingColumn) {
  TempFile f("cols.csv", "time_s,opening_mm,load_N\n0,0,0\n1,1,1\n");
  RecordReadOptions o;
  o.crack_length = CrackLengthSource::measured;
  const std::string m = message_of(f.path(), o);
  EXPECT_TRUE(contains(m, "cols.csv:1: no column 'a_mm' for a_mm (headers found: #1 'time_s', "
                          "#2 'opening_mm', #3 'load_N'; text read as UTF-8 (detected)"))
      << m;
  TempFile g("noload.csv", "time_s,opening_mm,a_mm\n0,0,30\n1,1,31\n");
  const std::string n = message_of(g.path());
  EXPECT_TRUE(contains(n, "noload.csv:1: no column 'load_N' for load_N")) << n;
}

TEST(TestRecordReader, NaNCell) {
  std::string s = header + clean_rows();
  s.replace(s.find("\n6,3.0"), 6, "\n6,nan");
  TempFile f("nan.csv", s);
  const std::string m = message_of(f.path());
  EXPECT_TRUE(contains(m, "nan.csv:8:")) << m;
  EXPECT_TRUE(contains(m, "opening_mm")) << m;
}

TEST(TestRecordReader, NoCrackGrowth) {
  std::string s = header;
  for (int i = 0; i < 12; ++i)
    s +=
        std::to_string(i) + "," + std::to_string(0.5 * i) + "," + std::to_string(5.0 * i) + ",30\n";
  TempFile f("nogrowth.csv", s);
  const std::string m = message_of(f.path());
  EXPECT_TRUE(contains(m, "nogrowth.csv:13:")) << m;
  EXPECT_TRUE(contains(m, "no crack growth")) << m;
}

TEST(TestRecordReader, NegativeLoadAfterTheStart) {
  std::string s = header + clean_rows();
  s.replace(s.find("\n5,2.500000,50"), 14, "\n5,2.500000,-5");
  TempFile f("neg.csv", s);
  const std::string m = message_of(f.path());
  EXPECT_TRUE(contains(m, "neg.csv:7: load_N = -5 is negative after the test started")) << m;
}

TEST(TestRecordReader, TooFewRows) {
  TempFile f("short.csv", header + "0,0,0,30\n1,1,10,31\n2,2,20,32\n");
  const std::string m = message_of(f.path());
  EXPECT_TRUE(contains(m, "short.csv: record 'fb_")) << m;
  EXPECT_TRUE(contains(m, "has 3 rows after cleaning (lines 2-4)")) << m;
}

TEST(TestRecordReader, SharedRealRecords) {
  // The bundled records (data/dcb_records/README.md) read with the map their README gives; the
  // cleaning they need is the crack tracking stepping back by up to 0.5 mm and the crosshead stop.
  RecordReadOptions o;
  o.columns = RecordColumnMap::parse(
      "time_s: Time, opening_mm: Disp, load_N: Force, a_mm: CrackExt", "test");
  for (const char* name : {"DCB-01", "DCB-02", "DCB-03", "DCB-05"}) {
    const auto r =
        read_test_records(
            std::string(FIBERBRIDGE_DATA_DIR) + "/dcb_records/" + name + "_Toughness.csv", o)
            .at(0);
    EXPECT_EQ(r.name, std::string(name) + "_Toughness");
    EXPECT_GT(r.opening.size(), 150u) << name;
    EXPECT_GT(r.crack_length.back() - r.crack_length.front(), 40 * mm) << name;
    for (const auto& c : r.cleaning)
      std::printf("%s: %s\n", name, c.c_str());
  }
}
