#pragma once
// The records a call takes (fb.reduce, fb.identify): files to read, or records a script holds as
// arrays (fb.read_record's, fb.dic's, its own columns). Both go through the reader's one cleaning
// (analysis::read_test_records, analysis::clean_test_record), so a record read by read_record
// and handed back reduces as its file does.
#include "fiberbridge/analysis/record_chain.h"

#include <pybind11/pybind11.h>

#include <string>
#include <vector>

namespace fiberbridge::python {

namespace py = pybind11;

/// One entry of a call's records: a file, or a record's columns (SI) with its name and source.
struct RecordIn {
  std::string path; ///< "" for a record given as arrays
  analysis::TestRecord arrays;
};

/// The call's entries, with the GIL held: a str is a file; a dict (name, source, time_s,
/// opening_mm, load_N, a_mm, delta_root_mm; None or a missing key: no such column) is a record's
/// columns, copied once into SI vectors.
std::vector<RecordIn> records_in(const py::list& items);

/// Every record of the entries in order, read or cleaned with `read` (no GIL needed); the
/// entries' columns are moved into the cleaning. Throws InputError as the reader does, and for a
/// name that repeats.
std::vector<analysis::TestRecord> read_records_in(std::vector<RecordIn> in,
                                                  const analysis::RecordReadOptions& read);

} // namespace fiberbridge::python
