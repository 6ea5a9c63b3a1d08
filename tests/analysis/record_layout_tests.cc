// Machine exports of a shared real record (data/dcb_records/DCB-01) read back as the plain file:
// each layout a testing machine writes (Bluehill, testXpert, MTS, tab with units in the header,
// a spreadsheet with units in the header) gives the same rows to the round-off of the written
// digits and the same R(a); units are converted; the column map names headers with or without
// their unit (docs/design.md section 6).
#include "fiberbridge/analysis/record_reduction.h"
#include "fiberbridge/analysis/test_record.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/exported_table.h"
#include "fiberbridge/core/unit_parse.h"
#include "fiberbridge/core/units.h"

#include "encoded_text.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <string>
#include <unistd.h>
#include <vector>

using namespace fiberbridge;
using namespace fiberbridge::analysis;
using units::mm;

namespace {

const std::string shared = std::string(FIBERBRIDGE_DATA_DIR) + "/dcb_records/DCB-01_Toughness.csv";
const std::string shared_map = "time_s: Time, opening_mm: Disp, load_N: Force, a_mm: CrackExt";
constexpr double lbf = 4.4482216152605, inch = 25.4; // N, mm (exact by definition)

/// The raw columns of the shared record as written (s, mm, N, mm).
struct Raw {
  std::vector<double> t, x, P, a;
};

Raw raw_record() {
  const ExportedTable t = ExportedTable::read(shared);
  return {t.numeric(0), t.numeric(1), t.numeric(2), t.numeric(3)};
}

/// 9 significant digits, with a decimal comma and thousands separators on request.
std::string fmt(double v, char decimal = '.', bool thousands = false) {
  char b[64];
  std::snprintf(b, sizeof b, thousands ? "%.3f" : "%.9g", v);
  std::string s = b;
  if (thousands) {
    const auto dot = s.find('.');
    const std::size_t digits0 = s[0] == '-' ? 1 : 0;
    for (std::ptrdiff_t k = static_cast<std::ptrdiff_t>(dot) - 3;
         k > static_cast<std::ptrdiff_t>(digits0); k -= 3)
      s.insert(static_cast<std::size_t>(k), ",");
  }
  if (decimal == ',')
    for (auto& c : s)
      if (c == '.')
        c = ',';
  return s;
}

class TempFile {
public:
  TempFile(const std::string& name, const std::string& content)
      : path_(::testing::TempDir() + "fb_" + std::to_string(::getpid()) + "_" + name) {
    std::ofstream(path_, std::ios::binary) << content;
  }
  ~TempFile() { std::remove(path_.c_str()); }
  const std::string& path() const { return path_; }

private:
  std::string path_;
};

struct Layout {
  const char* name;
  std::string map;
  std::function<std::string(const Raw&)> write;
};

/// Instron Bluehill 2 raw data: `Label : name,"value"` preamble, a blank line, the header and a
/// units row, every cell quoted; here the time in ms with thousands separators and the load in kN.
std::string bluehill(const Raw& r) {
  std::string s = "Text Inputs : Specimen label,\"DCB-01\"\r\nGeneral : Start Date,13/11/2018 5:14 "
                  "PM\r\n\r\n\"Time\",\"Extension\",\"Load\",\"Crack length\"\r\n"
                  "\"(ms)\",\"(mm)\",\"(kN)\",\"(mm)\"\r\n";
  for (std::size_t i = 0; i < r.t.size(); ++i)
    s += "\"" + fmt(r.t[i] * 1e3, '.', true) + "\",\"" + fmt(r.x[i]) + "\",\"" + fmt(r.P[i] / 1e3) +
         "\",\"" + fmt(r.a[i]) + "\"\r\n";
  return s;
}

/// ZwickRoell testXpert ASCII export: `Name : value` lines, semicolons, decimal comma, a units row.
std::string testxpert(const Raw& r) {
  std::string s = "Prüfer : Labor 2\nProbe : DCB-01\nBreite : 25 mm\n\n"
                  "Prüfzeit;Standardweg;Standardkraft;Risslänge\ns;mm;N;mm\n";
  for (std::size_t i = 0; i < r.t.size(); ++i)
    s += fmt(r.t[i], ',') + ";" + fmt(r.x[i], ',') + ";" + fmt(r.P[i], ',') + ";" +
         fmt(r.a[i], ',') + "\n";
  return s;
}

/// Tab-separated with units in the header and a "Raw Data" marker; minutes, inches, lbf.
std::string tabbed(const Raw& r) {
  std::string s =
      "Test\tDCB mode I\nRaw Data\nTime [min]\tExtension [in]\tLoad [lbf]\tCrack [in]\n";
  for (std::size_t i = 0; i < r.t.size(); ++i)
    s += fmt(r.t[i] / 60) + "\t" + fmt(r.x[i] / inch) + "\t" + fmt(r.P[i] / lbf) + "\t" +
         fmt(r.a[i] / inch) + "\n";
  return s;
}

/// MTS 793 MPT specimen data: the format line, blank-separated columns with a units row, the
/// header repeated at each buffer; the opening in metres.
std::string mts(const Raw& r) {
  const std::string head =
      "Time      Crosshead   Load     Crack\n(s)       (m)         (N)      (mm)\n";
  std::string s = "MTS793|MPT|ENU|1|0|.|/|:|1|0|0|A\nData Acquisition\n" + head;
  for (std::size_t i = 0; i < r.t.size(); ++i) {
    if (i == r.t.size() / 2)
      s += head; // the next buffer
    s += fmt(r.t[i]) + "   " + fmt(r.x[i] * 1e-3) + "   " + fmt(r.P[i]) + "  " + fmt(r.a[i]) + "\n";
  }
  return s;
}

/// A spreadsheet's CSV with units in the header, mapped without the units (the case).
std::string spreadsheet(const Raw& r) {
  std::string s = "\xEF\xBB\xBFTime (s),Extension (mm),Load (N),Crack length (mm)\n";
  for (std::size_t i = 0; i < r.t.size(); ++i)
    s += fmt(r.t[i]) + "," + fmt(r.x[i]) + "," + fmt(r.P[i]) + "," + fmt(r.a[i]) + "\n";
  return s;
}

using test_support::encoded;

/// Bluehill on a Polish Windows: the Bluehill layout with Polish headers, in windows-1250
/// ("Obciążenie": ą and ż are 0xB9 and 0xBF, which windows-1252 reads as '¹' and '¿').
std::string bluehill_cp1250(const Raw& r) {
  std::string s = "Dane tekstowe : Etykieta próbki,\"DCB-01\"\r\nOgólne : Data rozpoczęcia,"
                  "13.11.2018 17:14\r\n\r\n\"Czas\",\"Wydłużenie\",\"Obciążenie\",\"Długość "
                  "pęknięcia\"\r\n\"(s)\",\"(mm)\",\"(N)\",\"(mm)\"\r\n";
  for (std::size_t i = 0; i < r.t.size(); ++i)
    s += "\"" + fmt(r.t[i]) + "\",\"" + fmt(r.x[i]) + "\",\"" + fmt(r.P[i]) + "\",\"" +
         fmt(r.a[i]) + "\"\r\n";
  return encoded(s, "CP1250");
}

/// Shimadzu Trapezium in Japanese: a quoted CSV with a title block, Japanese headers and a
/// units row, in Shift-JIS (CP932, what Japanese Windows writes).
std::string trapezium_sjis(const Raw& r) {
  std::string s = "\"試験名\",\"DCB-01\"\r\n\"試験日\",\"2018/11/13\"\r\n\r\n"
                  "\"時間\",\"ストローク\",\"試験力\",\"き裂長さ\"\r\n\"sec\",\"mm\",\"N\","
                  "\"mm\"\r\n";
  for (std::size_t i = 0; i < r.t.size(); ++i)
    s += fmt(r.t[i]) + "," + fmt(r.x[i]) + "," + fmt(r.P[i]) + "," + fmt(r.a[i]) + "\r\n";
  return encoded(s, "CP932");
}

/// MTS 793 MPT specimen.dat with two Data Acquisition blocks (normal for MPT: one per
/// acquisition process of the procedure), each with its title, a time stamp and the header.
std::string mpt_two_blocks(const Raw& r) {
  const std::string head =
      "Time      Crosshead   Load     Crack\n(s)       (m)         (N)      (mm)\n";
  std::string s = "MTS793|MPT|ENU|1|0|.|/|:|1|0|0|A\nData Acquisition\n"
                  "Time: 0 Sec 13.11.2018 17:14:02\n" +
                  head;
  for (std::size_t i = 0; i < r.t.size(); ++i) {
    if (i == r.t.size() / 3)
      s += "\nData Acquisition\nTime: " + fmt(r.t[i]) + " Sec 13.11.2018 17:20:11\n" + head;
    s += fmt(r.t[i]) + "   " + fmt(r.x[i] * 1e-3) + "   " + fmt(r.P[i]) + "  " + fmt(r.a[i]) + "\n";
  }
  return s;
}

/// Bluehill's per-specimen blocks: "Specimen 1" over its header and rows, then "Specimen 2"
/// (here the same rows again, as a second specimen). The first record reads as the plain file.
std::string bluehill_stacked(const Raw& r) {
  std::string s = "\"Sample ID\",\"DCB series\"\r\n";
  for (int specimen = 1; specimen <= 2; ++specimen) {
    s += "\r\n\"Specimen " + std::to_string(specimen) +
         "\"\r\n\"Time\",\"Extension\",\"Load\",\"Crack length\"\r\n\"(s)\",\"(mm)\",\"(N)\","
         "\"(mm)\"\r\n";
    for (std::size_t i = 0; i < r.t.size(); ++i)
      s += "\"" + fmt(r.t[i]) + "\",\"" + fmt(r.x[i]) + "\",\"" + fmt(r.P[i]) + "\",\"" +
           fmt(r.a[i]) + "\"\r\n";
  }
  return s;
}

/// Bluehill 3 "Unicode" export without a byte-order mark: UTF-16LE, tab-separated.
std::string utf16_without_bom(const Raw& r) {
  std::string s = "Time (s)\tExtension (mm)\tLoad (N)\tCrack length (mm)\r\n";
  for (std::size_t i = 0; i < r.t.size(); ++i)
    s += fmt(r.t[i]) + "\t" + fmt(r.x[i]) + "\t" + fmt(r.P[i]) + "\t" + fmt(r.a[i]) + "\r\n";
  return encoded(s, "UTF-16LE");
}

const Layout layouts[] = {
    {"bluehill", "time_s: Time, opening_mm: Extension, load_N: Load, a_mm: Crack length", bluehill},
    {"testxpert",
     "time_s: Prüfzeit, opening_mm: Standardweg (mm), load_N: Standardkraft, a_mm: Risslänge",
     testxpert},
    {"tabbed", "time_s: Time, opening_mm: Extension, load_N: Load, a_mm: Crack", tabbed},
    {"mts", "time_s: Time, opening_mm: Crosshead, load_N: Load, a_mm: Crack", mts},
    {"spreadsheet", "time_s: Time, opening_mm: Extension, load_N: Load, a_mm: Crack length",
     spreadsheet},
    {"bluehill_cp1250",
     "time_s: Czas, opening_mm: Wydłużenie, load_N: Obciążenie, a_mm: Długość pęknięcia",
     bluehill_cp1250},
    {"trapezium_sjis", "time_s: 時間, opening_mm: ストローク, load_N: 試験力, a_mm: き裂長さ",
     trapezium_sjis},
    {"trapezium_sjis_by_position", "time_s: #1, opening_mm: #2, load_N: #3, a_mm: #4",
     trapezium_sjis},
    {"mpt_two_blocks", "time_s: Time, opening_mm: Crosshead, load_N: Load, a_mm: Crack",
     mpt_two_blocks},
    {"bluehill_stacked", "time_s: Time, opening_mm: Extension, load_N: Load, a_mm: Crack length",
     bluehill_stacked},
    {"utf16_without_bom", "time_s: Time, opening_mm: Extension, load_N: Load, a_mm: Crack length",
     utf16_without_bom}};

RecordReadOptions with_map(const std::string& map) {
  RecordReadOptions o;
  o.columns = RecordColumnMap::parse(map, "test");
  return o;
}

specimen::Specimen test_specimen() { // data/dcb_records/README.md
  auto s = specimen::Specimen::unknown();
  s.width = 25 * mm;
  s.height = 2 * 2.7 * mm; // both arms
  return s;
}

/// |x - y| <= rel * scale element by element, scale the largest |x|.
void expect_same(const std::vector<double>& x, const std::vector<double>& y, double rel,
                 const std::string& what) {
  ASSERT_EQ(x.size(), y.size()) << what;
  double scale = 0;
  for (double v : x)
    scale = std::max(scale, std::abs(v));
  for (std::size_t i = 0; i < x.size(); ++i)
    ASSERT_NEAR(x[i], y[i], rel * scale) << what << " row " << i;
}

std::string all(const std::vector<std::string>& cleaning) {
  std::string s;
  for (const auto& c : cleaning)
    s += c + "\n";
  return s;
}

bool contains(const std::string& s, const std::string& part) {
  return s.find(part) != std::string::npos;
}

} // namespace

TEST(RecordLayouts, EachExportReadsAsThePlainFile) {
  const Raw raw = raw_record();
  const TestRecord plain = read_test_records(shared, with_map(shared_map)).at(0);
  const ReducedRecord plain_R = reduce_record(plain, test_specimen());
  for (const auto& layout : layouts) {
    SCOPED_TRACE(layout.name);
    TempFile f(std::string(layout.name) + ".csv", layout.write(raw));
    const TestRecord r = read_test_records(f.path(), with_map(layout.map)).at(0);
    std::printf("%s: %s\n", layout.name, all(r.cleaning).c_str());
    // 9 significant digits written (fmt), and unit factors applied in double: the values agree
    // to 1e-8 of each channel's largest value; 1e-7 leaves room for the ms/min/inch/lbf products.
    expect_same(r.time, plain.time, 1e-7, "time");
    expect_same(r.opening, plain.opening, 1e-7, "opening");
    expect_same(r.load, plain.load, 1e-7, "load");
    expect_same(r.crack_length, plain.crack_length, 1e-7, "crack length");
    const ReducedRecord R = reduce_record(r, test_specimen());
    // R(a) from values equal to 1e-7: the energy slope over a window of ~10 readings and the
    // beam-theory fits amplify relative input changes by at most ~100 here, so 1e-5.
    expect_same(R.a, plain_R.a, 1e-7, "a");
    expect_same(R.R_energy, plain_R.R_energy, 1e-5, "R_energy");
    expect_same(R.R_MBT, plain_R.R_MBT, 1e-5, "R_MBT");
    expect_same(R.R_CC, plain_R.R_CC, 1e-5, "R_CC");
  }
}

TEST(RecordLayouts, DetectionNamesWhatItFound) {
  const Raw raw = raw_record();
  const auto layout_of = [&](const std::string& text) { return detect_table_layout(text, "x"); };
  const TableLayout b = layout_of(bluehill(raw));
  EXPECT_EQ(b.delimiter, ',');
  EXPECT_EQ(b.decimal, '.');
  EXPECT_EQ(b.header_line, 4u);
  EXPECT_EQ(b.units_line, 5u);
  EXPECT_EQ(b.preamble_lines, 2u);
  const TableLayout z = layout_of(testxpert(raw));
  EXPECT_EQ(z.delimiter, ';');
  EXPECT_EQ(z.decimal, ',');
  EXPECT_EQ(z.header_line, 5u);
  EXPECT_EQ(z.units_line, 6u);
  const TableLayout t = layout_of(tabbed(raw));
  EXPECT_EQ(t.delimiter, '\t');
  EXPECT_EQ(t.units_line, 0u);
  EXPECT_EQ(t.header_line, 3u);
  const TableLayout m = layout_of(mts(raw));
  EXPECT_EQ(m.delimiter, ' ');
  EXPECT_EQ(m.header_line, 3u);
  const ExportedTable mt = ExportedTable::parse(mts(raw), "mts");
  EXPECT_EQ(mt.layout().repeated_headers, 2u) << "the header and units row of the second buffer";
  EXPECT_EQ(mt.header()[1], "Crosshead");
  EXPECT_EQ(mt.units()[1], "m");
  // A preamble's date with points above decimal-comma readings: the readings decide.
  const TableLayout dated = layout_of("Datum: 05.12.2026\nZeit;Weg;Kraft\n1,0;0,5;10,2\n"
                                      "2,0;1,0;20,4\n3,0;1,5;30,6\n");
  EXPECT_EQ(dated.decimal, ',') << dated.describe();
  EXPECT_EQ(dated.header_line, 2u) << dated.describe();
  const TableLayout p = layout_of("time_s,opening_mm,load_N,a_mm\n0,0,0,30\n1,0.5,10,30\n");
  EXPECT_FALSE(p.is_export()) << p.describe();
  EXPECT_EQ(p.header_line, 1u);
}

TEST(RecordLayouts, NumbersAsMachinesWriteThem) {
  double v = 0;
  bool grouped = false;
  EXPECT_TRUE(parse_exported_number("1,234.5", '.', v, &grouped));
  EXPECT_DOUBLE_EQ(v, 1234.5);
  EXPECT_TRUE(grouped);
  EXPECT_TRUE(parse_exported_number("1.234,5", ',', v));
  EXPECT_DOUBLE_EQ(v, 1234.5);
  EXPECT_TRUE(parse_exported_number("-0,25E-3", ',', v));
  EXPECT_DOUBLE_EQ(v, -0.25e-3);
  EXPECT_TRUE(parse_exported_number("1'000'000.5", '.', v));
  EXPECT_DOUBLE_EQ(v, 1000000.5);
  EXPECT_FALSE(parse_exported_number("1,23.5", '.', v))
      << "a group of two is not a thousands group";
  EXPECT_FALSE(parse_exported_number("12,5", '.', v));
  EXPECT_FALSE(parse_exported_number("inf", '.', v));
  EXPECT_FALSE(parse_exported_number("1e999", '.', v));
  EXPECT_FALSE(parse_exported_number("", '.', v));
  EXPECT_TRUE(is_missing_value("NaN"));
  EXPECT_TRUE(is_missing_value(" #N/A"));
  EXPECT_TRUE(is_missing_value("--"));
  EXPECT_FALSE(is_missing_value("0"));
}

TEST(RecordLayouts, UnitsAreConverted) {
  EXPECT_DOUBLE_EQ(units::si_factor("kN", units::Dimension::force, "x"), 1e3);
  EXPECT_DOUBLE_EQ(units::si_factor("lbf", units::Dimension::force, "x"), lbf);
  EXPECT_DOUBLE_EQ(units::si_factor("in", units::Dimension::length, "x"), inch * mm);
  EXPECT_DOUBLE_EQ(units::si_factor("m", units::Dimension::length, "x"), 1.0);
  EXPECT_DOUBLE_EQ(units::si_factor("ms", units::Dimension::time, "x"), 1e-3);
  EXPECT_DOUBLE_EQ(units::si_factor("min", units::Dimension::time, "x"), 60.0);
  const auto split = units::split_header_unit("Extension [mm]");
  EXPECT_EQ(split.name, "Extension");
  EXPECT_EQ(split.unit, "mm");
  // A kN file gives N: 0.05 kN is 50 N.
  TempFile f("kN.csv", "Time (s),Extension (mm),Load (kN),Crack (mm)\n"
                       "0,0,0,30\n1,0.5,0.01,30\n2,1,0.02,30\n3,1.5,0.03,30\n4,2,0.04,31\n"
                       "5,2.5,0.05,32\n6,3,0.045,33\n7,3.5,0.04,34\n8,4,0.038,35\n");
  const auto r =
      read_test_records(f.path(), with_map("time_s: Time, opening_mm: Extension, load_N: Load, "
                                           "a_mm: Crack"))
          .at(0);
  EXPECT_DOUBLE_EQ(r.load[5], 50.0);
  EXPECT_TRUE(contains(all(r.cleaning), "load_N from 'Load (kN)' in kN (from the file)"))
      << all(r.cleaning);
}

TEST(RecordLayouts, UnknownOrUnfittingUnitIsNamed) {
  const std::string rows = "0,0,0,30\n1,0.5,10,30\n2,1,20,30\n3,1.5,30,31\n4,2,40,32\n"
                           "5,2.5,50,33\n6,3,45,34\n7,3.5,40,35\n";
  TempFile f("furlong.csv", "Time (s),Extension (furlong),Load (N),Crack (mm)\n" + rows);
  const auto o = with_map("time_s: Time, opening_mm: Extension, load_N: Load, a_mm: Crack");
  try {
    read_test_records(f.path(), o);
    FAIL() << "an unknown unit was accepted";
  } catch (const InputError& e) {
    EXPECT_TRUE(contains(e.what(), "furlong.csv:1: column 'Extension (furlong)' for opening_mm: "
                                   "unit 'furlong' is not one this reader knows for a length"))
        << e.what();
  }
  TempFile g("kNmm.csv", "Time (s),Extension (kN),Load (N),Crack (mm)\n" + rows);
  try {
    read_test_records(g.path(), o);
    FAIL() << "a force unit on the opening was accepted";
  } catch (const InputError& e) {
    EXPECT_TRUE(contains(e.what(), "unit 'kN' is a force, not a length")) << e.what();
  }
  // The map's unit disagreeing with the file's is an error too, not a silent choice.
  try {
    read_test_records(f.path(), with_map("opening_mm: Extension (mm), load_N: Load, a_mm: Crack"));
    FAIL() << "a unit conflict was accepted";
  } catch (const InputError& e) {
    EXPECT_TRUE(contains(e.what(), "is in 'furlong'")) << e.what();
  }
}

TEST(RecordLayouts, MapEntryWithoutUnitMatchesHeaderWithUnit) {
  const std::string rows = "0,0,0,30\n1,0.5,10,30\n2,1,20,30\n3,1.5,30,31\n4,2,40,32\n"
                           "5,2.5,50,33\n6,3,45,34\n7,3.5,40,35\n";
  TempFile f("units.csv", "Time (s),Extension (mm),Load (N),Crack length (mm)\n" + rows);
  const auto r =
      read_test_records(f.path(), with_map("opening_mm: Extension, load_N: load, a_mm: Crack "
                                           "length (mm), time_s: Time [s]"))
          .at(0);
  EXPECT_DOUBLE_EQ(r.opening[3], 1.5 * mm);
  EXPECT_DOUBLE_EQ(r.load[3], 30.0);
  // Two headers with the same name but units: the map must say which.
  TempFile g("twice.csv", "Time (s),Extension (mm),Extension (in),Load (N),Crack (mm)\n"
                          "0,0,0,0,30\n1,1,1,1,30\n2,2,2,2,31\n");
  try {
    read_test_records(g.path(), with_map("opening_mm: Extension, load_N: Load, a_mm: Crack"));
    FAIL() << "an ambiguous map entry was accepted";
  } catch (const InputError& e) {
    EXPECT_TRUE(contains(e.what(), "matches several headers ('Extension (mm)', 'Extension (in)')"))
        << e.what();
  }
}

TEST(RecordLayouts, NoCrackColumnGivesAnEmptyCrackLength) {
  std::string s = "Time (s),Extension (mm),Load (N)\n";
  for (int i = 0; i < 12; ++i)
    s += std::to_string(i) + "," + std::to_string(0.5 * i) + "," +
         std::to_string(i < 6 ? 10.0 * i : 60.0 - 2 * i) + "\n";
  TempFile f("nocrack.csv", s);
  const auto o = with_map("time_s: Time, opening_mm: Extension, load_N: Load");
  const auto r = read_test_records(f.path(), o).at(0);
  EXPECT_TRUE(r.crack_length.empty());
  EXPECT_TRUE(crack_reading_rows(r).empty());
  EXPECT_TRUE(contains(all(r.cleaning), "the record has no crack readings")) << all(r.cleaning);
  // Crack length = equivalent drops a crack column that is there.
  std::string t = "time_s,opening_mm,load_N,a_mm\n";
  for (int i = 0; i < 12; ++i)
    t += std::to_string(i) + "," + std::to_string(0.5 * i) + "," +
         std::to_string(i < 6 ? 10.0 * i : 60.0 - 2 * i) + "," + std::to_string(30 + i) + "\n";
  TempFile g("equivalent.csv", t);
  RecordReadOptions e;
  e.crack_length = CrackLengthSource::equivalent;
  EXPECT_TRUE(read_test_records(g.path(), e).at(0).crack_length.empty());
}

// The fuzz seeds (tests/analysis/data/record_layout_*.csv, one per layout and one with a fault
// of each class; scripts/fuzz.sh seeds the record reader's corpus with them) are read with the
// column map on their first line, as the fuzz target does, and give the same first rows. The
// code-page seeds map by position (their first line is read as bytes, like the fuzz target's).
TEST(RecordLayouts, FuzzSeedsAreRead) {
  std::vector<TestRecord> records;
  for (const char* name :
       {"bluehill", "testxpert", "tabbed", "mts", "spreadsheet", "bluehill_cp1250",
        "trapezium_sjis", "mpt_blocks", "stacked", "utf16", "faults"}) {
    SCOPED_TRACE(name);
    const std::string path =
        std::string(FIBERBRIDGE_SOURCE_DIR) + "/tests/analysis/data/record_layout_" + name + ".csv";
    if (std::string(name) == "utf16") { // UTF-16 without a byte-order mark: our names, no map
      records.push_back(read_test_records(path).at(0));
      continue;
    }
    std::ifstream in(path);
    std::string first;
    std::getline(in, first);
    ASSERT_EQ(first.rfind("#columns: ", 0), 0u);
    first = first.substr(10);
    if (!first.empty() && first.back() == '\r')
      first.pop_back();
    records.push_back(read_test_records(path, with_map(first)).at(0));
    std::printf("%s: %s\n", name, all(records.back().cleaning).c_str());
  }
  for (std::size_t k = 1; k < records.size(); ++k) {
    // Same 9 digits written in every layout: equal to 1e-7 of each channel's largest value.
    const std::size_t n = 30; // rows before the faults seed's first fault that changes values
    ASSERT_GE(records[k].load.size(), n);
    for (std::size_t i = 1; i < n; ++i) {
      EXPECT_NEAR(records[k].load[i], records[0].load[i], 1e-7 * 100) << k << " row " << i;
      EXPECT_NEAR(records[k].opening[i], records[0].opening[i], 1e-7 * 5 * mm) << k << " row " << i;
    }
  }
  const std::string faults = all(records.back().cleaning);
  for (const char* named :
       {"negative opening", "without a crack reading", "spike", "a pause", "The last 10 row(s)"})
    EXPECT_TRUE(contains(faults, named)) << named << " in\n" << faults;
}

// German and French Windows exports are Windows-1252 ("Prüfzeit" with a single byte for ü);
// Excel's "Unicode text" is UTF-16 with a byte-order mark. Both read as UTF-8, so a map written
// in UTF-8 matches.
TEST(RecordLayouts, EncodingsAreRead) {
  const Raw raw = raw_record();
  const TestRecord plain = read_test_records(shared, with_map(shared_map)).at(0);
  std::string latin1 = testxpert(raw);
  for (std::size_t p; (p = latin1.find("\xC3\xBC")) != std::string::npos;) // ü
    latin1.replace(p, 2, "\xFC");
  for (std::size_t p; (p = latin1.find("\xC3\xA4")) != std::string::npos;) // ä
    latin1.replace(p, 2, "\xE4");
  TempFile f("latin1.csv", latin1);
  const auto r = read_test_records(f.path(), with_map(layouts[1].map)).at(0);
  EXPECT_TRUE(contains(all(r.cleaning), "(text in windows-1252, detected")) << all(r.cleaning);
  expect_same(r.load, plain.load, 1e-7, "load");

  const std::string ascii = tabbed(raw);
  std::string utf16 = "\xFF\xFE";
  for (char c : ascii) {
    utf16 += c;
    utf16 += '\0';
  }
  TempFile g("utf16.txt", utf16);
  const auto u = read_test_records(g.path(), with_map(layouts[2].map)).at(0);
  EXPECT_TRUE(contains(all(u.cleaning), "(text in UTF-16LE, byte-order mark)")) << all(u.cleaning);
  expect_same(u.opening, plain.opening, 1e-7, "opening");
}

// A machine set up for compression writes the load and the extension negative, and a crosshead
// position is not zeroed (here it starts at -2 mm). Both signs are turned over, the 2 mm offset
// removed from the initial linear part: the openings are the plain record's shifted by one
// constant (its own seating offset, under 0.1 mm), the loads are the plain record's.
TEST(RecordLayouts, CompressionSignsAndAnUnzeroedPosition) {
  const Raw raw = raw_record();
  const TestRecord plain = read_test_records(shared, with_map(shared_map)).at(0);
  std::string s = "Time,Extension,Load,Crack length\n(s),(mm),(N),(mm)\n";
  for (std::size_t i = 0; i < raw.t.size(); ++i)
    s += fmt(raw.t[i]) + "," + fmt(-(raw.x[i] + 2.0)) + "," + fmt(-raw.P[i]) + "," + fmt(raw.a[i]) +
         "\n";
  TempFile f("compression.csv", s);
  const auto r = read_test_records(f.path(), with_map(layouts[0].map)).at(0);
  const std::string c = all(r.cleaning);
  EXPECT_TRUE(contains(c, "load_N is negative throughout")) << c;
  EXPECT_TRUE(contains(c, "opening_mm is negative throughout")) << c;
  EXPECT_TRUE(contains(c, "Opening zero offset 2.0")) << c;
  expect_same(r.load, plain.load, 1e-7, "load");
  ASSERT_EQ(r.opening.size(), plain.opening.size());
  const double shift = plain.opening.back() - r.opening.back();
  EXPECT_LT(std::abs(shift), 0.1 * mm);
  // After the toe (rows the shift would take below zero, set to 0) one constant, to the digits.
  for (std::size_t i = 0; i < r.opening.size(); ++i)
    if (plain.opening[i] > shift + 0.01 * mm)
      ASSERT_NEAR(plain.opening[i] - r.opening[i], shift, 1e-6 * mm) << "row " << i;
}

// A data logger's clock times for the time, and results appended after the data (Bluehill's
// "Maximum Load" lines): the time is read as seconds from the first row, the trailer set aside.
TEST(RecordLayouts, ClockTimesAndATrailer) {
  const Raw raw = raw_record();
  const TestRecord plain = read_test_records(shared, with_map(shared_map)).at(0);
  std::string s = "Time,Extension (mm),Load (N),Crack (mm)\n";
  for (std::size_t i = 0; i < raw.t.size(); ++i) {
    const double t = 23 * 3600 + 59 * 60 + raw.t[i]; // passes midnight 44 s into the record
    const double tod = std::fmod(t, 86400);
    char clock[64];
    std::snprintf(clock, sizeof clock, "2024-05-0%d %02d:%02d:%06.3f", t < 86400 ? 1 : 2,
                  int(tod / 3600), int(std::fmod(tod, 3600) / 60), std::fmod(tod, 60));
    s +=
        std::string(clock) + "," + fmt(raw.x[i]) + "," + fmt(raw.P[i]) + "," + fmt(raw.a[i]) + "\n";
  }
  s += "\nMaximum Load (N),99.8\nOperator,AB\n";
  TempFile f("clock.csv", s);
  const auto r =
      read_test_records(f.path(), with_map("time_s: Time, opening_mm: Extension, load_N: Load, "
                                           "a_mm: Crack"))
          .at(0);
  const std::string c = all(r.cleaning);
  EXPECT_TRUE(contains(c, "time_s read as clock times")) << c;
  EXPECT_TRUE(contains(c, "2 line(s) after the data from line")) << c;
  ASSERT_EQ(r.time.size(), plain.time.size());
  // Milliseconds written: the times from the first row agree to 1 ms.
  for (std::size_t i = 0; i < r.time.size(); ++i)
    ASSERT_NEAR(r.time[i], plain.time[i] - plain.time[0], 1e-3) << "row " << i;
  expect_same(r.load, plain.load, 1e-7, "load");
}

// Stacked specimens become one record each, named from the file: Bluehill's per-specimen blocks
// and a machine's `Specimen` column. Two blocks with one title, and a block whose header differs
// (an MPT block with other channels), cannot be split unambiguously and are refused with why.
TEST(RecordLayouts, StackedSpecimensAreSplit) {
  const Raw raw = raw_record();
  const TestRecord plain = read_test_records(shared, with_map(shared_map)).at(0);
  TempFile f("stacked.csv", bluehill_stacked(raw));
  const auto records = read_test_records(f.path(), with_map(layouts[0].map));
  ASSERT_EQ(records.size(), 2u);
  const std::string file = f.path().substr(f.path().find_last_of('/') + 1);
  EXPECT_EQ(records[0].name, file + "#Specimen 1");
  EXPECT_EQ(records[1].name, file + "#Specimen 2");
  expect_same(records[1].load, plain.load, 1e-7, "load");

  std::string column = "Specimen,Time (s),Extension (mm),Load (N),Crack length (mm)\n";
  for (const char* specimen : {"A-1", "A-2"})
    for (std::size_t i = 0; i < raw.t.size(); ++i)
      column += std::string(specimen) + "," + fmt(raw.t[i]) + "," + fmt(raw.x[i]) + "," +
                fmt(raw.P[i]) + "," + fmt(raw.a[i]) + "\n";
  TempFile g("column.csv", column);
  const auto by_column = read_test_records(g.path(), with_map(layouts[0].map));
  ASSERT_EQ(by_column.size(), 2u);
  const std::string gfile = g.path().substr(g.path().find_last_of('/') + 1);
  EXPECT_EQ(by_column[0].name, gfile + "#A-1");
  EXPECT_EQ(by_column[1].name, gfile + "#A-2");
  expect_same(by_column[1].opening, plain.opening, 1e-7, "opening");

  const auto refusal = [](const std::string& path, const std::string& map) {
    try {
      read_test_records(path, with_map(map));
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("(accepted)");
  };
  std::string twice = bluehill_stacked(raw);
  twice.replace(twice.find("Specimen 2"), 10, "Specimen 1");
  TempFile h("twice.csv", twice);
  const std::string m = refusal(h.path(), layouts[0].map);
  EXPECT_TRUE(contains(m, "two specimen blocks are labelled 'Specimen 1'")) << m;

  // MPT's second block records seven channels: not the table above, refused at its title.
  std::string other = mpt_two_blocks(raw);
  const std::size_t second = other.find("Data Acquisition", other.find("Data Acquisition") + 1);
  const std::size_t header = other.find("Time      Crosshead", second);
  other.replace(header, other.find('\n', header) - header,
                "Time Crosshead Load Crack Strain1 Strain2 Temperature");
  TempFile k("mpt_other.dat", other);
  const std::string n = refusal(k.path(), layouts[3].map);
  EXPECT_TRUE(contains(n, "'Data Acquisition' is not a row of the table whose header is on line 4"))
      << n;
  EXPECT_TRUE(contains(n, "split unambiguously")) << n;
}

// Columns by position, for headers no one can type: '#N' is the N-th column (1-based); beyond the
// last column the message lists the headers found with their numbers.
TEST(RecordLayouts, ColumnsByPosition) {
  const Raw raw = raw_record();
  TempFile f("sjis.csv", trapezium_sjis(raw));
  try {
    read_test_records(f.path(), with_map("time_s: #1, opening_mm: #2, load_N: #9, a_mm: #4"));
    FAIL() << "#9 of four columns was accepted";
  } catch (const InputError& e) {
    EXPECT_TRUE(contains(e.what(), "'#9' for load_N asks for column 9 but the rows have 4"))
        << e.what();
    EXPECT_TRUE(contains(e.what(), "#3 '試験力' (N)")) << e.what();
    EXPECT_TRUE(contains(e.what(), "Shift-JIS (CP932)")) << e.what();
  }
}
