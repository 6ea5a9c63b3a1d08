#pragma once
// Vectors of the typed API as numpy arrays. A vector whose values go out in the unit they have
// inside (J/m^2, N, s) is moved into the array's owner, not copied; one that changes unit on the
// way out (m -> mm, Pa -> kPa: the names carry the unit, as the CSV columns do) is scaled into a
// new array. (Arrays come in as files today: the calls take paths.)
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <vector>

namespace fiberbridge::python {

namespace py = pybind11;

/// The vector's values as a 1-D float64 array that owns them (no copy).
inline py::array_t<double> moved_array(std::vector<double>&& v) {
  auto* owner = new std::vector<double>(std::move(v));
  py::capsule free_owner(owner, [](void* p) { delete static_cast<std::vector<double>*>(p); });
  return py::array_t<double>({owner->size()}, {sizeof(double)}, owner->data(), free_owner);
}

/// The vector's values divided by `unit` (1e-3 for mm) as a new 1-D float64 array.
inline py::array_t<double> scaled_array(const std::vector<double>& v, double unit) {
  py::array_t<double> out(v.size());
  auto w = out.mutable_unchecked<1>();
  for (std::size_t i = 0; i < v.size(); ++i)
    w(static_cast<py::ssize_t>(i)) = v[i] / unit;
  return out;
}

/// One field of each row (a struct per row: an R-curve point, a DIC record row) divided by `unit`,
/// as a 1-D float64 array: a table's column.
template <class Row>
py::array_t<double> member_array(const std::vector<Row>& rows, double Row::*field, double unit) {
  std::vector<double> v;
  v.reserve(rows.size());
  for (const auto& r : rows)
    v.push_back(r.*field / unit);
  return moved_array(std::move(v));
}

} // namespace fiberbridge::python
