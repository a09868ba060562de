// Between numpy and the library's containers: checked conversion of user input, and zero-copy
// views of library-owned buffers.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <vector>

#include "stitch/mesh/halfedge_mesh.hpp"

namespace stitch::python {

namespace py = pybind11;

/// A read-only numpy array of `shape` (C order) over `data`, which `owner` keeps alive: the
/// array holds a reference to `owner`, so nothing is copied.
template <class T>
py::array view(const T* data, std::vector<py::ssize_t> shape, py::handle owner) {
  py::array a(py::dtype::of<T>(), std::move(shape), {}, data, owner);
  a.attr("setflags")(py::arg("write") = false);
  return a;
}

/// A one-dimensional view of a vector of scalars.
template <class T>
py::array view(const std::vector<T>& values, py::handle owner) {
  return view(values.data(), {static_cast<py::ssize_t>(values.size())}, owner);
}

/// The same for arrays of fixed-size vectors (Vec3, Eigen::Vector2d, std::array<int, 4>): an
/// (n, k) array of their scalars.
template <class Scalar, int K, class Vector>
py::array view_rows(const std::vector<Vector>& rows, py::handle owner) {
  static_assert(sizeof(Vector) == K * sizeof(Scalar), "rows must be K packed scalars");
  return view(reinterpret_cast<const Scalar*>(rows.data()),
              {static_cast<py::ssize_t>(rows.size()), K}, owner);
}

enum class IntStatus { ok, not_integer, out_of_range };
/// `value` as an int the way operator.index sees it: Python and numpy integers pass, floats and
/// strings do not. Leaves no Python error set.
IntStatus to_int(py::handle value, int& out);

/// Vertex positions from an (n, 3) array-like of real numbers. Raises ValueError otherwise.
std::vector<Vec3> to_positions(py::handle vertices);

/// Face loops (0-based vertex indices) from an (m, k) integer array or a sequence of integer
/// sequences of any lengths. Raises ValueError for anything else; range and shape checks of the
/// loops themselves are the mesh builder's.
std::vector<std::vector<int>> to_faces(py::handle faces);

/// `value` as a numpy array, after checking that its kind is one of `kinds` ("iu" for integers,
/// "fiu" for reals); `what` names the argument in the ValueError otherwise.
py::array checked_kind(py::handle value, const char* kinds, const char* what);

/// The same, converted to a C-contiguous array of T (a copy only where the input is not one).
template <class T>
py::array_t<T, py::array::c_style | py::array::forcecast> checked_array(py::handle value,
                                                                        const char* kinds,
                                                                        const char* what) {
  return py::array_t<T, py::array::c_style | py::array::forcecast>::ensure(
      checked_kind(value, kinds, what));
}

}  // namespace stitch::python
