#include "cells.h"

#include "fiberbridge/core/format.h"

namespace fiberbridge::cells {

bool split(const std::string& line, char delim, std::vector<std::string>& cells, Fault* fault) {
  if (fault)
    *fault = Fault::none;
  cells.clear();
  const bool blanks = delim == ' ';
  const auto is_sep = [&](char c) { return blanks ? (c == ' ' || c == '\t') : c == delim; };
  const auto is_pad = [&](char c) { return c == ' ' || (c == '\t' && delim != '\t') || c == '\r'; };
  std::size_t i = 0;
  const std::size_t n = line.size();
  while (true) {
    while (i < n && (is_pad(line[i]) || (blanks && is_sep(line[i]))))
      ++i;
    std::string cell;
    if (i < n && line[i] == '"') {
      bool closed = false;
      for (++i; i < n; ++i) {
        if (line[i] != '"') {
          cell += line[i];
        } else if (i + 1 < n && line[i + 1] == '"') {
          cell += '"';
          ++i;
        } else {
          closed = true;
          ++i;
          break;
        }
      }
      if (!closed) {
        if (fault)
          *fault = Fault::unclosed_quote;
        return false;
      }
      while (i < n && is_pad(line[i]) && !is_sep(line[i]))
        ++i;
      if (i < n && !is_sep(line[i])) {
        if (fault)
          *fault = Fault::text_after_quote;
        return false;
      }
    } else {
      std::size_t e = i;
      while (e < n && !is_sep(line[e]))
        ++e;
      cell = trim_blanks(line.substr(i, e - i), delim == '\t' ? " \r" : cell_blanks);
      i = e;
    }
    cells.push_back(std::move(cell));
    if (i >= n)
      return true;
    ++i; // the delimiter
    if (blanks) {
      while (i < n && is_sep(line[i]))
        ++i;
      if (i >= n)
        return true;
    }
  }
}

} // namespace fiberbridge::cells
