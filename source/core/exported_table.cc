// Machine-export tables: layout detection and parsing (exported_table.h).
#include "fiberbridge/core/exported_table.h"

#include "cells.h"

#include "fiberbridge/core/error.h"
#include "fiberbridge/core/format.h"
#include "fiberbridge/core/text_encoding.h"
#include "fiberbridge/core/unit_parse.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace fiberbridge {

namespace {

/// Detection looks at no more than this many content lines before the first data row (a
/// preamble is a few dozen lines at most), so its cost does not grow with the record.
constexpr std::size_t max_detection_lines = 2000;
/// Consecutive data-like lines of equal width that mark the start of the data.
constexpr std::size_t data_run = 3;

struct Line {
  std::size_t number; ///< 1-based
  std::string text;   ///< without the line end, trimmed of trailing blanks
};

/// Content lines of UTF-8 text: not blank, not a '#' comment. "\r\n", "\n" and a lone "\r"
/// (old Mac exports) all end a line.
std::vector<Line> content_lines(const std::string& raw,
                                std::size_t max_lines = static_cast<std::size_t>(-1)) {
  const std::size_t start = 0;
  const bool cr_only = raw.find('\n') == std::string::npos;
  const char end = cr_only ? '\r' : '\n';
  std::vector<Line> lines;
  std::size_t number = 0;
  for (std::size_t i = start; i <= raw.size() && lines.size() < max_lines;) {
    std::size_t j = raw.find(end, i);
    if (j == std::string::npos)
      j = raw.size();
    ++number;
    std::string t = trim_blanks(raw.substr(i, j - i), cell_blanks);
    if (!t.empty() && t[0] != '#')
      lines.push_back({number, std::move(t)});
    i = j + 1;
  }
  return lines;
}

enum class CellKind { number, missing, text };

CellKind kind_of(const std::string& cell, char decimal) {
  double v;
  if (parse_exported_number(cell, decimal, v))
    return CellKind::number;
  return is_missing_value(cell) ? CellKind::missing : CellKind::text;
}

/// A data row: at least two numbers and fewer text cells than numbers (a record label or a
/// status column may be text).
bool is_data(const std::vector<std::string>& cells, char decimal) {
  std::size_t numbers = 0, texts = 0;
  for (const auto& c : cells) {
    const auto k = kind_of(c, decimal);
    numbers += k == CellKind::number;
    texts += k == CellKind::text;
  }
  return numbers >= 2 && texts < numbers;
}

/// A units row: every non-empty cell a bracketed text or a unit this reader knows, at least one.
bool is_units_row(const std::vector<std::string>& cells) {
  std::size_t units = 0;
  for (const auto& c : cells) {
    if (c.empty())
      continue;
    const bool bracketed =
        (c.front() == '(' && c.back() == ')') || (c.front() == '[' && c.back() == ']');
    if (!bracketed && !units::is_known_unit(c))
      return false;
    ++units;
  }
  return units > 0;
}

/// The decimal separator of a file whose delimiter is not a comma: a comma when a "1.234,5"
/// grouping shows up (and no "1,234.5"), a point for the reverse; otherwise the separator written
/// between digits more often ("0,5" against "0.5"). Counted rather than merely seen: a preamble's
/// date ("Datum: 05.12.2026") or version number above thousands of "0,5" readings must not make
/// the file a decimal-point one (whose data rows then hold no number).
char detect_decimal(const std::string& text) {
  std::size_t comma = 0, dot = 0;
  bool euro = false, english = false;
  const auto digit = [&](std::size_t k) {
    return k < text.size() && std::isdigit(static_cast<unsigned char>(text[k]));
  };
  for (std::size_t k = 1; k + 1 < text.size(); ++k) {
    const char c = text[k];
    if ((c != ',' && c != '.') || !digit(k - 1) || !digit(k + 1))
      continue;
    ++(c == ',' ? comma : dot);
    // A group of three digits then the other separator: "1.234,5" or "1,234.5".
    if (digit(k + 2) && digit(k + 3) && k + 4 < text.size() && digit(k + 5)) {
      if (c == '.' && text[k + 4] == ',')
        euro = true;
      if (c == ',' && text[k + 4] == '.')
        english = true;
    }
  }
  if (euro != english)
    return euro ? ',' : '.';
  return comma > dot ? ',' : '.';
}

/// In a blank-separated header, "Load (kN)" is two tokens: a bracketed token joins the one
/// before it.
std::vector<std::string> join_bracketed_units(const std::vector<std::string>& cells) {
  std::vector<std::string> out;
  for (const auto& c : cells)
    if (!out.empty() && !c.empty() && (c.front() == '(' || c.front() == '['))
      out.back() += " " + c;
    else
      out.push_back(c);
  return out;
}

const char* delimiter_name(char d) {
  switch (d) {
  case '\t':
    return "tab";
  case ';':
    return "semicolon";
  case ',':
    return "comma";
  default:
    return "blank";
  }
}

struct Detected {
  TableLayout layout;
  std::size_t n_columns = 0;
  std::size_t first_data = 0; ///< index into the content lines
  std::vector<std::string> header, units;
};

/// Tries one delimiter; false when it finds no run of data rows with a header above. The data
/// start at the first line that begins `data_run` data rows of equal width (or a shorter run that
/// ends the file); lines are classified only up to there.
bool try_delimiter(const std::vector<Line>& lines, char delim, char decimal, Detected& d) {
  std::vector<std::string> cells;
  std::vector<std::size_t> widths;
  std::vector<char> data;
  const auto classify = [&](std::size_t i) {
    while (widths.size() <= i) {
      const std::size_t k = widths.size();
      const bool ok = cells::split(lines[k].text, delim, cells);
      widths.push_back(ok ? cells.size() : 0);
      data.push_back(ok && cells.size() >= 2 && is_data(cells, decimal));
    }
  };
  const std::size_t limit = std::min(lines.size(), max_detection_lines);
  std::size_t f = 0;
  for (; f < limit; ++f) {
    classify(f);
    if (!data[f])
      continue;
    std::size_t run = 1;
    while (run < data_run && f + run < lines.size()) {
      classify(f + run);
      if (!data[f + run] || widths[f + run] != widths[f])
        break;
      ++run;
    }
    if (run == data_run || f + run == lines.size())
      break;
  }
  if (f >= limit || f == 0) // no data, or data without a header above
    return false;
  d.first_data = f;
  d.n_columns = widths[f];
  std::size_t h = f - 1;
  cells::split(lines[h].text, delim, cells);
  if (is_units_row(cells) && h > 0) {
    d.units = cells;
    d.layout.units_line = lines[h].number;
    --h;
  }
  if (!cells::split(lines[h].text, delim, cells))
    return false;
  d.header = delim == ' ' ? join_bracketed_units(cells) : cells;
  d.layout.delimiter = delim;
  d.layout.decimal = decimal;
  d.layout.header_line = lines[h].number;
  d.layout.first_data_line = lines[f].number;
  d.layout.preamble_lines = h;
  return true;
}

Detected detect(const std::vector<Line>& lines, const std::string& raw, const std::string& source) {
  if (lines.empty())
    throw InputError(source + ": empty file, expected a header line and rows of numbers");
  // The decimal convention shows in the first 256 kB (some 5000 rows): enough, and it keeps
  // detection's cost independent of the record's length.
  const char other_decimal = detect_decimal(raw.substr(0, std::size_t(1) << 18));
  for (char delim : {'\t', ';', ',', ' '}) {
    Detected d;
    if (try_delimiter(lines, delim, delim == ',' ? '.' : other_decimal, d))
      return d;
  }
  throw InputError(source + ": no header line followed by rows of numbers found (tried tab-, "
                            "semicolon-, comma- and blank-separated cells; a data row needs at "
                            "least two numbers)");
}

/// Lines between two blocks of one export (a block title, a time stamp, a blank): at most this
/// many before the header repeats, else they are no block break.
constexpr std::size_t max_block_break_lines = 12;

/// "Specimen 2" for a line that titles a specimen's block (Bluehill "Specimen 2", "Sample: 3",
/// testXpert "Probe 2" / "Prüfkörper 2"); "" for any other line.
std::string specimen_label(const std::vector<std::string>& cells) {
  std::string text;
  for (const auto& c : cells)
    if (!c.empty())
      text += (text.empty() ? "" : " ") + c;
  std::string low;
  for (char c : text)
    low += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const char* word : {"specimen", "sample", "probe",
                           "pr\xC3\xBC"
                           "fk\xC3\xB6rper"}) {
    const std::string w = word;
    if (low.rfind(w, 0) != 0 || text.size() > 60)
      continue;
    // The word, an optional '#', ':' or '-', then an identifier.
    std::string rest = text.substr(w.size());
    while (!rest.empty() && (rest[0] == ' ' || rest[0] == ':' || rest[0] == '#' || rest[0] == '-'))
      rest.erase(0, 1);
    if (rest.empty() || rest.find(' ') != std::string::npos)
      return "";
    return text.substr(0, w.size()) + " " + rest;
  }
  return "";
}

/// A NUL or other control byte in decoded text is no character a testing machine writes: it is
/// a damaged file (a NUL-filled tail from a crash while writing, binary garbage, UTF-16 that lost
/// a byte). Its rows cannot be read, and they must not pass as "results after the data" (issue
/// 42: a tail set aside that way silently shortened the record), so the file is refused with the
/// extent of the damage. Tab, line ends, form feed and a final Ctrl-Z (DOS end of file) are text.
void refuse_damaged_text(const std::string& text, const std::string& source) {
  std::size_t first = std::string::npos, count = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto b = static_cast<unsigned char>(text[i]);
    const bool control =
        (b < 0x20 && b != '\t' && b != '\n' && b != '\r' && b != '\f') || b == 0x7F;
    if (!control || (b == 0x1A && i + 1 == text.size()))
      continue;
    if (first == std::string::npos)
      first = i;
    ++count;
  }
  if (first == std::string::npos)
    return;
  const auto line_of = [&](std::size_t at) {
    return 1 + static_cast<std::size_t>(std::count(text.begin(), text.begin() + at, '\n'));
  };
  const std::size_t total = line_of(text.size());
  char byte[8];
  std::snprintf(byte, sizeof byte, "0x%02X", static_cast<unsigned char>(text[first]));
  throw InputError(source + ":" + std::to_string(line_of(first)) + ": the file is damaged: " +
                   std::to_string(count) + " NUL or control byte(s) (the first " + byte +
                   ") from this line on, of " + std::to_string(total) +
                   " line(s); the rows there cannot be read and are not dropped silently. "
                   "Re-export the file, or cut it before this line if the rows above suffice");
}

std::string lower(std::string s) {
  for (auto& c : s)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

} // namespace

bool is_missing_value(const std::string& cell) {
  static const char* const tokens[] = {"",  "nan", "-nan", "+nan", "n/a",  "#n/a", "na",
                                       "-", "--",  "---",  "null", "none", "#nv",  "nv"};
  const std::string c = lower(trim_blanks(cell, cell_blanks));
  return std::find(std::begin(tokens), std::end(tokens), c) != std::end(tokens);
}

bool parse_exported_number(const std::string& cell, char decimal, double& value, bool* grouped) {
  const char group = decimal == ',' ? '.' : ',';
  std::string clean;
  clean.reserve(cell.size());
  std::size_t i = 0;
  const std::size_t n = cell.size();
  while (i < n && cell[i] == ' ')
    ++i;
  if (i < n && (cell[i] == '-' || cell[i] == '+')) {
    if (cell[i] == '-')
      clean += '-';
    ++i;
  }
  // Integer part, possibly grouped: 1-3 digits, then groups of exactly three.
  std::size_t digits = 0, group_len = 0, groups = 0;
  for (; i < n; ++i) {
    const char c = cell[i];
    if (std::isdigit(static_cast<unsigned char>(c))) {
      clean += c;
      ++digits;
      ++group_len;
    } else if ((c == group || c == '\'') && i + 1 < n &&
               std::isdigit(static_cast<unsigned char>(cell[i + 1]))) {
      if (group_len == 0 || group_len > 3 || (groups > 0 && group_len != 3))
        return false;
      ++groups;
      group_len = 0;
    } else {
      break;
    }
  }
  if (groups > 0 && group_len != 3)
    return false;
  std::size_t fraction = 0;
  if (i < n && cell[i] == decimal) {
    clean += '.';
    for (++i; i < n && std::isdigit(static_cast<unsigned char>(cell[i])); ++i, ++fraction)
      clean += cell[i];
  }
  if (digits + fraction == 0)
    return false;
  if (i < n && (cell[i] == 'e' || cell[i] == 'E')) {
    clean += 'e';
    ++i;
    if (i < n && (cell[i] == '-' || cell[i] == '+'))
      clean += cell[i++];
    std::size_t e = 0;
    for (; i < n && std::isdigit(static_cast<unsigned char>(cell[i])); ++i, ++e)
      clean += cell[i];
    if (e == 0)
      return false;
  }
  while (i < n && cell[i] == ' ')
    ++i;
  if (i != n)
    return false;
  double v = 0;
  const auto r = std::from_chars(clean.data(), clean.data() + clean.size(), v);
  if (r.ec != std::errc() || r.ptr != clean.data() + clean.size() || !std::isfinite(v))
    return false;
  value = v;
  if (grouped && groups > 0)
    *grouped = true;
  return true;
}

bool TableLayout::is_export() const {
  return delimiter != ',' || decimal != '.' || units_line != 0 || preamble_lines != 0 ||
         encoding != "UTF-8" || repeated_headers != 0 || short_rows != 0 || trailer_lines != 0 ||
         continued_blocks != 0 || specimen_blocks != 0;
}

std::string TableLayout::describe() const {
  std::ostringstream s;
  s << "Read as " << delimiter_name(delimiter) << "-separated with a decimal "
    << (decimal == ',' ? "comma" : "point");
  if (encoding != "UTF-8" || encoding_how != "detected")
    s << " (text in " << encoding << ", " << encoding_how << ")";
  if (preamble_lines)
    s << "; " << preamble_lines << " preamble line(s) above the header on line " << header_line
      << " skipped";
  else
    s << "; header on line " << header_line;
  if (units_line)
    s << "; units row on line " << units_line;
  if (repeated_headers)
    s << "; " << repeated_headers
      << " repeat(s) of the header or units row inside the data skipped";
  if (trailer_lines)
    s << "; " << trailer_lines << " line(s) after the data from line " << trailer_line
      << " (results or notes, not rows) set aside";
  if (continued_blocks)
    s << "; " << continued_blocks + 1 << " data blocks (" << continued_blocks
      << " new block(s) with the same header inside the data) read as one record";
  if (specimen_blocks)
    s << "; " << specimen_blocks << " specimen blocks, one record each";
  if (short_rows)
    s << "; " << short_rows << " row(s) with fewer cells than the header (missing cells empty)";
  s << ".";
  return s.str();
}

TableLayout detect_table_layout(const std::string& raw, const std::string& source,
                                const std::string& encoding) {
  DecodedText decoded = decode_text(raw, encoding, source);
  refuse_damaged_text(decoded.utf8, source);
  const std::string& text = decoded.utf8;
  // Only the lines detection can look at: its cost does not grow with the record.
  auto layout = detect(content_lines(text, max_detection_lines + data_run), text, source).layout;
  layout.encoding = decoded.encoding;
  layout.encoding_how = decoded.how;
  return layout;
}

ExportedTable ExportedTable::read(const std::string& path, const std::string& encoding) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw InputError(path + ": cannot open file for reading");
  std::stringstream buffer;
  buffer << in.rdbuf();
  return parse(buffer.str(), path, encoding);
}

ExportedTable ExportedTable::parse(const std::string& raw, const std::string& source_name,
                                   const std::string& encoding) {
  DecodedText decoded = decode_text(raw, encoding, source_name);
  refuse_damaged_text(decoded.utf8, source_name);
  const std::string& text = decoded.utf8;
  const std::vector<Line> lines = content_lines(text);
  Detected d = detect(lines, text, source_name);
  d.layout.encoding = decoded.encoding;
  d.layout.encoding_how = decoded.how;
  ExportedTable t;
  t.source_ = source_name;
  t.layout_ = d.layout;
  const std::size_t n = d.n_columns;
  const std::string header_at = source_name + ":" + std::to_string(d.layout.header_line);
  // Trailing empty header cells (a delimiter at the end of the line) name nothing.
  while (d.header.size() > n && d.header.back().empty())
    d.header.pop_back();
  if (d.header.size() > n)
    throw InputError(header_at + ": the header has " + std::to_string(d.header.size()) +
                     " names but the data rows below it " + std::to_string(n) + " cells");
  const std::vector<std::string> raw_header = d.header, raw_units = d.units;
  d.header.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    d.header[i] = trim_blanks(d.header[i], cell_blanks);
  t.header_ = d.header;
  t.units_.assign(n, "");
  for (std::size_t i = 0; i < n && i < d.units.size(); ++i)
    t.units_[i] = units::strip_unit_brackets(d.units[i]);
  t.columns_.resize(n);
  for (auto& c : t.columns_)
    c.reserve(lines.size() - d.first_data);
  t.line_numbers_.reserve(lines.size() - d.first_data);
  std::vector<std::string> cells;
  // A trailer after the data (Bluehill and testXpert can append results: "Maximum Load,95.2")
  // is not data: the lines after the last data-like one are set aside and counted.
  std::size_t end = lines.size();
  while (end > d.first_data + 1) {
    const bool ok = cells::split(lines[end - 1].text, d.layout.delimiter, cells);
    if (ok && cells.size() >= 2 && is_data(cells, d.layout.decimal))
      break;
    --end;
  }
  if (end < lines.size()) {
    t.layout_.trailer_lines = lines.size() - end;
    t.layout_.trailer_line = lines[end].number;
  }
  const auto is_header = [&](const std::vector<std::string>& c) {
    return c == raw_header || (!raw_units.empty() && c == raw_units) ||
           (d.layout.delimiter == ' ' && join_bracketed_units(c) == raw_header);
  };
  // The first block's specimen label stands in the preamble ("Specimen 1" above the header).
  t.block_labels_.push_back("");
  for (std::size_t k = 0; k < d.first_data; ++k)
    if (cells::split(lines[k].text, d.layout.delimiter, cells) && !specimen_label(cells).empty())
      t.block_labels_[0] = specimen_label(cells);
  // A preamble's "Probe : DCB-01" alone names no stack: one specimen stays one record named
  // after the file; only a second titled block makes the file a stack.
  bool specimen_blocks = false;
  std::size_t block = 0;
  for (std::size_t i = d.first_data; i < end; ++i) {
    const std::string at = source_name + ":" + std::to_string(lines[i].number);
    if (!cells::split(lines[i].text, d.layout.delimiter, cells))
      throw InputError(at + ": a quoted cell has no closing quote or text follows it (quoted "
                            "cells must end on their line)");
    if (is_header(cells)) {
      ++t.layout_.repeated_headers;
      continue;
    }
    // A block break: lines that are not data ("Data Acquisition", "Specimen 2", a time stamp)
    // followed by the header again. MTS 793 MPT writes one block per data acquisition of the
    // same test (continued); Bluehill and testXpert one per specimen (new records).
    if (!is_data(cells, d.layout.decimal)) {
      std::size_t k = i;
      std::string label;
      std::vector<std::string> c2;
      for (; k < end && k < i + max_block_break_lines; ++k) {
        cells::split(lines[k].text, d.layout.delimiter, c2);
        if (is_header(c2) || is_data(c2, d.layout.decimal))
          break; // a units row alone is no break: the block's own header stood above it
        if (label.empty())
          label = specimen_label(c2);
      }
      const bool same_names =
          c2 == raw_header || (d.layout.delimiter == ' ' && join_bracketed_units(c2) == raw_header);
      if (k < end && k > i && same_names) {
        if (!label.empty()) {
          specimen_blocks = true;
          t.block_labels_.push_back(label);
          ++block;
        } else {
          ++t.layout_.continued_blocks;
        }
        i = k - 1;
        continue;
      }
      // Not a block break. A row with text cells and the wrong width is no row of this table
      // (a row of the right width goes on: its cells are named when read as numbers).
      while (cells.size() > n && cells.back().empty())
        cells.pop_back();
      const bool text = std::any_of(cells.begin(), cells.end(), [&](const std::string& c) {
        return kind_of(c, d.layout.decimal) == CellKind::text;
      });
      if (text && cells.size() != n)
        throw InputError(at + ": '" + message_excerpt(lines[i].text) +
                         "' is not a row of the table whose header is on line " +
                         std::to_string(d.layout.header_line) + " (" +
                         std::to_string(cells.size()) + " cells, expected " + std::to_string(n) +
                         "): a new block with another header, a second table, or a damaged "
                         "line; the file cannot be read or split unambiguously");
    }
    while (cells.size() > n && cells.back().empty())
      cells.pop_back();
    if (cells.size() > n)
      throw InputError(at + ": " + std::to_string(cells.size()) +
                       " cells, but the header on line " + std::to_string(d.layout.header_line) +
                       " and the rows above have " + std::to_string(n) +
                       " (a new block with another header, or a damaged line: '" +
                       message_excerpt(lines[i].text) + "')");
    if (cells.size() < n) {
      ++t.layout_.short_rows;
      cells.resize(n);
    }
    for (std::size_t c = 0; c < n; ++c)
      t.columns_[c].push_back(std::move(cells[c]));
    t.line_numbers_.push_back(lines[i].number);
    t.block_of_row_.push_back(block);
  }
  if (!specimen_blocks) {
    t.block_labels_.clear();
    t.block_of_row_.clear();
  } else {
    for (std::size_t b = 0; b < t.block_labels_.size(); ++b) {
      if (t.block_labels_[b].empty())
        t.block_labels_[b] = "Specimen " + std::to_string(b + 1);
      for (std::size_t c = 0; c < b; ++c)
        if (t.block_labels_[c] == t.block_labels_[b])
          throw InputError(source_name + ": two specimen blocks are labelled '" +
                           message_excerpt(t.block_labels_[b]) +
                           "': the file cannot be split into records unambiguously");
    }
    t.layout_.specimen_blocks = t.block_labels_.size();
  }
  return t;
}

std::vector<double> ExportedTable::numeric(std::size_t column, std::size_t* grouped) const {
  const auto& cells = columns_.at(column);
  std::vector<double> values(cells.size());
  std::size_t n_grouped = 0;
  for (std::size_t r = 0; r < cells.size(); ++r) {
    bool g = false;
    if (parse_exported_number(cells[r], layout_.decimal, values[r], &g)) {
      n_grouped += g;
      continue;
    }
    if (!is_missing_value(cells[r]))
      throw InputError(source_ + ":" + std::to_string(line_numbers_[r]) + ": column '" +
                       message_excerpt(header_[column]) + "' holds '" + message_excerpt(cells[r]) +
                       "', expected a number (decimal " +
                       (layout_.decimal == ',' ? "comma" : "point") + ") or an empty cell");
    values[r] = NAN;
  }
  if (grouped)
    *grouped = n_grouped;
  return values;
}

} // namespace fiberbridge
