#pragma once
// Private to the record reader: our columns found in a machine export through the column map,
// with their units read and converted to SI (test_record.h, docs/design.md section 6).
#include "fiberbridge/analysis/test_record.h"
#include "fiberbridge/core/exported_table.h"

#include <string>
#include <vector>

namespace fiberbridge::analysis {

/// The columns of a record file in SI, one entry per table row. Missing cells are NaN.
struct RecordColumns {
  std::vector<double> time, opening, load, crack, root;
  std::vector<std::string> labels; ///< the `record` column; empty without one
  std::string labels_header;       ///< the header the labels came from
  /// The labels came from a machine's own specimen column ("Specimen", "Sample", "Probe")
  /// rather than our `record` column: records are named from the file ("f.csv#2").
  bool labels_from_specimen_column = false;
  bool has_time = false, has_crack = false, has_root = false;
  /// The crack column's factor from the file's unit to m (dropout codes such as -999 are
  /// recognised in the file's own unit).
  double crack_factor = 1;
  /// Sentences for TestRecord::cleaning: the layout when the file is an export, and which header
  /// and unit each column was read from when not under our own name.
  std::vector<std::string> notes;
};

/// Finds and converts the columns (errors name the file, the header line and what was found).
RecordColumns read_record_columns(const ExportedTable& t, const RecordReadOptions& options);

} // namespace fiberbridge::analysis
