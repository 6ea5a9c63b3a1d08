#pragma once
// Private to the record reader: the cleaning of one record's rows (test_record.h lists the steps,
// docs/design.md section 6 the classes of fault and why each is fixed or refused).
#include "record_columns.h"

#include <string>
#include <vector>

namespace fiberbridge::analysis {

/// Cleans the rows `rows` (indices into `t`, file order) of record `name`.
TestRecord clean_record(const ExportedTable& t, const RecordColumns& c, const std::string& name,
                        const std::vector<std::size_t>& rows, const RecordReadOptions& o);

} // namespace fiberbridge::analysis
