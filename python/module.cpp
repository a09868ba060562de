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
  py::register_exception<stitch::MeshError>(m, "StitchError", PyExc_ValueError);
  stitch::python::bind_mesh(m);
  stitch::python::bind_surface(m);
}
