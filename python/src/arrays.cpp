// Conversions between numpy arrays and the library's value types (bind.hpp).
#include <pybind11/stl.h>

#include <cstring>
#include <memory>
#include <string>
#include <type_traits>

#include "bind.hpp"

namespace frontpack::python {

static_assert(std::is_standard_layout_v<Disk> && std::is_trivially_copyable_v<Disk>);
static_assert(sizeof(Disk) == 3 * sizeof(double), "an (N, 3) float64 array views std::vector<Disk>");
static_assert(sizeof(Point) == 2 * sizeof(double));

namespace {

using Doubles = py::array_t<double, py::array::c_style | py::array::forcecast>;

// The array as C-contiguous float64 with `columns` columns; an empty 1-D sequence is (0, columns).
Doubles table(const py::handle& object, py::ssize_t columns, const char* what) {
  Doubles a = Doubles::ensure(object);
  if (!a) {
    throw py::type_error(std::string(what) + " must be an array-like of numbers");
  }
  if (a.ndim() == 1 && a.shape(0) == 0) {
    return Doubles(std::vector<py::ssize_t>{0, columns});
  }
  if (a.ndim() != 2 || a.shape(1) != columns) {
    std::string shape = "(";
    for (py::ssize_t i = 0; i < a.ndim(); ++i) {
      shape += (i > 0 ? ", " : "") + std::to_string(a.shape(i));
    }
    throw py::value_error(std::string(what) + " must have shape (N, " + std::to_string(columns) + "), not " + shape +
                          (a.ndim() == 1 ? ",)" : ")"));
  }
  return a;
}

template <class T>
py::array owning_array(std::vector<T>&& values, std::vector<py::ssize_t> shape) {
  auto* owned = new std::vector<T>(std::move(values));
  py::capsule base(owned, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  using Element = std::conditional_t<std::is_same_v<T, Disk>, double, T>;
  return py::array_t<Element>(std::move(shape), reinterpret_cast<const Element*>(owned->data()), base);
}

}  // namespace

std::vector<Disk> disks_from(const py::handle& array) {
  const Doubles a = table(array, 3, "disks");
  std::vector<Disk> disks(static_cast<std::size_t>(a.shape(0)));
  if (!disks.empty()) {
    std::memcpy(static_cast<void*>(disks.data()), a.data(), disks.size() * sizeof(Disk));
  }
  return disks;
}

py::array disks_array(std::vector<Disk>&& disks) {
  const auto n = static_cast<py::ssize_t>(disks.size());
  return owning_array(std::move(disks), {n, 3});
}

py::array grid_array(std::vector<double>&& values, std::size_t rows, std::size_t columns) {
  return owning_array(std::move(values), {static_cast<py::ssize_t>(rows), static_cast<py::ssize_t>(columns)});
}

Ring ring_from(const py::handle& array) {
  const Doubles a = table(array, 2, "a ring");
  Ring ring(static_cast<std::size_t>(a.shape(0)));
  if (!ring.empty()) {
    std::memcpy(static_cast<void*>(ring.data()), a.data(), ring.size() * sizeof(Point));
  }
  return ring;
}

py::array ring_array(const Ring& ring) {
  py::array_t<double> a({static_cast<py::ssize_t>(ring.size()), py::ssize_t{2}});
  if (!ring.empty()) {
    std::memcpy(a.mutable_data(), ring.data(), ring.size() * sizeof(Point));
  }
  return a;
}

py::array index_array(const std::vector<std::size_t>& indices) {
  py::array_t<std::int64_t> a(static_cast<py::ssize_t>(indices.size()));
  auto out = a.mutable_unchecked<1>();
  for (std::size_t i = 0; i < indices.size(); ++i) {
    out(static_cast<py::ssize_t>(i)) = static_cast<std::int64_t>(indices[i]);
  }
  return a;
}

std::vector<std::uint32_t> types_from(const py::handle& array) {
  if (array.is_none()) {
    return {};
  }
  using Ints = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>;
  const Ints a = Ints::ensure(array);
  if (!a || a.ndim() != 1) {
    throw py::value_error("types must be a 1-D array-like of whole numbers >= 1");
  }
  std::vector<std::uint32_t> types(static_cast<std::size_t>(a.shape(0)));
  const std::int64_t* p = a.data();
  for (std::size_t i = 0; i < types.size(); ++i) {
    if (p[i] < 1 || p[i] > std::int64_t{UINT32_MAX}) {
      throw py::value_error("types[" + std::to_string(i) + "] is " + std::to_string(p[i]) +
                            ": types are whole numbers >= 1");
    }
    types[i] = static_cast<std::uint32_t>(p[i]);
  }
  return types;
}

py::array types_array(std::vector<std::uint32_t>&& types) {
  const auto n = static_cast<py::ssize_t>(types.size());
  return owning_array(std::move(types), {n});
}

py::tuple box_tuple(const Box& box) {
  return py::make_tuple(box.xmin, box.ymin, box.xmax, box.ymax);
}

Box box_from(const py::handle& bounds) {
  const auto v = bounds.cast<std::vector<double>>();
  if (v.size() != 4) {
    throw py::value_error("a box is (xmin, ymin, xmax, ymax): 4 numbers, not " + std::to_string(v.size()));
  }
  return Box{v[0], v[1], v[2], v[3]};
}

}  // namespace frontpack::python
