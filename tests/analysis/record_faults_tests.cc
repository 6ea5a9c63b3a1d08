// What real lab records carry, injected into a shared real record (data/dcb_records/DCB-01):
// each fault class is read, named in the cleaning report with its row count, and, where the
// fix is safe, gives the plain record's values; what would give a wrong result is refused
// naming file:line (docs/design.md section 6).
#include "fiberbridge/analysis/record_reduction.h"
#include "fiberbridge/analysis/synthetic_record.h"
#include "fiberbridge/analysis/test_record.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/exported_table.h"
#include "fiberbridge/core/units.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

using namespace fiberbridge;
using namespace fiberbridge::analysis;
using units::mm;

namespace {

const std::string shared = std::string(FIBERBRIDGE_DATA_DIR) + "/dcb_records/DCB-01_Toughness.csv";
const std::string shared_map = "time_s: Time, opening_mm: Disp, load_N: Force, a_mm: CrackExt";

/// The shared record's rows as text cells (time_s, opening_mm, load_N, a_mm), 9 digits.
using Row = std::array<std::string, 4>;

std::string fmt(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.9g", v);
  return b;
}

std::vector<Row> raw_rows() {
  const ExportedTable t = ExportedTable::read(shared);
  const auto T = t.numeric(0), x = t.numeric(1), P = t.numeric(2), a = t.numeric(3);
  std::vector<Row> rows;
  for (std::size_t i = 0; i < T.size(); ++i)
    rows.push_back({fmt(T[i]), fmt(x[i]), fmt(P[i]), fmt(a[i])});
  return rows;
}

double value(const std::string& cell) {
  return std::stod(cell);
}

class TempFile {
public:
  TempFile(const std::string& name, const std::vector<Row>& rows)
      : path_(::testing::TempDir() + "fb_" + std::to_string(::getpid()) + "_" + name) {
    std::ofstream out(path_);
    out << "time_s,opening_mm,load_N,a_mm\n";
    for (const auto& r : rows)
      out << r[0] << "," << r[1] << "," << r[2] << "," << r[3] << "\n";
  }
  ~TempFile() { std::remove(path_.c_str()); }
  const std::string& path() const { return path_; }

private:
  std::string path_;
};

specimen::Specimen test_specimen() { // data/dcb_records/README.md
  auto s = specimen::Specimen::unknown();
  s.width = 25 * mm;
  s.height = 2 * 2.7 * mm; // both arms
  return s;
}

/// The shared record as the faulty files write it (9 digits), without a fault.
TestRecord plain();

std::string all(const std::vector<std::string>& cleaning) {
  std::string s;
  for (const auto& c : cleaning)
    s += c + "\n";
  return s;
}

bool contains(const std::string& s, const std::string& part) {
  return s.find(part) != std::string::npos;
}

std::string refusal(const std::string& path) {
  try {
    read_test_records(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

/// Line of row i in a TempFile (the header is line 1).
std::string line_of(std::size_t i) {
  return std::to_string(i + 2);
}

TestRecord plain() {
  TempFile f("plain.csv", raw_rows());
  return read_test_records(f.path()).at(0);
}

} // namespace

// The real case: an extensometer zeroed a little off, -0.00006 to -0.0002 mm in the
// first rows of a record reaching 30 mm, was refused. Noise around zero: set to 0.
TEST(RecordFaults, ZeroOffsetNegativesAreNoise) {
  auto rows = raw_rows();
  rows[0][1] = "-0.0002";
  rows.insert(rows.begin() + 1, Row{"16.3", "-0.00006", "0.1", rows[0][3]});
  TempFile f("zero_negatives.csv", rows);
  const auto r = read_test_records(f.path()).at(0);
  const std::string c = all(r.cleaning);
  EXPECT_TRUE(contains(c, "2 negative opening(s) (first on line 2, lowest -0.0002 mm")) << c;
  EXPECT_EQ(r.opening[0], 0.0);
  const auto p = plain();
  const auto R = reduce_record(r, test_specimen()), Rp = reduce_record(p, test_specimen());
  // Rows at zero opening add no work: the same R to round-off.
  EXPECT_NEAR(R.mbt.plateau, Rp.mbt.plateau, 1e-9 * Rp.mbt.plateau);
  EXPECT_NEAR(R.energy.plateau, Rp.energy.plateau, 1e-6 * Rp.energy.plateau);
}

// A negative opening far beyond noise that no zero offset explains is refused at its line.
TEST(RecordFaults, NegativeOpeningBeyondNoiseIsRefused) {
  auto rows = raw_rows();
  for (std::size_t i = 200; i < 205; ++i) // five rows: a single one would be a spike
    rows[i][1] = "-2";
  TempFile f("negative_opening.csv", rows);
  const std::string m = refusal(f.path());
  EXPECT_TRUE(contains(m, "negative_opening.csv:" + line_of(200) +
                              ": opening_mm = -2 is negative "
                              "beyond reading noise"))
      << m;
}

// An extensometer not zeroed before the test: every opening 0.3 mm low. The offset comes from
// the initial linear part extrapolated to zero load; on a record from a linear-elastic model
// (which starts at the origin) the openings come back as they were.
TEST(RecordFaults, OpeningZeroOffsetIsRemoved) {
  result::SimulationResult sim;
  sim.model = "closed-form beam";
  const double B = 25 * mm, h = 2.7 * mm, E = 30e9;
  for (double a = 35 * mm; a <= 80 * mm; a += 0.5 * mm) {
    const double C = 8 * a * a * a / (E * B * h * h * h), dC = 24 * a * a / (E * B * h * h * h);
    result::RCurvePoint q;
    q.a = a;
    q.load = std::sqrt(2 * B * 500 / dC);
    q.load_point_opening = C * q.load;
    sim.rcurve.push_back(q);
  }
  SyntheticRecordOptions o;
  o.load_noise = 0;
  o.opening_noise = 0;
  o.crack_reading_noise = 0;
  const TestRecord clean = make_synthetic_record(sim, o, "offset");
  TestRecord shifted = clean;
  for (double& x : shifted.opening)
    x -= 0.3 * mm;
  const std::string path = ::testing::TempDir() + "fb_" + std::to_string(::getpid()) + "_off.csv";
  write_test_record_csv(path, shifted, {});
  const auto r = read_test_records(path).at(0);
  std::remove(path.c_str());
  const std::string c = all(r.cleaning);
  EXPECT_TRUE(contains(c, "Opening zero offset -0.3")) << c;
  ASSERT_EQ(r.opening.size(), clean.opening.size());
  // The load is linear in the opening before growth: the fit is exact to the 10 written digits.
  for (std::size_t i = 0; i < r.opening.size(); ++i)
    ASSERT_NEAR(r.opening[i], clean.opening[i], 1e-6 * mm) << "row " << i;
}

// Crack tracking writes NaN, leaves cells empty, or writes a dropout code (-999, or 0 after
// positive readings) when it loses the tip: rows without a reading, kept for load and opening.
TEST(RecordFaults, MissingCrackReadingsAreRowsWithoutAReading) {
  const auto p = plain();
  auto rows = raw_rows();
  // Rows that repeat the reading before them (stale readings): blanking them loses nothing.
  std::vector<std::size_t> stale;
  for (std::size_t i = 1; i + 1 < rows.size() && stale.size() < 4; i += 5)
    if (rows[i][3] == rows[i - 1][3] && rows[i + 1][3] == rows[i][3])
      stale.push_back(i);
  ASSERT_EQ(stale.size(), 4u);
  rows[stale[0]][3] = "NaN";
  rows[stale[1]][3] = "";
  rows[stale[2]][3] = "-999";
  rows[stale[3]][3] = "0";
  TempFile f("missing_crack.csv", rows);
  const auto r = read_test_records(f.path()).at(0);
  const std::string c = all(r.cleaning);
  EXPECT_TRUE(contains(c, "4 row(s) without a crack reading (2 empty or NaN cell(s); 2 dropout "
                          "value(s) <= 0 or 999..., first -999 on line " +
                              line_of(stale[2])))
      << c;
  ASSERT_EQ(r.crack_length.size(), p.crack_length.size());
  for (std::size_t k : stale)
    EXPECT_TRUE(std::isnan(r.crack_length[k])) << "row " << k;
  EXPECT_EQ(crack_reading_rows(r), crack_reading_rows(p));
  // The same readings, loads and openings: the same R(a).
  const auto R = reduce_record(r, test_specimen()), Rp = reduce_record(p, test_specimen());
  ASSERT_EQ(R.R_MBT.size(), Rp.R_MBT.size());
  for (std::size_t i = 0; i < R.R_MBT.size(); ++i) {
    EXPECT_NEAR(R.R_MBT[i], Rp.R_MBT[i], 1e-9 * Rp.R_MBT[i]);
    EXPECT_NEAR(R.R_energy[i], Rp.R_energy[i], 1e-9 * std::abs(Rp.R_energy[i]));
  }
}

// The second real case: tracking lost for the last 55 rows while the load is still
// about 70 % of its peak. The rows are kept (the energy needs them) and the block is named.
TEST(RecordFaults, TrailingBlockWithoutReadingsIsKept) {
  const auto p = plain();
  auto rows = raw_rows();
  const std::size_t n = rows.size();
  for (std::size_t i = n - 55; i < n; ++i)
    rows[i][3] = "nan";
  TempFile f("lost_tracking.csv", rows);
  const auto r = read_test_records(f.path()).at(0);
  const std::string c = all(r.cleaning);
  EXPECT_EQ(r.opening.size(), p.opening.size());
  EXPECT_TRUE(contains(c, "The last 55 row(s) (lines " + line_of(n - 55) + "-" + line_of(n - 1) +
                              ") have no crack reading while the load is still up to"))
      << c;
  EXPECT_TRUE(std::isnan(r.crack_length.back()));
  // Every reading before the block is the plain record's.
  const auto readings = crack_reading_rows(r);
  ASSERT_FALSE(readings.empty());
  EXPECT_LT(readings.back(), n - 55);
  for (std::size_t k : readings)
    EXPECT_EQ(r.crack_length[k], p.crack_length[k]);
}

// A single-row glitch of the load cell (here +50 %) is replaced by its neighbours' mean.
TEST(RecordFaults, LoadSpikeIsReplaced) {
  const auto p = plain();
  auto rows = raw_rows();
  const std::size_t k = 150;
  rows[k][2] = fmt(1.5 * value(rows[k][2]));
  TempFile f("spike.csv", rows);
  const auto r = read_test_records(f.path()).at(0);
  const std::string c = all(r.cleaning);
  EXPECT_TRUE(contains(c, "1 single-row spike(s) in load_N (first on line " + line_of(k))) << c;
  ASSERT_EQ(r.load.size(), p.load.size());
  const double peak = *std::max_element(p.load.begin(), p.load.end());
  // The neighbours' mean differs from the true value by the load's curvature over two rows and
  // its noise: well under 2 % of the peak on this record (a 1 s sampling at 5 mm/min).
  EXPECT_NEAR(r.load[k], p.load[k], 0.02 * peak);
  for (std::size_t i = 0; i < r.load.size(); ++i)
    if (i != k)
      ASSERT_EQ(r.load[i], p.load[i]) << "row " << i;
}

// The real crack jumps of the record (load drops that stay down) are not spikes.
TEST(RecordFaults, CrackJumpLoadDropsAreNotSpikes) {
  for (const char* name : {"DCB-01", "DCB-02", "DCB-03", "DCB-05"}) {
    RecordReadOptions o;
    o.columns = RecordColumnMap::parse(shared_map, "test");
    const auto r =
        read_test_records(
            std::string(FIBERBRIDGE_DATA_DIR) + "/dcb_records/" + name + "_Toughness.csv", o)
            .at(0);
    EXPECT_FALSE(contains(all(r.cleaning), "spike")) << name << ":\n" << all(r.cleaning);
    EXPECT_FALSE(contains(all(r.cleaning), "zero offset")) << name << ":\n" << all(r.cleaning);
  }
}

// A pause: the machine held, the logger repeated its last row with advancing time (and once
// with the same time). Dropped and named; the record is the plain one.
TEST(RecordFaults, PauseWithRepeatedRowsIsDropped) {
  const auto p = plain();
  auto rows = raw_rows();
  const std::size_t k = 120;
  const double t = value(rows[k][0]);
  std::vector<Row> pause;
  for (int j = 1; j <= 5; ++j)
    pause.push_back({fmt(t + 0.1 * j), rows[k][1], rows[k][2], rows[k][3]});
  pause.push_back(pause.back()); // the same time twice
  rows.insert(rows.begin() + static_cast<std::ptrdiff_t>(k + 1), pause.begin(), pause.end());
  TempFile f("pause.csv", rows);
  const auto r = read_test_records(f.path()).at(0);
  const std::string c = all(r.cleaning);
  EXPECT_TRUE(contains(c, "1 row(s) repeating the time of the row before dropped")) << c;
  EXPECT_TRUE(contains(c, "5 row(s) repeating every channel of the row before while the time "
                          "advanced (a pause"))
      << c;
  EXPECT_EQ(r.opening, p.opening);
  EXPECT_EQ(r.load, p.load);
  EXPECT_EQ(r.crack_length, p.crack_length);
}

// The opening channel re-zeroed mid-test (the operator pressed "zero extension"): it restarts
// at 0 while the load carries on. Continued from before by one row's increment.
TEST(RecordFaults, ReZeroedOpeningIsContinued) {
  const auto p = plain();
  auto rows = raw_rows();
  const std::size_t k = 180;
  const double at_k = value(rows[k][1]);
  for (std::size_t i = k; i < rows.size(); ++i)
    rows[i][1] = fmt(value(rows[i][1]) - at_k);
  TempFile f("rezero.csv", rows);
  const auto r = read_test_records(f.path()).at(0);
  const std::string c = all(r.cleaning);
  EXPECT_TRUE(
      contains(c, "1 re-zeroed opening_mm channel(s) continued from before (on line " + line_of(k)))
      << c;
  ASSERT_EQ(r.opening.size(), p.opening.size());
  // The shift assumes the increment of the row before; the true one differs by the crosshead's
  // reading noise and its rate change over one row: under 0.05 mm on this record.
  for (std::size_t i = 0; i < r.opening.size(); ++i)
    ASSERT_NEAR(r.opening[i], p.opening[i], 0.05 * mm) << "row " << i;
  const auto R = reduce_record(r, test_specimen()), Rp = reduce_record(p, test_specimen());
  // 0.05 mm on openings of 10-30 mm changes the compliance by < 0.5 %, MBT G by about as much.
  EXPECT_NEAR(R.mbt.plateau, Rp.mbt.plateau, 0.01 * Rp.mbt.plateau);
}

// The load cell tared mid-test: the load restarts from ~0 while the opening carries on. A
// fracture looks the same to a continuity argument, so this is refused at its line.
TEST(RecordFaults, ReZeroedLoadIsRefused) {
  auto rows = raw_rows();
  const std::size_t k = 40; // on the rise, before the peak
  const double at_k = value(rows[k][2]);
  for (std::size_t i = k; i < rows.size(); ++i)
    rows[i][2] = fmt(value(rows[i][2]) - at_k + 0.01);
  TempFile f("tare.csv", rows);
  const std::string m = refusal(f.path());
  EXPECT_TRUE(contains(m, "tare.csv:" + line_of(k) + ": load_N falls from")) << m;
  EXPECT_TRUE(contains(m, "re-zeroed (tared) mid-test")) << m;
}

// A short dropout of the load channel to 0 (a loose connector for three rows) is dropped.
TEST(RecordFaults, LoadDropoutIsDropped) {
  const auto p = plain();
  auto rows = raw_rows();
  for (std::size_t i = 200; i < 203; ++i)
    rows[i][2] = "0";
  TempFile f("dropout.csv", rows);
  const auto r = read_test_records(f.path()).at(0);
  const std::string c = all(r.cleaning);
  EXPECT_TRUE(contains(c, "1 dropout(s) of load_N to ~0 for at most 10 rows (3 rows, first lines " +
                              line_of(200) + "-" + line_of(202)))
      << c;
  EXPECT_EQ(r.opening.size(), p.opening.size() - 3);
}

// Rows missing the load or the opening are dropped and named.
TEST(RecordFaults, RowsWithoutLoadOrOpeningAreDropped) {
  const auto p = plain();
  auto rows = raw_rows();
  rows[100][2] = "";
  rows[101][1] = "NaN";
  TempFile f("missing_load.csv", rows);
  const auto r = read_test_records(f.path()).at(0);
  EXPECT_TRUE(contains(all(r.cleaning), "2 row(s) with an empty or NaN time, load or opening cell "
                                        "(first on line " +
                                            line_of(100)))
      << all(r.cleaning);
  EXPECT_EQ(r.opening.size(), p.opening.size() - 2);
}

// A tracking spike: one reading 5 mm beyond its neighbours, which agree. No reading there
// (it used to refuse the record: the next reading went back 5 mm).
TEST(RecordFaults, CrackSpikeIsNoReading) {
  auto rows = raw_rows();
  std::size_t k = 100;
  while (rows[k][3] == rows[k - 1][3] || rows[k + 1][3] != rows[k][3])
    ++k; // a new reading held for at least two rows
  std::size_t end = k;
  while (rows[end][3] == rows[k][3])
    ++end;
  const std::string spiked = fmt(value(rows[k][3]) + 5);
  for (std::size_t i = k; i < end; ++i)
    rows[i][3] = spiked;
  TempFile f("crack_spike.csv", rows);
  const auto r = read_test_records(f.path()).at(0);
  EXPECT_TRUE(contains(all(r.cleaning), "1 crack reading spike(s) (first on line " + line_of(k)))
      << all(r.cleaning);
  EXPECT_TRUE(std::isnan(r.crack_length[k]));
}

// A crack column that starts at 0 is the crack extension, not the length from the load line:
// read as a length it would give a wrong R, so it is refused (a 0 after positive readings is a
// tracker's dropout, MissingCrackReadingsAreRowsWithoutAReading).
TEST(RecordFaults, CrackExtensionColumnIsRefused) {
  auto rows = raw_rows();
  const double a0 = value(rows[0][3]);
  for (auto& row : rows)
    row[3] = fmt(value(row[3]) - a0);
  TempFile f("extension.csv", rows);
  const std::string m = refusal(f.path());
  EXPECT_TRUE(contains(m, "extension.csv:2: a_mm = 0 before any positive crack reading")) << m;
}

// What must be refused: time going back, a crack going back beyond the tolerance, no growth.
TEST(RecordFaults, WhatWouldGiveAWrongResultIsRefused) {
  {
    auto rows = raw_rows();
    rows[50][0] = fmt(value(rows[48][0]));
    TempFile f("time_back.csv", rows);
    const std::string m = refusal(f.path());
    EXPECT_TRUE(contains(m, "time_back.csv:" + line_of(50) + ": time_s = ")) << m;
    EXPECT_TRUE(contains(m, "a record must be in time order")) << m;
  }
  {
    auto rows = raw_rows();
    for (std::size_t i = 300; i < rows.size(); ++i)
      rows[i][3] = fmt(value(rows[i][3]) - 3);
    TempFile f("crack_back.csv", rows);
    const std::string m = refusal(f.path());
    EXPECT_TRUE(contains(m, "crack_back.csv:" + line_of(300) + ": a_mm = ")) << m;
    EXPECT_TRUE(contains(m, "tracking tolerance of 1 mm")) << m;
  }
  {
    auto rows = raw_rows();
    for (auto& row : rows)
      row[3] = rows[0][3];
    rows[10][3] = "";
    TempFile f("no_growth.csv", rows);
    const std::string m = refusal(f.path());
    EXPECT_TRUE(contains(m, "no crack growth, so no R curve")) << m;
  }
}

// An absolute crosshead column (the position, 112 mm at the start, never zeroed): the zero
// offset is removed, and the noise band is then a fraction of the openings measured from that
// zero, not of the 112 mm position (issue 42: a band ten times too wide passed real negatives
// as noise). Five rows 0.08 mm below zero mid-test are beyond the band (1e-3 of ~25 mm) and
// refused; with the band taken before the shift (1e-3 of ~137 mm) they were set to 0.
TEST(RecordFaults, NoiseBandIsTakenAfterTheZeroOffset) {
  auto rows = raw_rows();
  for (auto& r : rows)
    r[1] = fmt(value(r[1]) + 112);
  TempFile f("absolute.csv", rows);
  const auto r = read_test_records(f.path()).at(0);
  const std::string c = all(r.cleaning);
  EXPECT_TRUE(contains(c, "Opening zero offset 112")) << c;
  const auto p = plain();
  ASSERT_EQ(r.opening.size(), p.opening.size());
  for (std::size_t i = 0; i < r.opening.size(); ++i)
    if (p.opening[i] > 0.2 * mm)
      ASSERT_NEAR(r.opening[i], p.opening[i], 0.2 * mm) << "row " << i;

  const double x0 = value(rows[0][1]) - r.opening[0]; // where the reader put the zero
  for (std::size_t i = 200; i < 205; ++i)
    rows[i][1] = fmt(x0 - 0.08);
  TempFile g("absolute_negative.csv", rows);
  const std::string m = refusal(g.path());
  EXPECT_TRUE(contains(m, "is negative beyond reading noise")) << m;
  EXPECT_TRUE(contains(m, "after removing the zero offset 112")) << m;
}

// A script's arrays (the Python module's records in memory, clean_test_record) go through the
// file's cleaning: the same faults injected give the same record, value for value, and the same
// sentences; only the line numbers differ (a file's line is its row + 2, an array's row + 1).
TEST(RecordFaults, ArraysInMemoryAreCleanedAsTheirFile) {
  auto rows = raw_rows();
  rows[150][2] = fmt(1.5 * value(rows[150][2])); // a load spike
  rows[200][3] = "-999";                         // a crack tracker's dropout code
  TempFile f("arrays.csv", rows);
  const TestRecord from_file = read_test_records(f.path()).at(0);
  TestRecord given;
  given.name = "S1";
  given.source = "arrays of S1";
  for (const auto& r : rows) {
    given.time.push_back(value(r[0]));
    given.opening.push_back(value(r[1]) * mm);
    given.load.push_back(value(r[2]));
    given.crack_length.push_back(value(r[3]) * mm);
  }
  const TestRecord from_arrays = clean_test_record(given);
  EXPECT_EQ(from_arrays.name, "S1");
  EXPECT_EQ(from_arrays.source, "arrays of S1");
  ASSERT_EQ(from_arrays.load.size(), from_file.load.size());
  for (std::size_t i = 0; i < from_file.load.size(); ++i) {
    ASSERT_EQ(from_arrays.line[i] + 1, from_file.line[i]) << "row " << i;
    ASSERT_DOUBLE_EQ(from_arrays.time[i], from_file.time[i]) << "row " << i;
    ASSERT_DOUBLE_EQ(from_arrays.opening[i], from_file.opening[i]) << "row " << i;
    ASSERT_DOUBLE_EQ(from_arrays.load[i], from_file.load[i]) << "row " << i;
    ASSERT_EQ(std::isnan(from_arrays.crack_length[i]), std::isnan(from_file.crack_length[i]));
    if (!std::isnan(from_file.crack_length[i]))
      ASSERT_DOUBLE_EQ(from_arrays.crack_length[i], from_file.crack_length[i]) << "row " << i;
  }
  const std::string c = all(from_arrays.cleaning);
  EXPECT_EQ(from_arrays.cleaning.size(), from_file.cleaning.size()) << c;
  EXPECT_TRUE(contains(c, "single-row spike(s) in load_N (first on line 151,")) << c;
  EXPECT_TRUE(contains(c, "dropout")) << c;
}

TEST(RecordFaults, ArraysOfDifferentLengthsOrWithoutCrackWhenMeasuredAreRefused) {
  TestRecord given;
  given.name = "S1";
  given.source = "arrays of S1";
  given.opening = {0, 1e-3, 2e-3};
  given.load = {0, 10};
  const auto refused = [](const TestRecord& g, const RecordReadOptions& o) -> std::string {
    try {
      clean_test_record(g, o);
    } catch (const InputError& e) {
      return e.what();
    }
    return "no error";
  };
  EXPECT_EQ(refused(given, {}), "arrays of S1: opening_mm has 3 values and load_N 2; expected one "
                                "of each per row");
  given.load = {0, 10, 20};
  given.crack_length = {0.03, 0.031};
  EXPECT_TRUE(contains(refused(given, {}), "arrays of S1: a_mm has 2 values for 3 rows"));
  given.crack_length.clear();
  RecordReadOptions measured;
  measured.crack_length = CrackLengthSource::measured;
  EXPECT_TRUE(contains(refused(given, measured), "arrays of S1: no a_mm column"));
  // Three rows pass the columns' checks and are then refused as a file of three rows is.
  EXPECT_TRUE(contains(refused(given, {}), "arrays of S1")) << refused(given, {});
}
