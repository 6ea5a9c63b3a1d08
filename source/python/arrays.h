#pragma once
// Vectors of the typed API as numpy arrays. A vector whose values go out in the unit they have
// inside (J/m^2, N, s) is not copied: moved into the array's owner when the call made it, or
// viewed read-only in the outcome that holds it (the array keeps the outcome alive; an outcome is
// handed on to later calls, so its values may not be changed through the view). One that changes
// unit on the way out (m -> mm, Pa -> kPa: the names carry the unit, as the CSV columns do) is
// scaled into a new array. Columns in memory come in as ColumnIn (a contiguous float64 view of what
// the caller passed, converted only when it is not one) and are copied once into the typed API's
// vectors.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <memory>
#include <vector>

namespace fiberbridge::python {

namespace py = pybind11;

/// The vector's values as a 1-D float64 array that owns them (no copy).
inline py::array_t<double> moved_array(std::vector<double>&& v) {
  auto* owner = new std::vector<double>(std::move(v));
  py::capsule free_owner(owner, [](void* p) { delete static_cast<std::vector<double>*>(p); });
  return py::array_t<double>({owner->size()}, {sizeof(double)}, owner->data(), free_owner);
}

/// A Python object that keeps `p`'s object alive as long as it lives: the base of views into it.
template <class T>
py::object keeper_of(std::shared_ptr<T> p) {
  return py::capsule(new std::shared_ptr<T>(std::move(p)),
                     [](void* q) { delete static_cast<std::shared_ptr<T>*>(q); });
}

/// The vector's values as a read-only 1-D float64 view (no copy); `owner` keeps the object that
/// holds the vector alive (keeper_of, or the Python object of a bound outcome).
inline py::array_t<double> viewed_array(const std::vector<double>& v, const py::object& owner) {
  if (v.empty())
    return py::array_t<double>(0);
  py::array_t<double> a({v.size()}, {sizeof(double)}, v.data(), owner);
  py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return a;
}

/// The vector's values divided by `unit` (1e-3 for mm) as a new 1-D float64 array.
inline py::array_t<double> scaled_array(const std::vector<double>& v, double unit) {
  py::array_t<double> out(v.size());
  auto w = out.mutable_unchecked<1>();
  for (std::size_t i = 0; i < v.size(); ++i)
    w(static_cast<py::ssize_t>(i)) = v[i] / unit;
  return out;
}

/// A 1-D float64 column handed in: numpy passes a C-contiguous float64 array as it is (no copy)
/// and converts anything else (a list, int or float32 arrays, a strided slice) once.
using ColumnIn = py::array_t<double, py::array::c_style | py::array::forcecast>;

/// The column's values as the typed API's vector: one copy of the buffer.
inline std::vector<double> vector_of(const ColumnIn& column) {
  const double* p = column.data();
  return std::vector<double>(p, p + column.size());
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
