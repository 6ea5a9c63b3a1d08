#include "fiberbridge/core/csv.h"

#include "cells.h"

#include "fiberbridge/core/error.h"
#include "fiberbridge/core/format.h"
#include "fiberbridge/core/output_guard.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace fiberbridge {

namespace {

/// The cells of one line of our own CSV: commas separate them (cells::split). `where` is
/// "file:line" for messages.
std::vector<std::string> split_cells(const std::string& line, const std::string& where) {
  std::vector<std::string> cells;
  cells::Fault fault{};
  if (!cells::split(line, ',', cells, &fault))
    throw InputError(where + (fault == cells::Fault::unclosed_quote
                                  ? ": a quoted cell has no closing quote (quoted cells must end "
                                    "on their line)"
                                  : ": text after the closing quote of a quoted cell"));
  return cells;
}

} // namespace

CsvTable CsvTable::read(const std::string& path) {
  std::ifstream in(path);
  if (!in)
    throw InputError(path + ": cannot open file for reading");
  std::stringstream buffer;
  buffer << in.rdbuf();
  return parse(buffer.str(), path);
}

CsvTable CsvTable::parse(const std::string& text, const std::string& source_name) {
  CsvTable t;
  t.source_ = source_name;
  // A UTF-8 byte-order mark (spreadsheet exports) is not part of the first column's name.
  const std::string bom = "\xEF\xBB\xBF";
  std::istringstream in(text.compare(0, bom.size(), bom) == 0 ? text.substr(bom.size()) : text);
  std::string line;
  std::size_t line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    const std::string content = trim_blanks(line, cell_blanks);
    if (content.empty() || content[0] == '#')
      continue;
    auto cells = split_cells(content, source_name + ":" + std::to_string(line_no));
    if (t.header_.empty()) {
      t.header_ = cells;
      for (std::size_t i = 0; i < cells.size(); ++i) {
        if (cells[i].empty())
          throw InputError(source_name + ":" + std::to_string(line_no) + ": header column " +
                           std::to_string(i + 1) + " has no name");
        for (std::size_t j = 0; j < i; ++j)
          if (cells[j] == cells[i])
            throw InputError(source_name + ":" + std::to_string(line_no) + ": duplicate column '" +
                             cells[i] + "' in header");
      }
      t.columns_.resize(cells.size());
      continue;
    }
    if (cells.size() != t.header_.size())
      throw InputError(source_name + ":" + std::to_string(line_no) + ": expected " +
                       std::to_string(t.header_.size()) + " comma-separated values (header has " +
                       std::to_string(t.header_.size()) + " columns), found " +
                       std::to_string(cells.size()));
    for (std::size_t i = 0; i < cells.size(); ++i)
      t.columns_[i].push_back(cells[i]);
    t.line_numbers_.push_back(line_no);
  }
  if (t.header_.empty())
    throw InputError(source_name + ": empty file, expected a header line with column names");
  if (t.line_numbers_.empty())
    throw InputError(source_name + ": header found but no data rows");
  return t;
}

bool CsvTable::has_column(const std::string& name) const {
  for (const auto& h : header_)
    if (h == name)
      return true;
  return false;
}

std::size_t CsvTable::index_of(const std::string& name) const {
  for (std::size_t i = 0; i < header_.size(); ++i)
    if (header_[i] == name)
      return i;
  std::string have;
  for (const auto& h : header_)
    have += (have.empty() ? "" : ", ") + h;
  throw InputError(source_ + ": missing column '" + name + "' (columns present: " + have + ")");
}

const std::vector<std::string>& CsvTable::text(const std::string& name) const {
  return columns_[index_of(name)];
}

std::vector<double> CsvTable::numeric(const std::string& name) const {
  const auto& cells = columns_[index_of(name)];
  std::vector<double> values(cells.size());
  for (std::size_t r = 0; r < cells.size(); ++r) {
    const std::string& c = cells[r];
    char* end = nullptr;
    errno = 0;
    const double v = c.empty() ? NAN : std::strtod(c.c_str(), &end);
    if (c.empty() || end != c.c_str() + c.size() || errno == ERANGE || !std::isfinite(v))
      throw InputError(source_ + ":" + std::to_string(line_numbers_[r]) + ": column '" + name +
                       "' holds '" + c + "', expected a finite number");
    values[r] = v;
  }
  return values;
}

void write_file_atomically(const std::string& path, const std::string& content) {
  if (!output_enabled()) // an MPI rank other than 0: rank 0 writes this file (output_guard.h)
    return;
  const std::string tmp = path + ".partial";
  {
    std::ofstream out(tmp, std::ios::trunc);
    if (!out)
      throw InputError(path + ": cannot open for writing");
    out << content;
    out.flush();
    if (!out)
      throw InputError(path + ": write failed");
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0)
    throw InputError(path + ": cannot rename temporary file into place");
}

CsvWriter::CsvWriter(const std::string& path, const std::vector<std::string>& header,
                     const std::vector<std::string>& comment_lines)
    : path_(path), n_columns_(header.size()) {
  for (const auto& c : comment_lines)
    buffer_ += "# " + c + "\n";
  for (std::size_t i = 0; i < header.size(); ++i)
    buffer_ += (i ? "," : "") + header[i];
  buffer_ += "\n";
}

CsvWriter::~CsvWriter() {
  // An unclosed writer (an exception unwound past it) leaves no file behind.
}

void CsvWriter::row(const std::vector<double>& values) {
  if (values.size() != n_columns_)
    throw std::logic_error("CsvWriter::row: " + path_ + " expects " + std::to_string(n_columns_) +
                           " values, got " + std::to_string(values.size()));
  std::ostringstream s;
  s << std::setprecision(10);
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i)
      s << ',';
    if (std::isfinite(values[i]))
      s << values[i];
  }
  s << '\n';
  buffer_ += s.str();
}

void CsvWriter::row(const std::vector<std::string>& labels, const std::vector<double>& values) {
  if (labels.size() + values.size() != n_columns_)
    throw std::logic_error("CsvWriter::row: " + path_ + " expects " + std::to_string(n_columns_) +
                           " cells, got " + std::to_string(labels.size() + values.size()));
  for (const auto& l : labels) {
    if (l.find(',') != std::string::npos)
      throw std::logic_error("CsvWriter::row: label with a comma: " + l);
    buffer_ += l + ",";
  }
  const std::size_t keep = n_columns_;
  n_columns_ = values.size();
  row(values);
  n_columns_ = keep;
}

void CsvWriter::close() {
  if (closed_)
    return;
  write_file_atomically(path_, buffer_);
  closed_ = true;
}

} // namespace fiberbridge
