// What the binding files of the Python module share: the mesh as Python holds it, and the
// functions that add each part of the API to the module.
#pragma once

#include <pybind11/pybind11.h>

#include <memory>
#include <string>

#include "stitch/kgon/kgon.hpp"
#include "stitch/mesh/halfedge_mesh.hpp"

namespace stitch::python {

namespace py = pybind11;

/// A Python `stitch.Mesh`: an immutable snapshot that edits replace as a whole, so a Surface
/// (or a numpy view of the vertices) keeps the mesh it was made from, whatever happens later.
struct MeshHandle {
  std::shared_ptr<const HalfedgeMesh> mesh;
};

/// The K-gon controls of stitch.Surface's and stitch.IncrementalSurface's keyword arguments
/// (the command line's --kgon-scale, --kgon-rotate, --regularize, --kgon-construction),
/// range-checked.
KgonOptions kgon_options(double scale, double rotate_deg, bool regularize,
                         const std::string& construction);

/// Raises ValueError unless 1 <= resolution <= limits::max_resolution and a tessellation of
/// `mesh` at that resolution, (resolution + 1)^2 samples per half-edge, can number its samples
/// with int.
void check_tessellation_size(const HalfedgeMesh& mesh, int resolution);

/// stitch.Mesh, stitch.read, stitch.primitive.
void bind_mesh(py::module_& m);
/// stitch.Surface and the stitch.Tessellation it returns.
void bind_surface(py::module_& m);
/// stitch.IncrementalSurface.
void bind_incremental_surface(py::module_& m);

}  // namespace stitch::python
