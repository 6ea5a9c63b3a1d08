// The one door of records to R(a) (record_chain.h).
#include "fiberbridge/analysis/record_chain.h"

#include "fiberbridge/core/error.h"

#include <cmath>

namespace fiberbridge::analysis {

void set_crack_length(RecordChainOptions& o, const std::string& word, const std::string& where) {
  if (word != "auto" && word != "measured" && word != "equivalent")
    throw InputError(where + ": expected auto, measured or equivalent, got '" + word + "'");
  o.read.crack_length =
      word == "measured" ? CrackLengthSource::measured : CrackLengthSource::automatic;
  o.reduce.use_equivalent_crack = word == "equivalent";
}

std::vector<TestRecord> read_records(const std::vector<std::string>& files,
                                     const RecordReadOptions& read) {
  std::vector<TestRecord> records;
  for (const auto& f : files)
    for (auto& rec : read_test_records(f, read))
      add_record(records, std::move(rec));
  return records;
}

void add_record(std::vector<TestRecord>& records, TestRecord record) {
  for (const auto& other : records)
    if (other.name == record.name)
      throw InputError(record.source + ": record name '" + record.name +
                       "' repeats a record already read from " + other.source +
                       "; give each record its own name");
  records.push_back(std::move(record));
}

RecordChainOptions with_specimen_overrides(RecordChainOptions o, double width, double arm_thickness,
                                           double length, double initial_crack) {
  if (std::isfinite(width))
    o.specimen.width = width;
  if (std::isfinite(arm_thickness))
    o.specimen.height = 2 * arm_thickness; // both arms
  if (std::isfinite(length))
    o.specimen.length = length;
  if (std::isfinite(initial_crack)) {
    if (std::isfinite(o.specimen.initial_crack))
      o.specimen.initial_crack = initial_crack;
    o.reduce.initial_crack_without_readings = initial_crack;
  }
  return o;
}

} // namespace fiberbridge::analysis
