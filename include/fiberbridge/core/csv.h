#pragma once
// CSV with a header line; units live in the column names (delta_mm, R_J_m2, sigma_kPa).
// Lines starting with '#' are comments (provenance of bundled data goes there); blank lines are
// skipped; CRLF line ends and a UTF-8 byte-order mark are accepted; a cell in double quotes may
// hold commas ("" inside it is one quote) but must end on its line.
#include <cstddef>
#include <string>
#include <vector>

namespace fiberbridge {

/// A CSV table read from a file: every data row has as many cells as the header (a trailing comma
/// is an empty last cell); numeric() requires finite numbers, text() takes cells as they are.
class CsvTable {
public:
  /// Reads `path`; throws InputError naming file and line for malformed content.
  static CsvTable read(const std::string& path);
  /// Parses text as if it came from `source_name` (used by tests and by read()).
  static CsvTable parse(const std::string& text, const std::string& source_name);

  bool has_column(const std::string& name) const;
  /// Values of a column; throws InputError naming the file and the columns it does have.
  /// Non-numeric or non-finite cells throw with the line number.
  std::vector<double> numeric(const std::string& name) const;
  /// Raw text of a column (for labels such as material names).
  const std::vector<std::string>& text(const std::string& name) const;
  /// 1-based line number in the file of data row `row` (for error messages).
  std::size_t line_of_row(std::size_t row) const { return line_numbers_.at(row); }
  std::size_t n_rows() const { return line_numbers_.size(); }
  const std::vector<std::string>& header() const { return header_; }
  const std::string& source() const { return source_; }

private:
  std::size_t index_of(const std::string& name) const;
  std::string source_;
  std::vector<std::string> header_;
  std::vector<std::vector<std::string>> columns_;
  std::vector<std::size_t> line_numbers_;
};

/// Writes a CSV with a header; NaN values are written as empty cells ("not available").
/// Writing goes to a temporary file renamed at close(), so a crash never leaves half a table.
class CsvWriter {
public:
  CsvWriter(const std::string& path, const std::vector<std::string>& header,
            const std::vector<std::string>& comment_lines = {});
  ~CsvWriter();
  CsvWriter(const CsvWriter&) = delete;
  CsvWriter& operator=(const CsvWriter&) = delete;
  void row(const std::vector<double>& values);
  /// A row that starts with text labels (material, property, ...) followed by numbers.
  void row(const std::vector<std::string>& labels, const std::vector<double>& values);
  void close();

private:
  std::string path_, tmp_path_;
  std::size_t n_columns_;
  std::string buffer_;
  bool closed_ = false;
};

/// Writes `content` to `path` atomically (temporary file + rename).
void write_file_atomically(const std::string& path, const std::string& content);

} // namespace fiberbridge
