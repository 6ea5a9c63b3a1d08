#pragma once
// Private to the record reader: the cleaning of one record's rows (test_record.h lists the steps,
// docs/design.md section 6 the classes of fault and why each is fixed or refused).
#include "record_columns.h"

#include <functional>
#include <string>
#include <vector>

namespace fiberbridge::analysis {

/// Where the rows came from, for messages: the file (or the arrays' name) and the line each row
/// was read from (for arrays in memory, the row's own 1-based number).
struct RowOrigin {
  std::string source;
  std::function<std::size_t(std::size_t)> line_of_row;
};

/// Cleans the rows `rows` (indices into `c`'s columns, file order) of record `name`.
TestRecord clean_record(const RowOrigin& origin, const RecordColumns& c, const std::string& name,
                        const std::vector<std::size_t>& rows, const RecordReadOptions& o);

} // namespace fiberbridge::analysis
