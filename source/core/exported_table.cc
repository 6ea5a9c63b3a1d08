// Machine-export tables: layout detection and parsing (exported_table.h).
#include "fiberbridge/core/exported_table.h"

#include "cells.h"

#include "fiberbridge/core/error.h"
#include "fiberbridge/core/format.h"
#include "fiberbridge/core/unit_parse.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
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

bool valid_utf8(const std::string& s) {
  for (std::size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    const std::size_t n = c < 0x80         ? 1
                          : (c >> 5) == 6  ? 2
                          : (c >> 4) == 14 ? 3
                          : (c >> 3) == 30 ? 4
                                           : 0;
    if (n == 0 || i + n > s.size())
      return false;
    for (std::size_t k = 1; k < n; ++k)
      if ((static_cast<unsigned char>(s[i + k]) >> 6) != 2)
        return false;
    i += n;
  }
  return true;
}

void append_utf8(std::string& out, unsigned long code) {
  if (code < 0x80) {
    out += static_cast<char>(code);
  } else if (code < 0x800) {
    out += static_cast<char>(0xC0 | (code >> 6));
    out += static_cast<char>(0x80 | (code & 0x3F));
  } else if (code < 0x10000) {
    out += static_cast<char>(0xE0 | (code >> 12));
    out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (code >> 18));
    out += static_cast<char>(0x80 | ((code >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code & 0x3F));
  }
}

/// A line that is not UTF-8 is read as Latin-1 / Windows-1252, what German and French Windows
/// installations of testXpert and Bluehill write ("Prüfzeit", "µm"): each byte is its code point.
std::string latin1_to_utf8(const std::string& s) {
  std::string out;
  out.reserve(s.size() + 8);
  for (char c : s)
    append_utf8(out, static_cast<unsigned char>(c));
  return out;
}

/// Excel's "Unicode text" export is UTF-16 with a byte-order mark.
std::string utf16_to_utf8(const std::string& raw) {
  const bool little = static_cast<unsigned char>(raw[0]) == 0xFF;
  std::string out;
  out.reserve(raw.size() / 2);
  unsigned long high = 0;
  for (std::size_t i = 2; i + 1 < raw.size(); i += 2) {
    const auto a = static_cast<unsigned char>(raw[i]), b = static_cast<unsigned char>(raw[i + 1]);
    const unsigned long unit = little ? (b << 8 | a) : (a << 8 | b);
    if (unit >= 0xD800 && unit < 0xDC00) {
      high = unit;
      continue;
    }
    if (unit >= 0xDC00 && unit < 0xE000) {
      if (high)
        append_utf8(out, 0x10000 + ((high - 0xD800) << 10) + (unit - 0xDC00));
      high = 0;
      continue;
    }
    high = 0;
    append_utf8(out, unit);
  }
  return out;
}

bool is_utf16(const std::string& raw) {
  return raw.size() >= 2 && ((static_cast<unsigned char>(raw[0]) == 0xFF &&
                              static_cast<unsigned char>(raw[1]) == 0xFE) ||
                             (static_cast<unsigned char>(raw[0]) == 0xFE &&
                              static_cast<unsigned char>(raw[1]) == 0xFF));
}

/// Content lines: not blank, not a '#' comment. A byte-order mark is dropped; "\r\n", "\n" and
/// a lone "\r" (old Mac exports) all end a line. `latin1` is set when a line had to be read as
/// Latin-1.
std::vector<Line> content_lines(const std::string& raw, bool& latin1,
                                std::size_t max_lines = static_cast<std::size_t>(-1)) {
  const std::string bom = "\xEF\xBB\xBF";
  const std::size_t start = raw.compare(0, bom.size(), bom) == 0 ? bom.size() : 0;
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
    if (std::any_of(t.begin(), t.end(), [](char c) { return c & 0x80; }) && !valid_utf8(t)) {
      t = latin1_to_utf8(t);
      latin1 = true;
    }
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
         std::string(encoding) != "UTF-8" || repeated_headers != 0 || short_rows != 0 ||
         trailer_lines != 0;
}

std::string TableLayout::describe() const {
  std::ostringstream s;
  s << "Read as " << delimiter_name(delimiter) << "-separated with a decimal "
    << (decimal == ',' ? "comma" : "point");
  if (std::string(encoding) != "UTF-8")
    s << " (text in " << encoding << ")";
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
  if (short_rows)
    s << "; " << short_rows << " row(s) with fewer cells than the header (missing cells empty)";
  s << ".";
  return s.str();
}

TableLayout detect_table_layout(const std::string& raw, const std::string& source) {
  const std::string text = is_utf16(raw) ? utf16_to_utf8(raw) : raw;
  bool latin1 = false;
  // Only the lines detection can look at: its cost does not grow with the record.
  auto layout =
      detect(content_lines(text, latin1, max_detection_lines + data_run), text, source).layout;
  layout.encoding = is_utf16(raw) ? "UTF-16" : latin1 ? "Latin-1" : "UTF-8";
  return layout;
}

ExportedTable ExportedTable::read(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw InputError(path + ": cannot open file for reading");
  std::stringstream buffer;
  buffer << in.rdbuf();
  return parse(buffer.str(), path);
}

ExportedTable ExportedTable::parse(const std::string& raw, const std::string& source_name) {
  const std::string text = is_utf16(raw) ? utf16_to_utf8(raw) : raw;
  bool latin1 = false;
  const std::vector<Line> lines = content_lines(text, latin1);
  Detected d = detect(lines, text, source_name);
  d.layout.encoding = is_utf16(raw) ? "UTF-16" : latin1 ? "Latin-1" : "UTF-8";
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
  for (std::size_t i = d.first_data; i < end; ++i) {
    const std::string at = source_name + ":" + std::to_string(lines[i].number);
    if (!cells::split(lines[i].text, d.layout.delimiter, cells))
      throw InputError(at + ": a quoted cell has no closing quote or text follows it (quoted "
                            "cells must end on their line)");
    if (cells == raw_header || (!raw_units.empty() && cells == raw_units) ||
        (d.layout.delimiter == ' ' && join_bracketed_units(cells) == raw_header)) {
      ++t.layout_.repeated_headers;
      continue;
    }
    while (cells.size() > n && cells.back().empty())
      cells.pop_back();
    if (cells.size() > n)
      throw InputError(at + ": " + std::to_string(cells.size()) +
                       " cells, but the header on line " + std::to_string(d.layout.header_line) +
                       " and the rows above have " + std::to_string(n));
    if (cells.size() < n) {
      ++t.layout_.short_rows;
      cells.resize(n);
    }
    for (std::size_t c = 0; c < n; ++c)
      t.columns_[c].push_back(std::move(cells[c]));
    t.line_numbers_.push_back(lines[i].number);
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
                       header_[column] + "' holds '" + cells[r] + "', expected a number (decimal " +
                       (layout_.decimal == ',' ? "comma" : "point") + ") or an empty cell");
    values[r] = NAN;
  }
  if (grouped)
    *grouped = n_grouped;
  return values;
}

} // namespace fiberbridge
