#pragma once
// A raw DCB test record as a testing machine writes it: load, load-line opening and crack-length
// readings in time order, sometimes a measured notch-root opening (clip gauge, DIC). SI inside.
// This struct is the hand-over between the record reader, the direct-energy and beam-theory
// reductions (`reduce`) and the identification of the law from the record (`identify`).
#include <cmath>
#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace fiberbridge::analysis {

struct TestRecord {
  std::string name;            ///< record label: the `record` column's value, or the file's stem
  std::string source;          ///< the file it came from (for messages)
  std::vector<double> time;    ///< [s]; empty when the file has no time column
  std::vector<double> opening; ///< load-line opening [m]
  std::vector<double> load;    ///< load on the whole specimen width [N]
  std::vector<double> crack_length;  ///< crack length from the load line [m]
  std::vector<double> delta_root;    ///< measured notch-root opening [m]; empty when not measured
  std::vector<std::size_t> line;     ///< source line of each kept row (1-based, for messages)
  std::vector<std::string> cleaning; ///< what the reader did to the raw rows, one sentence each
};

/// Which header of the file holds each of our columns. Our names are time_s, opening_mm, load_N,
/// a_mm (required but time_s), delta_root_mm and record (optional); the units are in our names.
/// Without an entry a column is looked up under our own name.
struct RecordColumnMap {
  std::map<std::string, std::string> file_header; ///< our name -> header in the file

  /// Parses "time_s: Time (s), opening_mm: Extension (mm), ..." (entries separated by commas,
  /// our name before the first ':', the file's header after it, spaces around both trimmed).
  /// Throws InputError naming `where` for an unknown name of ours, a repeated one or an entry
  /// without ':'. An empty text gives the identity map.
  static RecordColumnMap parse(const std::string& text, const std::string& where);
  /// The file header that holds our column `ours`.
  std::string header_for(const std::string& ours) const;
};

/// How the reader cleans what a real machine writes (docs/design.md, "Test records").
struct RecordReadOptions {
  RecordColumnMap columns;
  /// A crack reading may fall below the longest earlier reading by at most this much [m]
  /// (optical tracking noise: the shared records in data/dcb_records fall back by up to 0.5 mm);
  /// such readings are replaced by the running maximum, because a crack does not heal. A larger
  /// step back is an error.
  double crack_back_tolerance = 1e-3;
  /// After the last row whose load is at least this fraction of the peak, the specimen has
  /// broken or been unloaded for good: those rows are dropped.
  double final_drop_fraction = 0.25;
  /// An opening that falls back by more than this fraction of its largest value so far starts
  /// an unload/reload segment; smaller falls are crosshead reading noise and are kept (the work
  /// integral takes them as they are).
  double unload_fraction = 0.01;
};

/// Reads one CSV record file; one TestRecord per value of the `record` column (in order of first
/// appearance), else one named after the file's stem. Rows are cleaned in this order, each step
/// that changed something stated as a sentence in TestRecord::cleaning:
///  1. negative loads before the test started (before the load first exceeds 5 % of its peak:
///     load-cell offset and noise) set to 0 N;
///  2. rows after the final drop (see RecordReadOptions::final_drop_fraction) dropped;
///  3. rows that repeat the time of the row before dropped (the first of each run kept);
///  4. unload/reload segments dropped: from the first row whose opening falls below the largest
///     opening so far until the opening exceeds it again, when it fell by more than
///     unload_fraction (the envelope is kept; an unloading at the end, where the opening never
///     recovers, is dropped the same way; smaller falls are reading noise and are kept);
///  5. crack readings that step back within the tolerance replaced by the running maximum;
///  6. repeated crack readings are kept (the load and opening of those rows are good) and
///     counted: crack_reading_rows() gives the rows where the reading changes.
/// Throws InputError naming file:line and the reason for: a missing column (with the columns
/// present), a non-number, NaN or empty cell, decreasing time, a crack length that goes back by
/// more than the tolerance, a negative opening or crack length, a negative load after the test
/// started, no crack growth at all, and fewer than 8 rows left after cleaning.
std::vector<TestRecord> read_test_records(const std::string& path,
                                          const RecordReadOptions& options = {});

/// Rows of `r` where a new crack reading is made: the first row, and every row whose crack length
/// differs from the row before (the rows in between repeat a stale reading).
std::vector<std::size_t> crack_reading_rows(const TestRecord& r);

/// Specimen geometry a reduction needs, SI. NaN means "not given".
struct TestSpecimen {
  double width = NAN;         ///< B [m]
  double arm_thickness = NAN; ///< h, thickness of one arm [m] (the specimen is 2h thick)
  double length = NAN;        ///< [m], informative
  double initial_crack = NAN; ///< a0 from the load line [m]; NaN: each record's first reading
  /// l1 of ASTM D5528 / ISO 15024: load-pin axis to the arm's mid-plane [m]; NaN: h/2 (a hinge
  /// on the arm's surface)
  double pin_to_arm_midplane = NAN;
  /// l2 of ASTM D5528 / ISO 15024: load-pin axis to the end block's inner edge [m]; NaN: no
  /// end blocks (hinges): l2 = 0 in N
  double pin_to_block_edge = NAN;

  /// Throws InputError naming `where` when width or arm thickness is missing or not positive,
  /// or a given length, initial crack or pin distance is not positive.
  void check(const std::string& where) const;
};

} // namespace fiberbridge::analysis
