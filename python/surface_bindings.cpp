// stitch.Surface: the smooth surface of a mesh for one method, built through the library's recipe
// (build_surface), with tessellation, exact evaluation, continuity analysis and export to every
// format of the output table; stitch.Tessellation owns tessellate()'s buffers.
#include <fmt/format.h>
#include <pybind11/stl.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <climits>
#include <cmath>
#include <cstdint>
#include <optional>

#include "arrays.hpp"
#include "bindings.hpp"
#include "stitch/analysis/build_surface.hpp"
#include "stitch/analysis/continuity.hpp"
#include "stitch/eval/uv_surface.hpp"
#include "stitch/mesh/limits.hpp"
#include "stitch/output/output.hpp"
#include "stitch/tess/tessellate.hpp"
#include "stitch/topology/operation.hpp"

namespace stitch::python {

namespace {

/// The surface with the mesh snapshot it was built from (tessellation, analysis and export need
/// both) and what build_surface chose.
struct SurfaceHandle {
  std::shared_ptr<const HalfedgeMesh> mesh;
  std::shared_ptr<const CornerUvs> uvs;  ///< the mesh's texture coordinates (null: none)
  /// The surface, the K-gon options it was built with and what unfold_tubes found (nothing when
  /// it was off or no tube folded).
  std::shared_ptr<const BuiltSurface> built;
  [[nodiscard]] const Surface& surface() const { return built->surface; }
  /// The mesh whose corners are the patches: `mesh`, or its refinement for semi-sharp tags.
  [[nodiscard]] const HalfedgeMesh& patch_mesh() const { return built->mesh(*mesh); }
  /// The texture coordinates that go with patch_mesh() (null: none): refined with it.
  [[nodiscard]] std::shared_ptr<const CornerUvs> patch_uvs() const {
    if (!uvs || !built->refined) return uvs;
    return {built, &built->refined->uvs};
  }
};

SurfaceHandle make_surface(const MeshHandle& mesh, const std::string& method,
                           const KgonKeywords& kgons, bool unfold) {
  // Copied while the GIL is held: another thread may edit `mesh` meanwhile.
  const MeshHandle snapshot = mesh;
  const SurfaceSpec spec{parse_method(method), kgon_options(kgons), unfold, semi_sharp(kgons),
                         snapshot.uvs.get()};
  py::gil_scoped_release release;
  auto built = std::make_shared<const BuiltSurface>(build_surface(*snapshot.mesh, spec));
  return {snapshot.mesh, snapshot.uvs, std::move(built)};
}

py::list unfolded_tubes(const SurfaceHandle& s) {
  py::list out;
  for (const TubeUnfolding& t : s.built->tubes) {
    py::dict d;
    d["face"] = t.face.idx;
    d["bridge"] = t.bridge.idx;
    d["fitted_folds"] = t.fitted.folds;
    d["fitted_self_intersections"] = t.fitted.self_intersections;
    d["unfolded"] = t.unfolded();
    d["face_scale"] = t.face_control.scale;
    d["face_rotate"] = t.face_control.rotate_deg;
    d["face_stretch"] = t.face_control.stretch;
    const Vec3& along = t.face_control.stretch_along;
    d["face_stretch_along"] = py::make_tuple(along.x(), along.y(), along.z());
    const Vec3& offset = t.face_control.offset;
    d["face_offset"] = py::make_tuple(offset.x(), offset.y(), offset.z());
    d["bridge_scale"] = t.bridge_control.scale;
    d["settings_tried"] = t.settings_tried;
    d["descended"] = t.descended;
    d["axis_open"] = t.axis_open;
    out.append(std::move(d));
  }
  return out;
}

TessellationOptions tessellation_options(const SurfaceHandle& s, int resolution, bool welded,
                                         bool uvs = false, bool patches = false,
                                         bool levels = false) {
  check_tessellation_size(s.patch_mesh(), resolution);
  return {.resolution = resolution, .welded = welded, .uv = uvs, .patch = patches, .level = levels};
}

TessellatedMesh run_tessellate(const SurfaceHandle& s, const TessellationOptions& options) {
  py::gil_scoped_release release;
  return tessellate(s.patch_mesh(), s.surface(), options);
}

/// The C++ call alone, in seconds, for bench/bench_python.py to compare with.
double time_tessellate(const SurfaceHandle& s, int resolution, bool welded) {
  const TessellationOptions options = tessellation_options(s, resolution, welded);
  py::gil_scoped_release release;
  const auto start = std::chrono::steady_clock::now();
  const TessellatedMesh result = tessellate(s.patch_mesh(), s.surface(), options);
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// `patches` with corner names ("V@F") replaced by their numbers, so evaluate takes either.
py::object patch_numbers(const HalfedgeMesh& mesh, py::handle patches) {
  if (py::isinstance<py::str>(patches)) return py::int_(corner_arg(mesh, patches).idx);
  const py::array a = py::array::ensure(patches);
  if (!a || (a.dtype().kind() != 'U' && a.dtype().kind() != 'O'))
    return py::reinterpret_borrow<py::object>(patches);
  py::array_t<std::int64_t> numbers(std::vector<py::ssize_t>(a.shape(), a.shape() + a.ndim()));
  const py::list flat = a.attr("ravel")().attr("tolist")();
  std::int64_t* out = numbers.mutable_data();
  for (size_t i = 0; i < flat.size(); ++i) out[i] = corner_arg(mesh, flat[i]).idx;
  return numbers;
}

py::object evaluate(const SurfaceHandle& s, py::handle patches, py::handle u, py::handle v) {
  const py::list args = py::module_::import("numpy").attr("broadcast_arrays")(
      checked_kind(patch_numbers(s.patch_mesh(), patches), "iu", "patches"),
      checked_kind(u, "fiu", "u"), checked_kind(v, "fiu", "v"));
  const auto p = checked_array<std::int64_t>(args[0], "iu", "patches");
  const auto pu = checked_array<double>(args[1], "fiu", "u");
  const auto pv = checked_array<double>(args[2], "fiu", "v");
  std::vector<py::ssize_t> shape(p.shape(), p.shape() + p.ndim());
  std::vector<py::ssize_t> vector_shape = shape;
  vector_shape.push_back(3);
  py::array_t<double> position(vector_shape), du(vector_shape), dv(vector_shape),
      normal(vector_shape);
  py::array_t<std::int32_t> level(shape);
  const std::int64_t* patch = p.data();
  const double* us = pu.data();
  const double* vs = pv.data();
  double* out[] = {position.mutable_data(), du.mutable_data(), dv.mutable_data(),
                   normal.mutable_data()};
  std::int32_t* levels = level.mutable_data();
  const py::ssize_t n = p.size();
  {
    py::gil_scoped_release release;
    const HalfedgeMesh& mesh = s.patch_mesh();
    for (py::ssize_t i = 0; i < n; ++i) {
      if (patch[i] < 0 || patch[i] >= mesh.halfedge_capacity() ||
          mesh.is_deleted(Halfedge(static_cast<int>(patch[i]))) ||
          mesh.is_hole(Halfedge(static_cast<int>(patch[i]))))
        throw py::value_error(
            fmt::format("patches[{}] = {} is not a patch of the surface (0 to {})", i, patch[i],
                        mesh.halfedge_capacity() - 1));
      if (!(us[i] >= 0 && us[i] <= 1) || !(vs[i] >= 0 && vs[i] <= 1))
        throw py::value_error(
            fmt::format("(u, v)[{}] = ({}, {}) is outside [0, 1]^2", i, us[i], vs[i]));
    }
    // Surface::evaluate is const and keeps no state, so points are evaluated in parallel as
    // tessellate() does.
    tbb::parallel_for(tbb::blocked_range<py::ssize_t>(0, n, 256), [&](const auto& range) {
      for (py::ssize_t i = range.begin(); i < range.end(); ++i) {
        const SurfacePoint sp =
            s.surface().evaluate(Corner(static_cast<int>(patch[i])), us[i], vs[i]);
        const Vec3* values[] = {&sp.position, &sp.du, &sp.dv, &sp.normal};
        for (int a = 0; a < 4; ++a)
          for (int k = 0; k < 3; ++k) out[a][3 * i + k] = (*values[a])[k];
        levels[i] = sp.level;
      }
    });
  }
  return py::module_::import("types").attr("SimpleNamespace")(
      py::arg("position") = position, py::arg("du") = du, py::arg("dv") = dv,
      py::arg("normal") = normal, py::arg("level") = level);
}

py::dict analyze(const SurfaceHandle& s, int samples_per_side) {
  if (samples_per_side < 1 || samples_per_side > 1000)
    throw py::value_error(
        fmt::format("samples_per_side must be 1 to 1000, not {}", samples_per_side));
  ContinuityOptions options;
  options.samples_per_side = samples_per_side;
  ContinuityReport r;
  {
    py::gil_scoped_release release;
    r = analyze_continuity(s.patch_mesh(), s.surface(), options);
  }
  // The keys of `stitch analyze --json`, so scripts can move between the two.
  auto stats = [](const JumpStats& j) {
    py::dict d;
    d["max_deg"] = j.max_deg;
    d["mean_deg"] = j.mean_deg;
    d["samples"] = j.samples;
    return d;
  };
  py::list by_distance;
  for (const auto& [distance, jump] : r.jump_by_distance) {
    py::dict d;
    d["distance"] = distance;
    d["max_deg"] = jump;
    by_distance.append(d);
  }
  py::dict d;
  d["method"] = to_string(r.method);
  d["touching_extraordinary"] = stats(r.touching_ev);
  d["away_from_extraordinary"] = stats(r.away_from_ev);
  d["max_position_gap_relative"] = r.max_gap;
  d["extraordinary_points"] = r.extraordinary_points;
  d["g1_normal_spread_at_extraordinary_points_deg"] = r.ev_normal_spread_deg;
  d["max_jump_by_distance"] = by_distance;
  return d;
}

/// The keyword arguments of Surface.export, named after `stitch smooth`'s options.
struct ExportKeywords {
  std::optional<int> resolution;
  std::optional<double> tolerance, angle_tolerance;
  std::string faces, units;
  bool unwelded = false, ascii = false, single_precision = false, kgons = false;
  std::optional<std::string> uv;
  std::optional<bool> welded, ascii_ply;  ///< the names of the first export()
};

OutputSpec output_spec(const SurfaceHandle& s, const std::string& path, const ExportKeywords& k) {
  OutputSpec spec;
  if (k.welded.value_or(false) && k.unwelded)
    throw py::value_error("welded=True and unwelded=True contradict each other");
  spec.unwelded = k.unwelded || (k.welded && !*k.welded);
  spec.ascii = k.ascii || k.ascii_ply.value_or(false);
  spec.single_precision = k.single_precision;
  spec.kgons = k.kgons;
  spec.units = k.units;
  spec.packing = parse_choice(face_packing_table(), k.faces, "face packing");
  const OutputFormat& format = output_format(path);
  if (k.resolution) spec.resolution = *k.resolution;
  // One tolerance for both kinds of output, as `stitch smooth --tolerance`: the exact outputs'
  // cells, or adaptive triangles instead of a fixed resolution for a mesh.
  if (k.tolerance) set_tolerance(spec, format, *k.tolerance, k.resolution.has_value());
  if (k.angle_tolerance) spec.patches.angle_tolerance_deg = *k.angle_tolerance;
  if (format.kind == OutputKind::tessellated && spec.adaptive_tolerance == 0)
    check_tessellation_size(s.patch_mesh(), spec.resolution);
  check_output(path, spec);
  return spec;
}

py::dict export_surface(const SurfaceHandle& s, const std::string& path, const ExportKeywords& k) {
  OutputSpec spec = output_spec(s, path, k);
  const OutputFormat& format = output_format(path);
  const bool none = k.uv && *k.uv == "none";
  const bool asked = k.uv && !none;
  const UvMode mode = asked ? parse_uv_mode(*k.uv) : uv_mode_table().front().value;
  std::vector<std::string> warnings, notes;
  spec.note = [&notes](const std::string& line) { notes.push_back(line); };
  OutputReport report;
  {
    py::gil_scoped_release release;
    std::unique_ptr<UvSurface> uvs;
    if (s.patch_uvs() && !none && writes_uvs(format, spec)) {
      uvs = std::make_unique<UvSurface>(s.patch_mesh(), *s.patch_uvs(), mode, s.built->kgons);
      warnings = uvs->warnings();
      spec.uvs = uvs.get();
    }
    report = write_surface(path, *s.mesh, *s.built, spec);
  }
  if (asked && report.texcoords == 0)
    warnings.push_back(
        s.uvs ? fmt::format("uv='{}': no texture coordinates were written to '{}': {} has no "
                            "place for them {}(see stitch.output_formats())",
                            *k.uv, path, format.name,
                            spec.adaptive_tolerance > 0 ? "with a tolerance " : "")
              : fmt::format("uv='{}': the mesh has no texture coordinates", *k.uv));
  for (const std::string& w : warnings)
    if (PyErr_WarnEx(PyExc_UserWarning, w.c_str(), 1) != 0) throw py::error_already_set();
  py::dict d;
  d["summary"] = report.summary;
  d["format"] = format.name;
  d["vertices"] = report.vertices;
  d["faces"] = report.faces;
  d["texcoords"] = report.texcoords;
  d["notes"] = notes;
  return d;
}

/// The texture coordinates of every sample of tessellate(resolution, welded=False), from the
/// mesh's UVs, as the writers evaluate them (the OBJ writer's `vt` lines, in the same order).
py::array_t<double> texcoords(const SurfaceHandle& s, int resolution,
                              const std::optional<std::string>& uv, py::handle other) {
  std::shared_ptr<const CornerUvs> given =
      other.is_none() ? s.patch_uvs() : corner_uvs(*s.mesh, other);
  if (s.built->refined && !other.is_none()) {
    // Refined for semi-sharp tags, the patches are the refined mesh's corners: another map is
    // refined as the mesh's own was (the same refinement again, which numbers the corners alike).
    py::gil_scoped_release release;
    given = std::make_shared<const CornerUvs>(
        refine_semi_sharp(*s.mesh, s.built->refinement.levels, s.built->kgons.boundary, given.get())
            .uvs);
  }
  if (!given)
    throw py::value_error(
        "texcoords: the mesh has no texture coordinates (has_uvs); give them with uvs=");
  check_tessellation_size(s.patch_mesh(), resolution);
  const UvMode mode = uv ? parse_uv_mode(*uv) : uv_mode_table().front().value;
  const std::vector<Corner>& corners = s.surface().corners();
  const auto per = static_cast<py::ssize_t>(resolution + 1) * (resolution + 1);
  py::array_t<double> out({per * static_cast<py::ssize_t>(corners.size()), py::ssize_t{2}});
  static_assert(sizeof(Eigen::Vector2d) == 2 * sizeof(double));
  auto* rows = reinterpret_cast<Eigen::Vector2d*>(out.mutable_data());
  std::vector<std::string> warnings;
  {
    py::gil_scoped_release release;
    const UvSurface uvs(s.patch_mesh(), *given, mode, s.built->kgons);
    warnings = uvs.warnings();
    tbb::parallel_for(tbb::blocked_range<size_t>(0, corners.size(), 64), [&](const auto& r) {
      for (size_t k = r.begin(); k < r.end(); ++k)
        uvs.evaluate_grid(corners[k], resolution, rows + static_cast<py::ssize_t>(k) * per);
    });
  }
  for (const std::string& w : warnings)
    if (PyErr_WarnEx(PyExc_UserWarning, w.c_str(), 1) != 0) throw py::error_already_set();
  return out;
}

/// The table of output formats, one dict per row.
py::list output_format_rows() {
  py::list rows;
  for (const OutputFormat& f : output_formats()) {
    py::list extensions;
    for (std::string_view e : f.extensions)
      if (!e.empty()) extensions.append(py::str(e.data(), e.size()));
    bool available = true;
    try {
      check_output(std::string("file") + std::string(f.extensions[0]), {});
    } catch (const OutputError&) {
      available = false;  // a build without OpenCASCADE
    }
    py::dict d;
    d["name"] = py::str(f.name.data(), f.name.size());
    d["extensions"] = extensions;
    d["kind"] = f.kind == OutputKind::exact ? "exact" : "tessellated";
    d["normals"] = f.mesh_format && has_vertex_normals(*f.mesh_format);
    d["uvs"] = f.uvs;
    d["unwelded"] = f.unwelded;
    d["adaptive"] = f.adaptive;
    d["needs_cad"] = f.needs_cad;
    d["available"] = available;
    const std::string_view memory = describe(f.memory);
    d["memory"] = py::str(memory.data(), memory.size());
    d["help"] = py::str(f.help.data(), f.help.size());
    rows.append(std::move(d));
  }
  return rows;
}

template <class T>
py::list rows_of(ChoiceTable<T> table) {
  py::list rows;
  for (const Choice<T>& c : table) {
    py::dict d;
    d["name"] = py::str(c.name.data(), c.name.size());
    d["help"] = py::str(c.help.data(), c.help.size());
    rows.append(std::move(d));
  }
  return rows;
}

/// Every table of names a keyword argument takes, keyed by the keyword, so front ends (the
/// Blender add-on's menus) list what the library accepts without writing the names again.
py::dict choice_rows() {
  py::dict d;
  d["method"] = rows_of(method_table());
  d["kgon_construction"] = rows_of(kgon_construction_table());
  d["boundary"] = rows_of(boundary_table());
  d["uv"] = rows_of(uv_mode_table());
  d["faces"] = rows_of(face_packing_table());
  py::list units;  // STEP's and IGES's, "a, b, c" (none in a build without OpenCASCADE)
  const std::string names = output_units();
  for (size_t at = 0; at < names.size();) {
    const size_t end = std::min(names.find(", ", at), names.size());
    py::dict u;
    u["name"] = names.substr(at, end - at);
    u["help"] = "";
    units.append(std::move(u));
    at = end + 2;
  }
  d["units"] = units;
  return d;
}

const TessellatedMesh& samples(const py::object& self) {
  return self.cast<const TessellatedMesh&>();
}

}  // namespace

void check_tessellation_size(const HalfedgeMesh& mesh, int resolution, long long patches) {
  // The command line's range; and TessellatedMesh numbers its samples with int, so their count
  // (at most (resolution + 1)^2 per half-edge) must fit one.
  if (resolution < 1 || resolution > limits::max_resolution)
    throw py::value_error(
        fmt::format("resolution must be 1 to {}, not {}", limits::max_resolution, resolution));
  const double corners = std::max<double>(mesh.halfedge_capacity(), static_cast<double>(patches));
  const double samples = corners * (resolution + 1) * (resolution + 1);
  if (samples > INT_MAX)
    throw py::value_error(fmt::format(
        "resolution {} gives up to {:.0f} samples on {:.0f} {}, more than the {} a "
        "tessellation can number",
        resolution, samples, corners,
        patches > mesh.halfedge_capacity() ? "patches of the refined mesh" : "half-edges",
        INT_MAX));
}

KgonOptions kgon_options(const KgonKeywords& k) {
  limits::check_range(k.scale, limits::min_kgon_scale, limits::max_kgon_scale, "kgon_scale");
  limits::check_range(k.rotate_deg, -limits::max_rotation_deg, limits::max_rotation_deg,
                      "kgon_rotate");
  // The range of `stitch --sharp-from`: OpenSubdiv's sharpness tops out at 10 (infinitely sharp).
  if (k.sharp_from) limits::check_range(*k.sharp_from, 0, 10, "sharp_from");
  KgonOptions o;
  o.global.scale = k.scale;
  o.global.rotate_deg = k.rotate_deg;
  o.global.regularize = k.regularize;
  o.construction = parse_choice(kgon_construction_table(), k.construction, "kgon_construction");
  o.boundary = parse_choice(boundary_table(), k.boundary, "boundary");
  o.sharp_from = k.sharp_from.value_or(KgonOptions{}.sharp_from);
  return o;
}

SemiSharp semi_sharp(const KgonKeywords& k) {
  return k.sharp_from ? SemiSharp::round : SemiSharp::refine;
}

py::dict refinement_dict(const SemiSharpRefinement& r) {
  py::dict d;
  d["levels"] = r.levels;
  d["levels_wanted"] = r.levels_wanted;
  d["largest_tag"] = r.largest_tag;
  d["faces"] = r.faces;
  d["patches"] = r.patches;
  d["summary"] = r.summary();
  return d;
}

std::string kgon_keywords_help() {
  return fmt::format(
      "kgon_scale, kgon_rotate (degrees), regularize: applied to every K-gon with K != 4, as "
      "stitch's --kgon-scale, --kgon-rotate and --regularize. kgon_construction: {}. boundary: "
      "{}. sharp_from: None (default) honours semi-sharp crease and corner tags as OpenSubdiv "
      "does, by refining the mesh before the patches (refinement; Surface.refined_mesh); a "
      "number rounds them for the K-gon methods: tags of at least this sharpness (0 to 10) "
      "infinitely sharp, smaller ones smooth.",
      choice_help(kgon_construction_table()), choice_help(boundary_table()));
}

void bind_surface(py::module_& m) {
  // Buffers stay where tessellate() put them: the arrays are views whose base is this object.
  py::class_<TessellatedMesh>(m, "Tessellation",
                              "The tessellated surface. Its arrays are read-only views of the "
                              "buffers the library filled (no copies); copy one to change it.")
      .def_property_readonly(
          "vertices",
          [](const py::object& self) {
            return view_rows<double, 3>(samples(self).positions, self);
          },
          "(n, 3) float64 sample positions")
      .def_property_readonly(
          "normals",
          [](const py::object& self) { return view_rows<double, 3>(samples(self).normals, self); },
          "(n, 3) float64 unit normals")
      .def_property_readonly(
          "uvs",
          [](const py::object& self) { return view_rows<double, 2>(samples(self).uv, self); },
          "(n, 2) float64: each sample's (u, v) in its patch (tessellate(uvs=True); else (0, 2))")
      .def_property_readonly(
          "patches", [](const py::object& self) { return view(samples(self).patch, self); },
          "(n,) int32: the patch (corner, half-edge index) each sample lies on "
          "(tessellate(patches=True); else empty)")
      .def_property_readonly(
          "levels", [](const py::object& self) { return view(samples(self).level, self); },
          "(n,) int32: hierarchy level of the sub-patch each sample came from "
          "(tessellate(levels=True); else empty)")
      .def_property_readonly(
          "quads",
          [](const py::object& self) { return view_rows<int, 4>(samples(self).quads, self); },
          "(m, 4) int32 vertex indices, counter-clockwise seen from the normal side")
      .def("__repr__", [](const TessellatedMesh& t) {
        return fmt::format("<stitch.Tessellation {} vertices, {} quads>", t.num_vertices(),
                           t.quads.size());
      });

  const std::string method_default{method_table().front().name};
  const std::string init_doc = fmt::format(
      "The smooth surface of the mesh, built as `stitch smooth` builds it (the library's "
      "build_surface), so the same request gives the same surface. method: {}. {} "
      "unfold_tubes: where the surface over a face made by inserting an edge between two faces "
      "folds, choose that face's and its bridge's K-gon controls by a search that checks the "
      "surface, as stitch does unless --no-unfold-tubes (see unfolded_tubes). The surface keeps "
      "the mesh as it was (later edits do not change it).",
      choice_help(method_table()), kgon_keywords_help());
  const std::string export_doc = fmt::format(
      "Writes the surface as `stitch smooth -o path` does, in the format the extension names: "
      "{} (stitch.output_formats() describes each). Returns a dict: summary (the line stitch "
      "prints), format, vertices, faces (quads or triangles of a mesh, patches of Bezier JSON, "
      "B-spline faces of STEP and IGES), texcoords, notes (the patch set's depth and "
      "deviation). Mesh outputs: resolution (segments per patch side, default {}), or "
      "tolerance for adaptive triangles instead (relative to the model size); unwelded: every "
      "patch's own grid with (u, v) and patch (binary PLY); ascii, float: PLY as text, or with "
      "32-bit positions and normals; uv: the texture coordinates of a mesh read with them: {}; "
      "'none' (default: the first, where the format has a place for them). Exact outputs: "
      "tolerance (default {:g}, relative to the model size) and angle_tolerance (degrees, "
      "default {:g}) of the innermost cells at extraordinary points; faces (STEP, IGES): {}; "
      "units (STEP, IGES, declared, coordinates are not scaled): {}; kgons (Bezier JSON): add "
      "every K-gon. welded=False and ascii_ply=True are the older names of unwelded and ascii.",
      output_extensions(), kDefaultResolution, choice_help(uv_mode_table()),
      PatchSetOptions{}.tolerance, PatchSetOptions{}.angle_tolerance_deg,
      choice_help(face_packing_table()), output_units());

  const std::string texcoords_doc = fmt::format(
      "The texture coordinates of the mesh's UVs (has_uvs) at every sample of "
      "tessellate(resolution, welded=False), an (n, 2) float64 array in the order of its "
      "vertices, as the writers evaluate them. uv: {} (default: the first). uvs: another UV "
      "map of the same mesh instead, per corner as stitch.Mesh(uvs=...) takes it (refined as the "
      "mesh's own where the surface is refined for semi-sharp tags).",
      choice_help(uv_mode_table()));
  py::class_<SurfaceHandle>(m, "Surface", "The smooth surface of a mesh: one patch per corner.")
      .def(py::init([](const MeshHandle& mesh, const std::string& method, double kgon_scale,
                       double kgon_rotate, bool regularize, const std::string& construction,
                       bool unfold, const std::string& boundary, std::optional<double> sharp_from) {
             return make_surface(
                 mesh, method,
                 {kgon_scale, kgon_rotate, regularize, construction, boundary, sharp_from}, unfold);
           }),
           py::arg("mesh"), py::arg("method") = method_default, py::kw_only(),
           py::arg("kgon_scale") = 1.0, py::arg("kgon_rotate") = 0.0, py::arg("regularize") = false,
           py::arg("kgon_construction") = std::string(kgon_construction_table().front().name),
           py::arg("unfold_tubes") = true,
           py::arg("boundary") = std::string(boundary_table().front().name),
           py::arg("sharp_from") = py::none(), init_doc.c_str())
      .def_property_readonly("unfolded_tubes", &unfolded_tubes,
                             "One dict per tube whose fitted K-gons folded: face and bridge "
                             "(0-based face and edge indices), fitted_folds and "
                             "fitted_self_intersections (pairs of triangles at resolution 16), "
                             "unfolded (a clean setting was found), face_scale, face_rotate "
                             "(degrees), face_stretch, face_stretch_along, face_offset and "
                             "bridge_scale (the controls used), settings_tried, descended (found "
                             "by the descent past the grid of settings), axis_open (the line "
                             "through the openings' centres misses the tube)")
      .def_property_readonly("method",
                             [](const SurfaceHandle& s) { return to_string(s.surface().method()); })
      .def_property_readonly("mesh",
                             [](const SurfaceHandle& s) {
                               return MeshHandle{s.mesh, s.uvs};
                             })
      .def_property_readonly(
          "refined_mesh",
          [](const SurfaceHandle& s) -> py::object {
            if (!s.built->refined) return py::none();
            return py::cast(
                MeshHandle{std::make_shared<const HalfedgeMesh>(s.patch_mesh()), nullptr});
          },
          "The mesh whose corners are the patches when the surface refined `mesh` for its "
          "semi-sharp tags (a copy); None otherwise, when the patches are mesh's corners")
      .def_property_readonly(
          "refinement", [](const SurfaceHandle& s) { return refinement_dict(s.built->refinement); },
          "What honouring the semi-sharp tags took: levels of uniform refinement (0: none), "
          "levels_wanted, largest_tag, faces and patches of the refined mesh, summary")
      .def_property_readonly(
          "patches",
          [](const py::object& self) {
            const auto& corners = self.cast<const SurfaceHandle&>().surface().corners();
            static_assert(sizeof(Corner) == sizeof(int));
            return view(reinterpret_cast<const int*>(corners.data()),
                        {static_cast<py::ssize_t>(corners.size())}, self);
          },
          "(p,) int32: the patch numbers. A patch is a corner of the mesh (of refined_mesh "
          "when the surface refined it for semi-sharp tags: a vertex on a face), numbered by "
          "its half-edge: 0 to p - 1 in half-edge order for a closed mesh, "
          "with gaps where a boundary's half-edges are (they have no patch). The numbers of "
          "evaluate, Tessellation.patches, unwelded PLY and `stitch eval`; corner_name(p) "
          "gives the name \"V@F\" of Bezier JSON, STEP and edit operations, patch(name) and "
          "patch_of(face=, vertex=) the number back.")
      .def(
          "corner_name",
          [](const SurfaceHandle& s, py::handle patch) {
            return corner_name(s.patch_mesh(), corner_arg(s.patch_mesh(), patch));
          },
          py::arg("patch"),
          "The name \"V@F\" of a patch: its corner, vertex V on face F, numbered from 1 as in "
          "Mesh.edit (\"V@F#k\" when V appears on F more than once), as `stitch eval`, Bezier "
          "JSON and the faces of STEP and IGES files name it.")
      .def(
          "patch",
          [](const SurfaceHandle& s, const std::string& name) {
            return corner_arg(s.patch_mesh(), py::str(name)).idx;
          },
          py::arg("name"), "The patch number of the corner named \"V@F\" (or \"V@F#k\").")
      .def(
          "patch_of",
          [](const SurfaceHandle& s, int face, int vertex, int occurrence) {
            return corner_of(s.patch_mesh(), face, vertex, occurrence).idx;
          },
          py::kw_only(), py::arg("face"), py::arg("vertex"), py::arg("occurrence") = 0,
          "The patch number of vertex `vertex` on face `face`, both 0-based like mesh.faces "
          "and mesh.vertices (the name is f\"{vertex + 1}@{face + 1}\"). occurrence: k >= 1 "
          "picks the k-th appearance of a vertex that appears on the face more than once.")
      .def_property_readonly(
          "patch_faces",
          [](const SurfaceHandle& s) {
            const std::vector<Corner>& corners = s.surface().corners();
            // A refined surface's patches come from the input corners whose patches hold them.
            const std::vector<Corner> input =
                s.built->refined ? s.built->refined->input_corners() : std::vector<Corner>{};
            py::array_t<int> faces(static_cast<py::ssize_t>(corners.size()));
            for (size_t k = 0; k < corners.size(); ++k)
              faces.mutable_data()[k] = input.empty() ? s.mesh->face(corners[k]).idx
                                                      : s.mesh->face(input[corners[k].idx]).idx;
            return faces;
          },
          "(p,) int32: the 0-based face of mesh (as in mesh.faces, also when the surface "
          "refined it for semi-sharp tags) of each patch, in the order of patches: where each "
          "patch, and each quad of a tessellation, comes from")
      .def("texcoords", &texcoords, py::arg("resolution") = kDefaultResolution, py::kw_only(),
           py::arg("uv") = py::none(), py::arg("uvs") = py::none(), texcoords_doc.c_str())
      .def(
          "tessellate",
          [](const SurfaceHandle& s, int resolution, bool welded, bool uvs, bool patches,
             bool levels) {
            return py::cast(run_tessellate(
                s, tessellation_options(s, resolution, welded, uvs, patches, levels)));
          },
          py::arg("resolution") = kDefaultResolution, py::arg("welded") = true, py::kw_only(),
          py::arg("uvs") = false, py::arg("patches") = false, py::arg("levels") = false,
          "Samples every patch on a (resolution + 1)^2 grid. welded: one watertight mesh "
          "sharing samples on patch boundaries; otherwise every patch's own grid. Both list "
          "the same quads in the same order, patch after patch in the order of patches "
          "(resolution^2 each), so quad q's corners are samples quads[q] of either: the "
          "unwelded ones carry what differs between patches at a shared sample (normals across "
          "a crease, texcoords across a seam). The result has vertices, normals and quads; uvs, "
          "patches, levels: also each sample's (u, v) in its patch, its patch, its level (empty "
          "arrays unless asked: 24 bytes per vertex together).")
      .def("evaluate", &evaluate, py::arg("patches"), py::arg("u"), py::arg("v"),
           "Exact evaluation at (patch, u, v), vectorised: the arguments broadcast against each "
           "other. A patch is its number (see patches) or its name \"V@F\"; an array of names "
           "works too. Returns a namespace of position, du, dv, normal (shape + (3,), float64) "
           "and level (int32).")
      .def("analyze", &analyze, py::kw_only(), py::arg("samples_per_side") = 8,
           "Continuity measured (normal jumps across patch boundaries, G1 at extraordinary "
           "points), as a dict with the keys of `stitch analyze --json`.")
      .def(
          "export",
          [](const SurfaceHandle& s, const std::string& path, std::optional<int> resolution,
             std::optional<double> tolerance, std::optional<double> angle_tolerance,
             const std::string& faces, const std::string& units, bool unwelded, bool ascii,
             bool single_precision, bool kgons, std::optional<std::string> uv,
             std::optional<bool> welded, std::optional<bool> ascii_ply) {
            return export_surface(
                s, path,
                {resolution, tolerance, angle_tolerance, faces, units, unwelded, ascii,
                 single_precision, kgons, std::move(uv), welded, ascii_ply});
          },
          py::arg("path"), py::kw_only(), py::arg("resolution") = py::none(),
          py::arg("tolerance") = py::none(), py::arg("angle_tolerance") = py::none(),
          py::arg("faces") = std::string(face_packing_table().front().name),
          py::arg("units") = OutputSpec{}.units, py::arg("unwelded") = false,
          py::arg("ascii") = false, py::arg("float") = false, py::arg("kgons") = false,
          py::arg("uv") = py::none(), py::arg("welded") = py::none(),
          py::arg("ascii_ply") = py::none(), export_doc.c_str())
      .def("_time_tessellate", &time_tessellate, py::arg("resolution"), py::arg("welded") = true,
           "Seconds the C++ tessellate() call takes, result discarded (for benchmarks).")
      .def("__repr__", [](const SurfaceHandle& s) {
        return fmt::format("<stitch.Surface {}, {} patches>", to_string(s.surface().method()),
                           s.surface().corners().size());
      });

  m.def("choices", &choice_rows,
        "The names the keyword arguments take, from the library's tables (as `stitch smooth "
        "--help` lists them): a dict from the keyword (method, kgon_construction, boundary, uv, "
        "faces, units) to a list of dicts of name and help, the default first.");
  m.def("output_formats", &output_format_rows,
        "The formats Surface.export writes, one dict per row of the library's table (as "
        "`stitch smooth --help` lists them): name, extensions, kind ('tessellated' or 'exact'), "
        "normals, uvs, unwelded, adaptive (what the format takes), needs_cad (written through "
        "OpenCASCADE), available (this build writes it), memory (what the writer holds), help.");
}

}  // namespace stitch::python
