#pragma once
// The records-to-R(a) settings that every door shares (docs/design.md, "Test records", "One chain,
// one door"): the scene's `reduce`, `dic` then `reduce`, the campaign's raw-record and DIC-set
// rows, `identify`, and `fiberbridge reduce` read and reduce a record with one value of this type.
// A scene builds it once from its Test, Specimen and Material sections (app/scene/test_section.h,
// record_chain_options); the command line builds it from its options. Nothing else turns those
// sections into reduce options, so no door can skip a setting the others use.
#include "fiberbridge/analysis/record_reduction.h"
#include "fiberbridge/analysis/test_record.h"
#include "fiberbridge/specimen/specimen.h"

#include <string>
#include <vector>

namespace fiberbridge::analysis {

struct RecordChainOptions {
  RecordReadOptions read;
  /// Width, height, length, pin distances; initial_crack only when the scene asks that a0 be the
  /// Specimen's (else each record's first crack reading). Nothing known by default.
  specimen::Specimen specimen = specimen::Specimen::unknown();
  ReduceOptions reduce;
};

/// Where crack lengths come from, one word for every door (Test/Crack length, --crack-length):
/// "auto" (the crack column when the file has one), "measured" (the crack column is required) or
/// "equivalent" (R against the CBBM equivalent crack from the compliance; readings, when the file
/// has them, give a0 and are reported beside). Throws InputError naming `where` for another word.
void set_crack_length(RecordChainOptions& o, const std::string& word, const std::string& where);

/// Every record of every file, read with `read` in file order. Throws InputError when a record's
/// name repeats one already read (naming both files), besides what read_test_records throws.
std::vector<TestRecord> read_records(const std::vector<std::string>& files,
                                     const RecordReadOptions& read);

/// Appends `record` to `records`; throws InputError when its name repeats one there (naming both
/// sources): the records of a reduction are told apart by name in every table.
void add_record(std::vector<TestRecord>& records, TestRecord record);

/// `specimen` with what one specimen's own measurements replace (a campaign row's width, arm
/// thickness, length, a0; NaN: not given). The a0 replaces the Specimen's where the reduction
/// uses the Specimen's, and is the a0 of a record without crack readings.
RecordChainOptions with_specimen_overrides(RecordChainOptions o, double width, double arm_thickness,
                                           double length, double initial_crack);

} // namespace fiberbridge::analysis
