// stitch.IncrementalSurface: a smooth surface kept up to date as the mesh's vertices move (an
// animation loop), over stitch::IncrementalSurface's position-only path. Its tessellation is a
// stitch.Tessellation whose arrays the updates rewrite in place.
#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "arrays.hpp"
#include "bindings.hpp"
#include "stitch/mesh/limits.hpp"
#include "stitch/tess/incremental_surface.hpp"
#include "stitch/tess/tessellate.hpp"

namespace stitch::python {

namespace {

/// The surface with the mesh as it last saw it (positions included) and its K-gon controls.
struct IncrementalHandle {
  std::shared_ptr<const HalfedgeMesh> mesh;
  KgonOptions options;
  IncrementalSurface surface;
};

std::unique_ptr<IncrementalHandle> make_incremental(const MeshHandle& mesh,
                                                    const std::string& method, int resolution,
                                                    const KgonKeywords& kgons) {
  const Method m = parse_method(method);
  // Before the work, for the mesh the surface will be built on (refined for semi-sharp tags).
  check_tessellation_size(*mesh.mesh, resolution,
                          semi_sharp_refinement(*mesh.mesh, m, semi_sharp(kgons)).patches);
  auto h = std::make_unique<IncrementalHandle>();
  h->mesh = mesh.mesh;
  h->options = kgon_options(kgons);
  limits::check_extent(*h->mesh);  // as stitch.Surface: no normals to build a surface from
  h->surface.rebuild(*h->mesh, h->options, m, resolution, semi_sharp(kgons));
  return h;
}

/// The GIL stays held: the tessellation's arrays are views of the buffers this rewrites.
int update_positions(IncrementalHandle& h, py::handle vertices) {
  const std::vector<Vec3> positions = to_positions(vertices);
  if (positions.size() != h.mesh->positions().size())
    throw py::value_error(fmt::format("update_positions: {} vertices given, the mesh has {}",
                                      positions.size(), h.mesh->positions().size()));
  auto moved = std::make_shared<HalfedgeMesh>(*h.mesh);
  for (size_t v = 0; v < positions.size(); ++v) {
    if (!limits::coordinate_problem(positions[v]).empty())
      limits::check_coordinates(positions[v], fmt::format("update_positions: vertex {}", v + 1));
    moved->position(Vertex(static_cast<int>(v))) = positions[v];
  }
  limits::check_extent(*moved);
  const SurfaceUpdateStats stats = h.surface.update_positions(*moved, h.options);
  h.mesh = std::move(moved);
  return stats.recomputed_patches;
}

}  // namespace

void bind_incremental_surface(py::module_& m) {
  const std::string init_doc = fmt::format(
      "method ({}) and K-gon controls as stitch.Surface; every patch sampled on a "
      "(resolution + 1)^2 grid. {}",
      choice_names(method_table()), kgon_keywords_help());
  py::class_<IncrementalHandle>(
      m, "IncrementalSurface",
      "A smooth surface kept up to date as the mesh's vertices move, its connectivity fixed (a "
      "deformation, an animation): update_positions recomputes the K-gons, control nets and "
      "the samples of the patches whose nets changed, and keeps the layout; semi-sharp tags are "
      "honoured as stitch.Surface honours them (the points refined again on each update). "
      "Tubes keep their "
      "fitted K-gons: the search stitch.Surface runs where they fold (unfold_tubes) is not run "
      "here, so a surface that folds shows it.")
      .def(py::init([](const MeshHandle& mesh, const std::string& method, int resolution,
                       double kgon_scale, double kgon_rotate, bool regularize,
                       const std::string& construction, const std::string& boundary,
                       std::optional<double> sharp_from) {
             return make_incremental(
                 mesh, method, resolution,
                 {kgon_scale, kgon_rotate, regularize, construction, boundary, sharp_from});
           }),
           py::arg("mesh"), py::arg("method") = std::string(method_table().front().name),
           py::arg("resolution") = kDefaultResolution, py::kw_only(), py::arg("kgon_scale") = 1.0,
           py::arg("kgon_rotate") = 0.0, py::arg("regularize") = false,
           py::arg("kgon_construction") = std::string(kgon_construction_table().front().name),
           py::arg("boundary") = std::string(boundary_table().front().name),
           py::arg("sharp_from") = py::none(), init_doc.c_str())
      .def("update_positions", &update_positions, py::arg("vertices"),
           "New positions for every vertex, an (n, 3) array in the order of mesh.vertices. "
           "Returns how many patches were evaluated again (those whose control nets changed). "
           "Raises StitchError for a coordinate that is not finite or too large.")
      .def_property_readonly(
          "tessellation",
          [](const IncrementalHandle& h) -> const TessellatedMesh& {
            return h.surface.tessellation();
          },
          py::return_value_policy::reference_internal,
          "The surface's Tessellation, unwelded: patch (half-edge) h's samples are rows "
          "[h * (resolution + 1)^2, (h + 1) * (resolution + 1)^2), laid out as "
          "Surface.tessellate(welded=False) lays out each patch; a hole's half-edges have "
          "blocks with patch -1 and degenerate quads. update_positions rewrites its arrays in "
          "place (quads, uvs and patches do not change).")
      .def_property_readonly(
          "recomputed",
          [](const IncrementalHandle& h) {
            const std::vector<Corner>& c = h.surface.recomputed();
            static_assert(sizeof(Corner) == sizeof(int));
            return py::array_t<int>(static_cast<py::ssize_t>(c.size()),
                                    reinterpret_cast<const int*>(c.data()));  // a copy
          },
          "(k,) int32: the patches the last update evaluated again")
      .def_property_readonly(
          "mesh", [](const IncrementalHandle& h) { return MeshHandle{h.mesh}; },
          "the mesh as the last update saw it")
      .def_property_readonly(
          "method", [](const IncrementalHandle& h) { return to_string(h.surface.method()); })
      .def_property_readonly("resolution",
                             [](const IncrementalHandle& h) { return h.surface.resolution(); })
      .def_property_readonly(
          "refinement",
          [](const IncrementalHandle& h) { return refinement_dict(h.surface.refinement()); },
          "What honouring the semi-sharp tags took, as Surface.refinement: with levels > 0 the "
          "patches (tessellation blocks, recomputed) are the corners of the refined mesh, "
          "Surface.refined_mesh's")
      .def_property_readonly("num_patches",
                             [](const IncrementalHandle& h) { return h.surface.num_patches(); })
      .def("__repr__", [](const IncrementalHandle& h) {
        return fmt::format("<stitch.IncrementalSurface {}, {} patches, resolution {}>",
                           to_string(h.surface.method()), h.surface.num_patches(),
                           h.surface.resolution());
      });
}

}  // namespace stitch::python
