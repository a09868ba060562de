// stitch.Mesh, stitch.read and stitch.primitive: building, inspecting, editing and writing meshes.
#include <fmt/format.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <string_view>
#include <tuple>

#include "arrays.hpp"
#include "bindings.hpp"
#include "stitch/mesh/build.hpp"
#include "stitch/mesh/formats.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/mesh/validate.hpp"
#include "stitch/topology/operation.hpp"
#include "stitch/topology/primitives.hpp"

namespace stitch::python {

namespace {

BuildOptions build_options(bool fill_holes, bool repair) {
  BuildOptions o;
  o.fill_holes = fill_holes;
  o.repair = repair;
  // The topology operators make 2-sided faces and edited meshes must read back, as in the CLI.
  o.allow_two_gons = true;
  return o;
}

void warn(const std::vector<std::string>& messages) {
  for (const std::string& w : messages)
    if (PyErr_WarnEx(PyExc_UserWarning, w.c_str(), 1) != 0) throw py::error_already_set();
}

/// Crease tags on the edges joining the vertex pairs of `creases`, and corner tags on the
/// vertices whose `corner_sharpness` is not 0: the soup's tags, as a file's `t crease` and
/// `t corner` lines give them, so build_mesh checks them the same way.
void add_tags(py::handle creases, py::handle crease_sharpness, py::handle corner_sharpness,
              PolygonSoup& soup) {
  if (!creases.is_none()) {
    const auto pairs = checked_array<std::int64_t>(creases, "iu", "creases");
    if (pairs.ndim() != 2 || pairs.shape(1) != 2)
      throw py::value_error("creases must have shape (k, 2): the two vertices of each edge");
    const py::ssize_t k = pairs.shape(0);
    std::vector<double> sharpness(static_cast<size_t>(k), infinitely_sharp);
    if (!crease_sharpness.is_none()) {
      const auto s = checked_array<double>(crease_sharpness, "fiu", "crease_sharpness");
      if (s.ndim() != 1 || s.shape(0) != k)
        throw py::value_error(
            fmt::format("crease_sharpness must have shape ({},), one value per crease", k));
      std::copy(s.data(), s.data() + k, sharpness.begin());
    }
    const auto p = pairs.unchecked<2>();
    for (py::ssize_t i = 0; i < k; ++i) {
      // Range checks of the vertices themselves are build_mesh's, as for a file's tags.
      for (int end = 0; end < 2; ++end)
        if (p(i, end) < std::numeric_limits<int>::min() ||
            p(i, end) > std::numeric_limits<int>::max())
          throw py::value_error(fmt::format("creases[{}][{}] is out of range", i, end));
      soup.creases.push_back({static_cast<int>(p(i, 0)), static_cast<int>(p(i, 1)),
                              sharpness[static_cast<size_t>(i)], 0});
    }
  } else if (!crease_sharpness.is_none()) {
    throw py::value_error("crease_sharpness needs creases: the edges it applies to");
  }
  if (!corner_sharpness.is_none()) {
    const auto s = checked_array<double>(corner_sharpness, "fiu", "corner_sharpness");
    if (s.ndim() != 1 || static_cast<size_t>(s.shape(0)) != soup.positions.size())
      throw py::value_error(fmt::format(
          "corner_sharpness must have shape ({},), one value per vertex", soup.positions.size()));
    for (py::ssize_t v = 0; v < s.shape(0); ++v)
      if (s.data()[v] != 0) soup.corners.push_back({static_cast<int>(v), s.data()[v], 0});
  }
}

MeshHandle build(py::handle vertices, py::handle faces, bool fill_holes, bool repair,
                 py::handle uvs, py::handle creases, py::handle crease_sharpness,
                 py::handle corner_sharpness) {
  PolygonSoup soup;
  soup.positions = to_positions(vertices);
  soup.faces = to_faces(faces);
  add_tags(creases, crease_sharpness, corner_sharpness, soup);
  BuildReport report;
  std::shared_ptr<const HalfedgeMesh> mesh;
  {
    py::gil_scoped_release release;
    mesh = std::make_shared<const HalfedgeMesh>(
        build_mesh(soup, build_options(fill_holes, repair), &report));
  }
  std::shared_ptr<const CornerUvs> texture;
  if (!uvs.is_none()) {
    // As read(): a UV surface needs every patch's corners to have UVs, which filled holes lack.
    if (fill_holes && report.filled_holes > 0)
      report.warnings.emplace_back(
          "its texture coordinates are not kept: the faces fill_holes added have none");
    else
      texture = corner_uvs(*mesh, uvs);
  }
  warn(report.warnings);
  return {std::move(mesh), std::move(texture)};
}

MeshHandle read(const std::string& path, bool fill_holes, bool repair) {
  BuildReport report;
  std::vector<std::string> warnings;
  std::shared_ptr<const HalfedgeMesh> mesh;
  {
    py::gil_scoped_release release;
    mesh = std::make_shared<const HalfedgeMesh>(
        read_mesh(path, build_options(fill_holes, repair), &report, &warnings));
  }
  warnings.insert(warnings.end(), report.warnings.begin(), report.warnings.end());
  std::shared_ptr<const CornerUvs> uvs;
  if (!report.corner_uvs.empty()) {
    // A UV surface needs every patch's corners to have UVs, which filled holes lack.
    if (fill_holes && report.filled_holes > 0)
      warnings.emplace_back(
          "its texture coordinates are not kept: the faces fill_holes added have none");
    else
      uvs = std::make_shared<const CornerUvs>(std::move(report.corner_uvs));
  }
  warn(warnings);
  return {std::move(mesh), std::move(uvs)};
}

std::string_view trimmed(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

/// One `stitch edit` run: numbers refer to the mesh as it stands during the call (see
/// docs/editing.md), and the mesh is replaced only when every operation succeeded.
std::vector<std::string> edit(MeshHandle& self, const std::vector<std::string>& ops) {
  std::vector<std::string> summaries;
  std::shared_ptr<HalfedgeMesh> edited;
  const std::shared_ptr<const HalfedgeMesh> before = self.mesh;  // see `stats`
  {
    py::gil_scoped_release release;
    edited = std::make_shared<HalfedgeMesh>(*before);
    int number = 0;
    for (const std::string& text : ops) {
      std::string_view rest = text;
      while (!rest.empty()) {  // a string may hold several lines, as an ops file does
        const std::string_view line = trimmed(rest.substr(0, rest.find('\n')));
        rest = rest.find('\n') == std::string_view::npos ? "" : rest.substr(rest.find('\n') + 1);
        ++number;
        OperationReport r;
        try {
          r = apply_operation(*edited, line);
        } catch (const Error& e) {
          throw_with_message(e, fmt::format("operation {} ('{}'): {} (the mesh is unchanged)",
                                            number, line, e.what()));
        }
        if (!r.what.empty()) summaries.push_back(r.summary(line.substr(0, line.find(" #"))));
      }
    }
    validate(*edited);
    // Compacted as the file `stitch edit` writes, so the numbers of the next edit are the ones
    // `faces` and `vertices` show (plus one).
    edited->garbage_collection();
  }
  self.mesh = std::move(edited);
  if (self.uvs) {
    self.uvs.reset();  // the operators do not carry texture coordinates (as `stitch edit`)
    warn({"the mesh's texture coordinates are not kept by edits"});
  }
  return summaries;
}

int euler(const HalfedgeMesh& mesh) {
  return topology_stats(mesh).euler;
}

// Takes the snapshot by value, before the GIL is released: another thread may edit the Mesh
// meanwhile, which replaces its snapshot but leaves this one alive.
TopologyStats stats(std::shared_ptr<const HalfedgeMesh> mesh) {
  py::gil_scoped_release release;
  return topology_stats(*mesh);
}

py::dict topology(std::shared_ptr<const HalfedgeMesh> mesh) {
  const TopologyStats s = stats(mesh);
  py::dict d;
  d["vertices"] = s.vertices;
  d["edges"] = s.edges;
  d["faces"] = s.faces;
  d["boundary_loops"] = s.boundary_loops;
  d["crease_edges"] = s.crease_edges;
  d["corner_vertices"] = s.corner_vertices;
  d["components"] = s.components;
  d["euler"] = s.euler;
  d["genus"] = s.genus;
  d["valence_histogram"] = s.valence_histogram;
  d["degree_histogram"] = s.degree_histogram;
  d["extraordinary_vertices"] = s.extraordinary_vertices;
  d["extraordinary_faces"] = s.extraordinary_faces;
  return d;
}

}  // namespace

std::shared_ptr<const CornerUvs> corner_uvs(const HalfedgeMesh& mesh, py::handle uvs) {
  const auto a = checked_array<double>(uvs, "fiu", "uvs");
  py::ssize_t corners = 0;
  for (Face f : mesh.surface_faces()) corners += static_cast<py::ssize_t>(mesh.degree(f));
  if (a.ndim() != 2 || a.shape(1) != 2 || a.shape(0) != corners)
    throw py::value_error(
        fmt::format("uvs must have shape ({}, 2), one row per corner of the faces in order, not {}",
                    corners, py::str(py::handle(a).attr("shape")).cast<std::string>()));
  const auto r = a.unchecked<2>();
  auto out = std::make_shared<CornerUvs>();
  out->index.assign(mesh.halfedge_capacity(), -1);
  std::map<std::tuple<int, double, double>, int> joined;
  py::ssize_t row = 0;
  // The faces and their corners in the order of `faces`, as build_mesh gives a file's UVs.
  for (Face f : mesh.surface_faces())
    for (Halfedge h : mesh.face_loop(f)) {
      const Eigen::Vector2d uv(r(row, 0), r(row, 1));
      if (!uv.allFinite())
        throw InputError(fmt::format("uvs[{}] = ({}, {}) is not finite", row, uv.x(), uv.y()));
      const auto [at, added] = joined.try_emplace({mesh.origin(h).idx, uv.x(), uv.y()},
                                                  static_cast<int>(out->uv.size()));
      if (added) out->uv.push_back(uv);
      out->index[h.idx] = at->second;
      ++row;
    }
  return out;
}

Corner corner_arg(const HalfedgeMesh& mesh, py::handle corner) {
  if (py::isinstance<py::str>(corner)) return parse_corner(mesh, corner.cast<std::string>());
  int h = -1;
  if (to_int(corner, h) != IntStatus::ok || h < 0 || h >= mesh.halfedge_capacity() ||
      mesh.is_deleted(Halfedge(h)) || mesh.is_hole(Halfedge(h)))
    throw py::value_error(fmt::format("{} is not a patch (a corner: 0 to {}, or a name \"V@F\")",
                                      py::repr(corner).cast<std::string>(),
                                      mesh.halfedge_capacity() - 1));
  return Corner(h);
}

Corner corner_of(const HalfedgeMesh& mesh, int face, int vertex, int occurrence) {
  // Through the name, so the checks and messages are those of "V@F#k" (numbered from 1).
  return parse_corner(mesh, corner_name(vertex, face, occurrence));
}

void bind_mesh(py::module_& m) {
  const std::string read_doc = fmt::format(
      "Reads {} with every check of the command line; warnings (dropped unused vertices, "
      "filled holes, each repair) become Python UserWarnings. repair (default True) fixes "
      "what the mesh's building would refuse where it can, as `stitch smooth` does; "
      "repair=False refuses it, as `--strict` does. The texture coordinates of the file, if any, "
      "stay with the mesh (has_uvs) until it is edited, for Surface.export(uv=...).",
      extension_list(kMeshReadExtensions));
  const std::string write_doc = fmt::format("Writes the mesh by extension ({}), atomically.",
                                            extension_list(kMeshWriteExtensions));
  py::class_<MeshHandle>(m, "Mesh",
                         "An oriented, manifold polygon mesh, closed or with boundaries (faces "
                         "of any degree). "
                         "Immutable except through edit().")
      .def(py::init(&build), py::arg("vertices"), py::arg("faces"), py::kw_only(),
           py::arg("fill_holes") = false, py::arg("repair") = true, py::arg("uvs") = py::none(),
           py::arg("creases") = py::none(), py::arg("crease_sharpness") = py::none(),
           py::arg("corner_sharpness") = py::none(),
           "Builds a mesh from an (n, 3) array of positions and faces given as 0-based vertex "
           "index lists of any length or an (m, k) integer array. repair (default True) fixes "
           "what it can, each change named in a UserWarning: faces flipped to one orientation, "
           "non-manifold edges and vertices split (the split edges infinitely sharp), repeated "
           "vertices, degenerate and duplicate faces dropped; repair=False refuses them. Raises "
           "StitchError (a ValueError) for what cannot be repaired (a non-orientable piece, "
           "indices out of range); messages number vertices and faces from 1, as files do. "
           "fill_holes closes each boundary loop with one face. "
           "uvs: texture coordinates, an (c, 2) array with one row per corner of the faces in "
           "order (corners at one vertex with equal coordinates are joined, others make a "
           "seam), kept as has_uvs says. creases: a (k, 2) integer array of the vertex pairs of "
           "crease edges, with crease_sharpness (k,) (default 10, infinitely sharp); "
           "corner_sharpness: (n,) sharpness of every vertex (0: none). The tags of a file's "
           "`t crease` and `t corner` lines, checked the same way.")
      .def_property_readonly("num_vertices",
                             [](const MeshHandle& h) { return h.mesh->num_vertices(); })
      .def_property_readonly("num_edges", [](const MeshHandle& h) { return h.mesh->num_edges(); })
      .def_property_readonly("num_faces",
                             [](const MeshHandle& h) { return topology_stats(*h.mesh).faces; })
      .def_property_readonly(
          "num_patches",
          [](const MeshHandle& h) { return static_cast<int>(h.mesh->patch_corners().size()); },
          "one patch per corner (half-edge)")
      .def(
          "corner_name",
          [](const MeshHandle& h, py::handle corner) {
            return corner_name(*h.mesh, corner_arg(*h.mesh, corner));
          },
          py::arg("corner"),
          "The name \"V@F\" of a corner (a patch number of Surface.patches): vertex V on face "
          "F, numbered from 1 as in edit(), or \"V@F#k\" when V appears on F more than once. "
          "The name `stitch eval`, Bezier JSON and the faces of STEP and IGES files use.")
      .def(
          "corner",
          [](const MeshHandle& h, const std::string& name) {
            return corner_arg(*h.mesh, py::str(name)).idx;
          },
          py::arg("name"), "The corner (patch number) named \"V@F\" or \"V@F#k\".")
      .def(
          "corner_of",
          [](const MeshHandle& h, int face, int vertex, int occurrence) {
            return corner_of(*h.mesh, face, vertex, occurrence).idx;
          },
          py::kw_only(), py::arg("face"), py::arg("vertex"), py::arg("occurrence") = 0,
          "The corner (patch number) of vertex `vertex` on face `face`, both 0-based as in "
          "`faces` and `vertices` (so corner_of(face=f, vertex=v) is corner(f\"{v+1}@{f+1}\")). "
          "occurrence: k >= 1 picks the k-th appearance of a vertex that appears on the face "
          "more than once.")
      .def_property_readonly(
          "has_uvs", [](const MeshHandle& h) { return h.uvs != nullptr; },
          "whether the mesh has the texture coordinates of the file it was read from")
      .def_property_readonly("euler", [](const MeshHandle& h) { return euler(*h.mesh); })
      .def_property_readonly(
          "genus", [](const MeshHandle& h) { return stats(h.mesh).genus; },
          "total genus over all components")
      .def_property_readonly("components",
                             [](const MeshHandle& h) { return stats(h.mesh).components; })
      .def(
          "topology", [](const MeshHandle& h) { return topology(h.mesh); },
          "counts, Euler characteristic, genus, components and the valence and degree "
          "histograms, as `stitch info` reports them")
      .def_property_readonly(
          "vertices",
          [](const MeshHandle& h) {
            // The owner is a Mesh sharing this snapshot, so a later edit() leaves the view valid.
            return view_rows<double, 3>(h.mesh->positions(), py::cast(MeshHandle{h.mesh}));
          },
          "(n, 3) float64 positions, a read-only view")
      .def_property_readonly(
          "faces", [](const MeshHandle& h) { return to_polygon_soup(*h.mesh).faces; },
          "list of 0-based vertex index lists")
      .def(
          "edit",
          [](MeshHandle& h, const py::args& ops) {
            std::vector<std::string> lines;
            for (py::handle op : ops) {
              if (!py::isinstance<py::str>(op))
                throw py::value_error(
                    "edit() takes operation strings, e.g. \"insert-edge 1@1 5@2\"");
              lines.push_back(op.cast<std::string>());
            }
            return edit(h, lines);
          },
          "Applies operations in the syntax of `stitch edit --op` (docs/editing.md), in order, "
          "each argument one operation or several lines of them. Vertices and faces are numbered "
          "from 1 in the order of `vertices` and `faces`; within one call the numbers refer to "
          "the mesh as it stands (removed elements leave gaps), afterwards the mesh is compacted. "
          "All or nothing: when an operation is refused the mesh is unchanged. Returns one "
          "summary line per operation.")
      .def(
          "refusal",
          [](const MeshHandle& h, const std::string& line) -> std::optional<std::string> {
            // Numbers as in edit(): the mesh as it stands. A line that does not parse raises.
            const std::optional<Operation> op = parse_operation(*h.mesh, line);
            if (!op) return std::nullopt;
            const Verdict v = can_apply(*h.mesh, *op);
            if (v) return std::nullopt;
            return v.refusal();
          },
          py::arg("operation"),
          "Why edit(operation) would be refused, or None when it applies, without changing the "
          "mesh (the operator's own check; a front end enables its buttons from it). A line "
          "that is not a valid operation raises stitch.UsageError.")
      .def(
          "write",
          [](const MeshHandle& h, const std::string& path) {
            const std::shared_ptr<const HalfedgeMesh> mesh = h.mesh;  // see `stats`
            py::gil_scoped_release release;
            write_mesh(path, *mesh);
          },
          py::arg("path"), write_doc.c_str())
      .def("__repr__", [](const MeshHandle& h) {
        return fmt::format("<stitch.Mesh V {} E {} F {}, Euler {}>", h.mesh->num_vertices(),
                           h.mesh->num_edges(), topology_stats(*h.mesh).faces, euler(*h.mesh));
      });

  m.def("read", &read, py::arg("path"), py::kw_only(), py::arg("fill_holes") = false,
        py::arg("repair") = true, read_doc.c_str());
  m.def(
      "primitive",
      [](const std::string& name, const py::args& params) {
        std::vector<int> p;
        for (py::handle param : params)
          if (to_int(param, p.emplace_back()) != IntStatus::ok)
            throw py::value_error(
                fmt::format("primitive {}: parameters are integers of int's range", name));
        py::gil_scoped_release release;
        return MeshHandle{std::make_shared<const HalfedgeMesh>(make_primitive(name, p))};
      },
      py::arg("name"),
      "A primitive solid as `stitch primitive` makes it: tetrahedron, cube, octahedron, "
      "dodecahedron, icosahedron, prism N, torus M N (numbering in docs/editing.md).");
}

}  // namespace stitch::python
