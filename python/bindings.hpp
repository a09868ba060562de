// What the binding files of the Python module share: the mesh as Python holds it, and the
// functions that add each part of the API to the module.
#pragma once

#include <pybind11/pybind11.h>

#include <memory>
#include <optional>
#include <string>

#include "stitch/eval/semi_sharp.hpp"
#include "stitch/kgon/kgon.hpp"
#include "stitch/mesh/build.hpp"
#include "stitch/mesh/halfedge_mesh.hpp"

namespace stitch::python {

namespace py = pybind11;

/// A Python `stitch.Mesh`: an immutable snapshot that edits replace as a whole, so a Surface
/// (or a numpy view of the vertices) keeps the mesh it was made from, whatever happens later.
struct MeshHandle {
  std::shared_ptr<const HalfedgeMesh> mesh;
  /// The texture coordinates read with it (null: none). They live beside the mesh, as in the
  /// library: edits do not carry them, so an edited mesh has none.
  std::shared_ptr<const CornerUvs> uvs = nullptr;
};

/// The K-gon keyword arguments of stitch.Surface and stitch.IncrementalSurface (the command
/// line's --kgon-scale, --kgon-rotate, --regularize, --kgon-construction, --boundary,
/// --sharp-from), range-checked, the names parsed with the library's tables.
struct KgonKeywords {
  double scale = 1;
  double rotate_deg = 0;
  bool regularize = false;
  std::string construction;
  std::string boundary;
  /// None: semi-sharp tags honoured by refinement; a value rounds them there.
  std::optional<double> sharp_from;
};
KgonOptions kgon_options(const KgonKeywords& k);
/// How the keywords take semi-sharp tags: rounded when sharp_from is given.
SemiSharp semi_sharp(const KgonKeywords& k);
/// Surface.refinement and IncrementalSurface.refinement: a dict of SemiSharpRefinement.
pybind11::dict refinement_dict(const SemiSharpRefinement& r);
/// The keywords' help, their names listed from the tables.
std::string kgon_keywords_help();

/// The corner (patch) that a Python argument names: its index (a half-edge of `mesh`, the
/// numbers of Surface.patches) or its name "V@F" (parse_corner). Raises ValueError otherwise.
Corner corner_arg(const HalfedgeMesh& mesh, py::handle corner);
/// The corner of 0-based `vertex` on 0-based `face`, as "V@F#k" would name it (k = occurrence,
/// 0 when the vertex is on the face once).
Corner corner_of(const HalfedgeMesh& mesh, int face, int vertex, int occurrence);

/// Texture coordinates given per corner, an (c, 2) array with one row per corner of the faces in
/// the order of Mesh.faces, as the mesh's CornerUvs: corners at one vertex with equal coordinates
/// share one, so the UV layout is connected there, and a vertex whose corners differ lies on a
/// seam (the rule Blender and OpenSubdiv's face-varying data follow). Raises ValueError for a
/// wrong shape, StitchError for a value that is not finite.
std::shared_ptr<const CornerUvs> corner_uvs(const HalfedgeMesh& mesh, py::handle uvs);

/// Raises ValueError unless 1 <= resolution <= limits::max_resolution and a tessellation of
/// `mesh` at that resolution, (resolution + 1)^2 samples per half-edge, can number its samples
/// with int.
/// `patches`: the surface's patches when it is built on a refinement of `mesh` (0: mesh's own).
void check_tessellation_size(const HalfedgeMesh& mesh, int resolution, long long patches = 0);

/// stitch.Mesh, stitch.read, stitch.primitive.
void bind_mesh(py::module_& m);
/// stitch.Surface and the stitch.Tessellation it returns.
void bind_surface(py::module_& m);
/// stitch.IncrementalSurface.
void bind_incremental_surface(py::module_& m);

}  // namespace stitch::python
