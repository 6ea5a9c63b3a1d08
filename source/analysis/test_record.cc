// Reading raw DCB test records (test_record.h): the file's layout and units (record_columns.cc,
// core/exported_table.cc), the split into records, and the cleaning (record_cleaning.cc).
#include "fiberbridge/analysis/test_record.h"

#include "fiberbridge/core/error.h"
#include "fiberbridge/core/exported_table.h"
#include "fiberbridge/core/format.h"
#include "fiberbridge/core/units.h"
#include "record_cleaning.h"
#include "record_columns.h"

#include <algorithm>
#include <sstream>
#include <utility>

namespace fiberbridge::analysis {

namespace {

const char* const our_columns[] = {"time_s", "opening_mm",    "load_N",
                                   "a_mm",   "delta_root_mm", "record"};

/// A column map may come from a command line as well as a scene: line ends are blanks too.
constexpr const char* map_blanks = " \t\r\n";

std::string file_name(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

std::string stem(const std::string& path) {
  std::string name = file_name(path);
  const auto dot = name.find_last_of('.');
  return dot == std::string::npos || dot == 0 ? name : name.substr(0, dot);
}

} // namespace

RecordColumnMap RecordColumnMap::parse(const std::string& text, const std::string& where_) {
  RecordColumnMap m;
  if (trim_blanks(text, map_blanks).empty())
    return m;
  for (const auto& entry : split_list(text, ',', map_blanks)) {
    const auto colon = entry.find(':');
    if (colon == std::string::npos)
      throw InputError(where_ + ": column map entry '" + entry +
                       "' has no ':'; expected 'our_name: File header', e.g. 'load_N: Load (N)'");
    const std::string ours = trim_blanks(entry.substr(0, colon), map_blanks);
    const std::string theirs = trim_blanks(entry.substr(colon + 1), map_blanks);
    if (std::find(std::begin(our_columns), std::end(our_columns), ours) == std::end(our_columns))
      throw InputError(where_ + ": column map names '" + ours +
                       "'; expected one of time_s, opening_mm, load_N, a_mm, delta_root_mm, "
                       "record");
    if (theirs.empty())
      throw InputError(where_ + ": column map entry '" + ours + "' gives no file header");
    if (!m.file_header.emplace(ours, theirs).second)
      throw InputError(where_ + ": column map names '" + ours + "' twice");
  }
  return m;
}

std::string RecordColumnMap::header_for(const std::string& ours) const {
  const auto it = file_header.find(ours);
  return it == file_header.end() ? ours : it->second;
}

std::vector<TestRecord> read_test_records(const std::string& path,
                                          const RecordReadOptions& options) {
  const ExportedTable t = ExportedTable::read(path, options.encoding);
  const RecordColumns c = read_record_columns(t, options);

  // One record per label of the `record` column, in order of first appearance.
  std::vector<std::string> names;
  std::vector<std::vector<std::size_t>> rows;
  if (!c.labels.empty()) {
    std::map<std::string, std::size_t> index;
    for (std::size_t row = 0; row < t.n_rows(); ++row) {
      if (c.labels[row].empty())
        throw InputError(path + ":" + std::to_string(t.line_of_row(row)) + ": column '" +
                         c.labels_header +
                         "' is empty; expected a record label (the rows cannot be assigned to a "
                         "specimen unambiguously)");
      const auto it = index.emplace(c.labels[row], names.size());
      if (it.second) {
        names.push_back(c.labels_from_specimen_column ? file_name(path) + "#" + c.labels[row]
                                                      : c.labels[row]);
        rows.emplace_back();
      }
      rows[it.first->second].push_back(row);
    }
  } else if (!t.specimen_blocks().empty()) {
    // A stacked export: one record per specimen block, named from the file and the block's
    // title ("DCB.csv#Specimen 2") so that records of several files stay apart.
    for (const auto& label : t.specimen_blocks())
      names.push_back(file_name(path) + "#" + label);
    rows.resize(names.size());
    for (std::size_t row = 0; row < t.n_rows(); ++row)
      rows[t.block_of_row(row)].push_back(row);
    for (std::size_t k = 0; k < names.size(); ++k)
      if (rows[k].empty())
        throw InputError(path + ": specimen block '" + t.specimen_blocks()[k] +
                         "' holds no rows; the file cannot be split into records unambiguously");
  } else {
    names.push_back(stem(path));
    rows.emplace_back(t.n_rows());
    for (std::size_t row = 0; row < t.n_rows(); ++row)
      rows[0][row] = row;
  }
  const RowOrigin origin{t.source(), [&t](std::size_t row) { return t.line_of_row(row); }};
  std::vector<TestRecord> records;
  for (std::size_t k = 0; k < names.size(); ++k)
    records.push_back(clean_record(origin, c, names[k], rows[k], options));
  return records;
}

TestRecord clean_test_record(TestRecord given, const RecordReadOptions& options,
                             double crack_code_unit) {
  const std::string where = given.source;
  const std::size_t n = given.load.size();
  if (given.opening.size() != n)
    throw InputError(where + ": opening_mm has " + std::to_string(given.opening.size()) +
                     " values and load_N " + std::to_string(n) + "; expected one of each per row");
  const auto check = [&](const std::vector<double>& v, const char* column) {
    if (!v.empty() && v.size() != n)
      throw InputError(where + ": " + column + " has " + std::to_string(v.size()) + " values for " +
                       std::to_string(n) +
                       " rows of load_N; expected one per row or none (no such column)");
  };
  check(given.time, "time_s");
  check(given.crack_length, "a_mm");
  check(given.delta_root, "delta_root_mm");

  RecordColumns c;
  c.opening = std::move(given.opening);
  c.load = std::move(given.load);
  c.has_time = !given.time.empty();
  c.time = std::move(given.time);
  c.has_root = !given.delta_root.empty();
  c.root = std::move(given.delta_root);
  if (options.crack_length == CrackLengthSource::equivalent) {
    c.notes.push_back("Crack readings not used (Crack length = equivalent): R against the "
                      "equivalent crack length from the compliance.");
  } else if (given.crack_length.empty()) {
    if (options.crack_length == CrackLengthSource::measured)
      throw InputError(where + ": no a_mm column; expected crack-length readings (Crack "
                               "length = measured)");
    c.notes.push_back("No a_mm column: the record has no crack readings.");
  } else {
    c.has_crack = true;
    c.crack = std::move(given.crack_length);
    c.crack_factor = crack_code_unit;
  }
  std::vector<std::size_t> rows(n);
  for (std::size_t k = 0; k < n; ++k)
    rows[k] = k;
  const RowOrigin origin{where, [](std::size_t row) { return row + 1; }};
  return clean_record(origin, c, given.name, rows, options);
}

std::vector<std::size_t> crack_reading_rows(const TestRecord& r) {
  std::vector<std::size_t> rows;
  double last = NAN;
  for (std::size_t i = 0; i < r.crack_length.size(); ++i) {
    const double a = r.crack_length[i];
    if (!std::isnan(a) && a != last) {
      rows.push_back(i);
      last = a;
    }
  }
  return rows;
}

} // namespace fiberbridge::analysis
