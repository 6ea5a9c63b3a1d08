#pragma once
// A table as a testing machine's software exports it (Instron Bluehill, MTS TestWorks/793,
// ZwickRoell testXpert, spreadsheets), read without options: the layout is detected from the
// text (docs/design.md section 6, "Layouts, units and cleaning of machine exports"):
//  - the delimiter: tab, semicolon, comma or runs of blanks (tried in that order; the first that
//    splits three consecutive lines into the same number (>= 2) of mostly numeric cells wins);
//  - the decimal separator: a point, or a comma when the delimiter is not a comma and the numbers
//    are written "0,5" (a "1.234,5" grouping also says decimal comma); thousands separators
//    ("1,234.5", "1.234,5", "1'234.5") in well-formed groups of three;
//  - a preamble above the header (Bluehill `"Sample ID","..."` or `Name : value,...` lines, an MTS
//    format line, a "Raw Data" marker): every line above the header is skipped;
//  - the header: the line above the first data row, or above a units row ("(s),(mm),(N)",
//    "s;mm;N") when there is one; units may also stand in the header ("Load (kN)");
//  - quoted cells ("" inside is one quote), '#' comment lines, blank lines, a UTF-8 byte-order
//    mark, CRLF or CR line ends; the header or units row repeated inside the data (MTS writes one
//    per buffer) skipped; rows shorter than the header read as empty trailing cells;
//  - blocks: non-data lines inside the data followed by the header again start a block; a block
//    titled as a specimen ("Specimen 2", "Sample 3", "Probe 2") is another specimen (stacked
//    exports: Bluehill, testXpert series), any other ("Data Acquisition" of MTS 793 MPT)
//    continues the table; a block whose header differs is refused (the split is ambiguous);
//  - lines after the last data row that are not data (appended results) set aside;
//  - the text encoding (core/text_encoding.h): UTF-8, UTF-16 with or without a byte-order mark,
//    or a Windows / legacy code page (windows-1252, windows-1250, Shift-JIS, GB18030, EUC-KR)
//    detected from the content or given by the user, all converted to UTF-8 with iconv;
//  - a damaged file (NUL or control bytes: a NUL-filled or binary tail) refused, never read up
//    to the damage with the rest set aside.
#include <cstddef>
#include <string>
#include <vector>

namespace fiberbridge {

/// What detection found (1-based line numbers).
struct TableLayout {
  char delimiter = ',';             ///< ',', ';', '\t', or ' ' for runs of blanks
  char decimal = '.';               ///< '.' or ','
  std::size_t header_line = 0;      ///< line of the column names
  std::size_t units_line = 0;       ///< line of the units row; 0: none
  std::size_t first_data_line = 0;  ///< line of the first data row
  std::size_t preamble_lines = 0;   ///< non-blank, non-comment lines above the header
  std::size_t repeated_headers = 0; ///< header / units rows repeated inside the data (skipped)
  std::size_t trailer_lines = 0;    ///< non-data lines after the last data row (set aside)
  std::size_t trailer_line = 0;     ///< the first of them
  std::size_t short_rows = 0;       ///< rows with fewer cells than the header (padded empty)
  /// Blocks after the first that continue the same table (MTS 793 MPT "Data Acquisition":
  /// non-data lines, then the header again)
  std::size_t continued_blocks = 0;
  /// Specimen blocks ("Specimen 2" above a repeated header: Bluehill, testXpert series); 0 when
  /// the file holds one specimen
  std::size_t specimen_blocks = 0;
  /// The text encoding the file was read in ("UTF-8", "UTF-16LE", "windows-1250",
  /// "Shift-JIS (CP932)", ...; core/text_encoding.h), converted to UTF-8 for reading
  std::string encoding = "UTF-8";
  std::string encoding_how = "detected"; ///< "byte-order mark", "given", "detected: ..."

  /// False for what our own files are: comma-separated, decimal point, header on the first
  /// content line, no units row, nothing repeated or short.
  bool is_export() const;
  /// One sentence: "Read as semicolon-separated with a decimal comma; 3 preamble line(s) above
  /// the header on line 5 skipped; units row on line 6."
  std::string describe() const;
};

/// Detects the layout of `text` (see the file comment); throws InputError naming `source` when
/// no block of numeric rows with a header above it is found.
/// `encoding`: "" or "auto" detects it, else an iconv name (core/text_encoding.h).
TableLayout detect_table_layout(const std::string& text, const std::string& source,
                                const std::string& encoding = "");

class ExportedTable {
public:
  /// Reads `path`; throws InputError naming file and line for what cannot be read.
  /// `encoding`: "" or "auto" detects it, else an iconv name (core/text_encoding.h).
  static ExportedTable read(const std::string& path, const std::string& encoding = "");
  /// Parses the file's bytes as if they came from `source_name` (tests, fuzzing, read()).
  static ExportedTable parse(const std::string& raw, const std::string& source_name,
                             const std::string& encoding = "");

  const TableLayout& layout() const { return layout_; }
  const std::string& source() const { return source_; }
  /// Column names as written (a unit in them kept: "Load (kN)"); "" for an unnamed column.
  const std::vector<std::string>& header() const { return header_; }
  /// The units row's cell of each column with brackets stripped; "" without a units row.
  const std::vector<std::string>& units() const { return units_; }
  std::size_t n_rows() const { return line_numbers_.size(); }
  std::size_t line_of_row(std::size_t row) const { return line_numbers_.at(row); }
  /// Specimen blocks of a stacked export ("Specimen 1", "Specimen 2", ...); empty when the file
  /// holds one specimen. block_of_row(r) is the index of row r's block.
  const std::vector<std::string>& specimen_blocks() const { return block_labels_; }
  std::size_t block_of_row(std::size_t row) const { return block_of_row_.at(row); }
  /// Raw text of a column's cells.
  const std::vector<std::string>& text(std::size_t column) const { return columns_.at(column); }
  /// Numbers of a column in the detected decimal convention. A missing value (empty cell, NaN,
  /// "-", "n/a", "#N/A", "null") is NaN; any other text throws InputError naming file:line, the
  /// column and the cell. `grouped` (optional) counts cells written with thousands separators.
  std::vector<double> numeric(std::size_t column, std::size_t* grouped = nullptr) const;

private:
  std::string source_;
  TableLayout layout_;
  std::vector<std::string> header_, units_;
  std::vector<std::vector<std::string>> columns_;
  std::vector<std::size_t> line_numbers_;
  std::vector<std::string> block_labels_;
  std::vector<std::size_t> block_of_row_;
};

/// Parses one number written with decimal separator `decimal` ('.' or ','), allowing thousands
/// separators (the other of '.' and ',', or an apostrophe) in groups of three and an exponent.
/// Returns false for anything else (including empty text and non-finite values); sets *grouped
/// when a separator was read.
bool parse_exported_number(const std::string& cell, char decimal, double& value,
                           bool* grouped = nullptr);

/// True for the texts machines write for a missing value: empty, NaN, "-", "--", "n/a", "#N/A",
/// "NA", "null", "none" (any case).
bool is_missing_value(const std::string& cell);

} // namespace fiberbridge
