// The Python module's parts (one file each) and the array conversions they share.
//
// Disks cross the boundary as numpy (N, 3) float64 arrays (x, y, r per row), never as one Python
// object per disk. Going out, an array takes over the std::vector<Disk> the library returned and
// views its memory (no copy: the vector lives in a capsule that is the array's base). Coming in,
// any array-like of shape (N, 3) is converted to float64 (a copy only when it is not already
// C-contiguous float64) and copied once into a std::vector<Disk>, bit for bit.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <vector>

#include "frontpack/frontpack.hpp"

namespace frontpack::python {

namespace py = pybind11;

void bind_errors(py::module_& m);
void bind_domain(py::module_& m);
void bind_radii(py::module_& m);
void bind_fill(py::module_& m);
void bind_certify(py::module_& m);
void bind_stats(py::module_& m);
void bind_io(py::module_& m);

/// Disks from an (N, 3) array-like (also an empty sequence). Throws ValueError for another shape.
[[nodiscard]] std::vector<Disk> disks_from(const py::handle& array);
/// An (N, 3) float64 array viewing `disks` (moved into a capsule, the array's base): no copy.
[[nodiscard]] py::array disks_array(std::vector<Disk>&& disks);
/// A (rows, columns) float64 array viewing `values`, row by row (moved into a capsule, the array's
/// base): no copy.
[[nodiscard]] py::array grid_array(std::vector<double>&& values, std::size_t rows, std::size_t columns);
/// A ring from an (N, 2) array-like. Throws ValueError for another shape.
[[nodiscard]] Ring ring_from(const py::handle& array);
/// An (N, 2) float64 array, a copy of the ring's vertices.
[[nodiscard]] py::array ring_array(const Ring& ring);
/// A 1-D int64 array of indices.
[[nodiscard]] py::array index_array(const std::vector<std::size_t>& indices);
/// Per-disk types from a 1-D array-like of integers >= 1 (None: empty). ValueError if negative.
[[nodiscard]] std::vector<std::uint32_t> types_from(const py::handle& array);
/// A 1-D uint32 array viewing `types` (moved into a capsule): no copy.
[[nodiscard]] py::array types_array(std::vector<std::uint32_t>&& types);

/// A box as (xmin, ymin, xmax, ymax), the order of shapely's `bounds`.
[[nodiscard]] py::tuple box_tuple(const Box& box);
[[nodiscard]] Box box_from(const py::handle& bounds);

}  // namespace frontpack::python
