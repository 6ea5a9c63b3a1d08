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
  /// Crack length from the load line [m], one entry per row; NaN on a row without a reading
  /// (empty or NaN cell, a dropout value). EMPTY when the record has no crack column at all or
  /// the reading is switched off (RecordReadOptions::crack_length = equivalent).
  std::vector<double> crack_length;
  std::vector<double> delta_root;    ///< measured notch-root opening [m]; empty when not measured
  std::vector<std::size_t> line;     ///< source line of each kept row (1-based, for messages)
  std::vector<std::string> cleaning; ///< what the reader did to the raw rows, one sentence each
};

/// Which header of the file holds each of our columns. Our names are time_s, opening_mm, load_N
/// (required but time_s), a_mm, delta_root_mm and record (optional); the units are in our names.
/// Without an entry a column is looked up under our own name. An entry names the file's header
/// with or without its unit, or by its position ('load_N: #3', the third column, 1-based, for
/// headers no one can type) ('opening_mm: Extension' matches a header 'Extension (mm)' or
/// 'Extension' over a units row '(mm)'); the file's unit then converts it (kN, lbf, in, ms, ...),
/// else the entry's unit, else the unit in our name.
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

/// Where a record's crack lengths come from.
enum class CrackLengthSource {
  automatic, ///< the crack column when the file has one (a_mm or mapped), else none
  measured,  ///< the crack column is required
  equivalent ///< any crack column is ignored: crack_length stays empty
};

/// How the reader cleans what a real machine writes (docs/design.md section 6).
struct RecordReadOptions {
  RecordColumnMap columns;
  /// The files' text encoding: "" (or "auto") detects it from the content, else an iconv name
  /// (CP1250, CP932, GB18030, EUC-KR, UTF-16LE, ...; core/text_encoding.h). Test/Encoding,
  /// --encoding.
  std::string encoding;
  CrackLengthSource crack_length = CrackLengthSource::automatic;
  /// A negative opening or load within this fraction of the channel's largest value is reading
  /// noise around zero (an extensometer zeroed 0.0002 mm off on a record reaching several mm)
  /// and set to 0; a larger one is an error unless the zero offset explains it.
  double noise_fraction = 1e-3;
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

/// Reads one record file as written by us or exported by a testing machine (layout, delimiter,
/// decimal comma, preamble, units detected: core/exported_table.h); one TestRecord per value of
/// the `record` column (in order of first appearance), else one named after the file's stem.
/// Values are converted to SI from the file's units. Rows are then cleaned, each step that
/// changed something stated as a sentence with row counts and lines in TestRecord::cleaning
/// (docs/design.md section 6 lists the classes):
///  - a load or opening negative throughout (a compression set-up) turned over;
///  - rows without a time, load or opening value dropped; rows repeating the time of the row
///    before, or repeating every channel while the time advances (a pause), dropped;
///  - crack cells that are empty, NaN, a dropout code (999, -9999, ...) or <= 0 after a positive
///    reading are rows without a reading (NaN), kept for load and opening, a trailing block of
///    them named;
///  - single-row spikes in load or opening replaced by the mean of their neighbours; a short
///    dropout of a channel to ~0 dropped; an opening re-zeroed mid-test continued from before;
///  - negative loads before the test started set to 0; negative openings or loads within
///    noise_fraction of their largest value set to 0; the opening's zero offset, extrapolated
///    from the initial linear part of load against opening, removed when it matters;
///  - rows after the final drop and unload/reload segments dropped (see the options);
///  - a single crack reading far beyond both neighbours (a tracking spike) made no reading;
///    readings stepping back within the tolerance held at the running maximum.
/// Throws InputError naming file:line and the reason for: a missing column (listing the headers
/// found), an unknown or unfitting unit, a non-number, time going back, a load channel re-zeroed
/// mid-test, a crack length <= 0 before any positive reading (a crack-extension column), a crack
/// length going back by more than the tolerance, a negative opening or load
/// beyond noise that no zero offset explains, no crack growth (when the record has crack
/// readings), and fewer than 8 rows left after cleaning.
std::vector<TestRecord> read_test_records(const std::string& path,
                                          const RecordReadOptions& options = {});

/// A record handed in as columns in memory (a script's arrays), cleaned exactly as
/// read_test_records cleans a file's rows, with the same refusals. `given` holds the name, the
/// source that messages name (line k there is row k of the arrays, from 1) and the columns in SI,
/// NaN for a missing cell; time, crack_length and delta_root may be empty (no such column),
/// opening and load are required, every column given has one value per row. `options`' crack
/// length source applies (equivalent ignores the crack column; measured requires it); its column
/// map and encoding do not. Dropout codes of the crack column (-999, 9999, ...) are recognised in
/// `crack_code_unit` (the unit the caller's values were written in; mm from Python). Throws
/// InputError naming the source for columns of different lengths and whatever the reader refuses.
/// `given` is taken by value: its columns are moved into the cleaning, not copied again.
TestRecord clean_test_record(TestRecord given, const RecordReadOptions& options = {},
                             double crack_code_unit = 1e-3);

/// Rows of `r` where a new crack reading is made: the first row with a reading, and every row
/// whose reading differs from the last reading before it (rows without a reading (NaN) and rows
/// repeating a stale reading are skipped). Empty when the record has no crack readings.
std::vector<std::size_t> crack_reading_rows(const TestRecord& r);

} // namespace fiberbridge::analysis
