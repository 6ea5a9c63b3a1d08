#pragma once
// identify's private view of a record (docs/design.md section 6, "identify"): the record with the
// specimen, modulus and weights its misfit uses, prepared once before the optimizer runs.
#include "fiberbridge/identify/identify.h"

#include <functional>
#include <string>
#include <vector>

namespace fiberbridge::identify::detail {

/// One record prepared for the misfit: its specimen, modulus and weights.
struct PreparedRecord {
  const analysis::TestRecord* record;
  specimen::Specimen specimen;
  specimen::Material material;
  double peak_load = 0;
  double compliance = 0;
  std::vector<std::size_t> crack_rows; ///< fresh crack readings (the first excluded)
  /// A crack length at each row for start values and diagnostics: the reading, or without
  /// readings (load and opening alone) the corrected-beam-theory crack from the row's compliance,
  /// a + chi h = (a0 + chi h) (C/C0)^(1/3) (held at a0 or more; rows under 5 % of the peak a0).
  std::vector<double> crack_estimate;
};

/// The first crack reading of a record (rows without one are NaN; NaN when it has none).
double first_reading(const analysis::TestRecord& rec);

/// Each record with its a0 (the first crack reading, else the specimen's), its initial
/// compliance and modulus (calibrated when the settings say so) and its fresh crack readings.
/// The records must outlive the result (PreparedRecord::record points into them).
std::vector<PreparedRecord>
prepare_records(const std::vector<analysis::TestRecord>& records,
                const specimen::Specimen& specimen, const specimen::Material& quoted,
                const IdentifySettings& settings, const ForwardModel& forward,
                const std::function<void(const std::string&)>& progress);

} // namespace fiberbridge::identify::detail
