// The module `stitch`: its exception type and the parts of the API.
#include "bindings.hpp"

PYBIND11_MODULE(stitch, m) {
  namespace py = pybind11;
  m.doc() =
      "stitch: smooth surfaces of bicubic Bezier patches from polygon meshes (modified de "
      "Casteljau). See docs/python.md.";
  // A ValueError, so callers catching bad input the Python way also catch the library's refusals
  // (invalid meshes, refused operations, unwritable files), with the library's message.
  m.attr("__version__") = STITCH_VERSION;
  auto& base = py::register_exception<stitch::Error>(m, "StitchError", PyExc_ValueError);
  // The kinds (include/stitch/error.hpp) as subclasses, so callers can tell a malformed file from
  // a refused edit; registered after the base, so pybind11 tries them first.
  py::register_exception<stitch::InputError>(m, "InputError", base.ptr());
  py::register_exception<stitch::TopologyError>(m, "TopologyError", base.ptr());
  py::register_exception<stitch::UsageError>(m, "UsageError", base.ptr());
  py::register_exception<stitch::OutputError>(m, "OutputError", base.ptr());
  stitch::python::bind_mesh(m);
  stitch::python::bind_surface(m);
  stitch::python::bind_incremental_surface(m);
}
