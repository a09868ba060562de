#include "arrays.hpp"

#include <fmt/format.h>

#include <cstdint>
#include <limits>
#include <string>
#include <string_view>

namespace stitch::python {

namespace {

std::string type_name(py::handle value) {
  return py::str(py::type::of(value).attr("__name__"));
}

int to_index(py::handle value, size_t face, size_t position) {
  int i = 0;
  switch (to_int(value, i)) {
    case IntStatus::ok:
      return i;
    case IntStatus::not_integer:
      throw py::value_error(
          fmt::format("faces[{}][{}] is not an integer ({})", face, position, type_name(value)));
    case IntStatus::out_of_range:
      break;
  }
  throw py::value_error(fmt::format("faces[{}][{}] is out of range", face, position));
}

std::string shape_text(const py::array& a) {
  return py::str(py::handle(a).attr("shape"));
}

bool is_text(py::handle value) {
  return py::isinstance<py::str>(value) || py::isinstance<py::bytes>(value);
}

}  // namespace

IntStatus to_int(py::handle value, int& out) {
  PyObject* index = PyNumber_Index(value.ptr());
  if (index == nullptr) {
    PyErr_Clear();
    return IntStatus::not_integer;
  }
  int overflow = 0;
  const long long i = PyLong_AsLongLongAndOverflow(index, &overflow);
  Py_DECREF(index);
  if (overflow != 0 || i < std::numeric_limits<int>::min() || i > std::numeric_limits<int>::max())
    return IntStatus::out_of_range;
  out = static_cast<int>(i);
  return IntStatus::ok;
}

py::array checked_kind(py::handle value, const char* kinds, const char* what) {
  const py::array a = py::array::ensure(value);  // null (error cleared) when not array-like
  if (!a) throw py::value_error(fmt::format("{} must be an array of numbers", what));
  const char kind = a.dtype().kind();
  if (std::string_view(kinds).find(kind) == std::string_view::npos)
    throw py::value_error(fmt::format("{} must be {}, not an array of {}", what,
                                      std::string_view(kinds) == "iu" ? "integers" : "real numbers",
                                      std::string(py::str(a.dtype()))));
  return a;
}

std::vector<Vec3> to_positions(py::handle vertices) {
  const auto a = checked_array<double>(vertices, "fiu", "vertices");
  if (a.ndim() != 2 || a.shape(1) != 3)
    throw py::value_error(fmt::format("vertices must have shape (n, 3), not {}", shape_text(a)));
  std::vector<Vec3> positions(a.shape(0));
  const auto r = a.unchecked<2>();
  for (py::ssize_t i = 0; i < a.shape(0); ++i) positions[i] = Vec3(r(i, 0), r(i, 1), r(i, 2));
  return positions;
}

std::vector<std::vector<int>> to_faces(py::handle faces) {
  std::vector<std::vector<int>> loops;
  if (py::isinstance<py::array>(faces)) {
    const auto a = checked_array<std::int64_t>(faces, "iu", "faces");
    if (a.ndim() != 2)
      throw py::value_error(
          fmt::format("a faces array must have shape (m, k), not {}", shape_text(a)));
    const auto r = a.unchecked<2>();
    loops.assign(a.shape(0), std::vector<int>(a.shape(1)));
    for (py::ssize_t f = 0; f < a.shape(0); ++f)
      for (py::ssize_t k = 0; k < a.shape(1); ++k) {
        if (r(f, k) < std::numeric_limits<int>::min() || r(f, k) > std::numeric_limits<int>::max())
          throw py::value_error(fmt::format("faces[{}][{}] is out of range", f, k));
        loops[f][k] = static_cast<int>(r(f, k));
      }
    return loops;
  }
  if (!py::isinstance<py::sequence>(faces) || is_text(faces))
    throw py::value_error(fmt::format(
        "faces must be a sequence of vertex index sequences or an (m, k) integer array, not {}",
        type_name(faces)));
  const auto outer = py::reinterpret_borrow<py::sequence>(faces);
  loops.reserve(outer.size());
  for (size_t f = 0; f < outer.size(); ++f) {
    const py::object face = outer[f];
    if (!py::isinstance<py::sequence>(face) || is_text(face))
      throw py::value_error(fmt::format("faces[{}] must be a sequence of vertex indices, not {}", f,
                                        type_name(face)));
    const auto loop = py::reinterpret_borrow<py::sequence>(face);
    std::vector<int>& out = loops.emplace_back(loop.size());
    for (size_t k = 0; k < loop.size(); ++k) out[k] = to_index(loop[k], f, k);
  }
  return loops;
}

}  // namespace stitch::python
