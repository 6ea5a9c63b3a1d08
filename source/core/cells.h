#pragma once
// The one tokenizer of a table line (core's private header): the cells of our own CSV files
// (csv.h, comma-separated) and of machine exports (exported_table.h, any detected delimiter) are
// split here, so a quoted cell, a blank around a cell and a trailing delimiter read the same in
// both (docs/design.md section 6).
#include <string>
#include <vector>

namespace fiberbridge::cells {

/// Why a line could not be split.
enum class Fault {
  none,
  unclosed_quote,   ///< a quoted cell does not end on its line
  text_after_quote, ///< something other than the delimiter follows a closing quote
};

/// Splits `line` at `delim` (' ' = runs of blanks), honouring double quotes ("" inside a quoted
/// cell is one quote, RFC 4180); blanks around an unquoted cell are dropped, and a line ending in
/// the delimiter has an empty last cell (not so for runs of blanks). Returns false, with the
/// reason in `fault` when given, when the line cannot be split.
bool split(const std::string& line, char delim, std::vector<std::string>& cells,
           Fault* fault = nullptr);

} // namespace fiberbridge::cells
