#include "record_input.h"

#include "arrays.h"

#include "fiberbridge/core/units.h"

#include <utility>

namespace fiberbridge::python {

namespace {

/// The dict's column `key` times `unit` (1e-3 for mm), empty when absent or None: one pass over
/// the caller's buffer (numpy hands a contiguous float64 array over without a copy).
std::vector<double> column_si(const py::dict& d, const char* key, double unit) {
  if (!d.contains(key) || d[key].is_none())
    return {};
  const auto column = py::cast<ColumnIn>(d[key]);
  const double* p = column.data();
  std::vector<double> v(static_cast<std::size_t>(column.size()));
  for (std::size_t i = 0; i < v.size(); ++i)
    v[i] = p[i] * unit;
  return v;
}

} // namespace

std::vector<RecordIn> records_in(const py::list& items) {
  std::vector<RecordIn> out;
  for (const py::handle item : items) {
    RecordIn r;
    if (py::isinstance<py::str>(item)) {
      r.path = py::cast<std::string>(item);
    } else {
      const auto d = py::cast<py::dict>(item);
      r.arrays.name = py::cast<std::string>(d["name"]);
      r.arrays.source = py::cast<std::string>(d["source"]);
      r.arrays.time = column_si(d, "time_s", 1);
      r.arrays.opening = column_si(d, "opening_mm", units::mm);
      r.arrays.load = column_si(d, "load_N", 1);
      r.arrays.crack_length = column_si(d, "a_mm", units::mm);
      r.arrays.delta_root = column_si(d, "delta_root_mm", units::mm);
    }
    out.push_back(std::move(r));
  }
  return out;
}

std::vector<analysis::TestRecord> read_records_in(std::vector<RecordIn> in,
                                                  const analysis::RecordReadOptions& read) {
  std::vector<analysis::TestRecord> records;
  for (auto& r : in) {
    if (r.path.empty())
      analysis::add_record(records,
                           analysis::clean_test_record(std::move(r.arrays), read, units::mm));
    else
      for (auto& rec : analysis::read_test_records(r.path, read))
        analysis::add_record(records, std::move(rec));
  }
  return records;
}

} // namespace fiberbridge::python
