// stitch.Surface: the smooth surface of a mesh for one method, with tessellation, exact
// evaluation, continuity analysis and export; stitch.Tessellation owns tessellate()'s buffers.
#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <chrono>
#include <climits>
#include <cstdint>

#include "arrays.hpp"
#include "bindings.hpp"
#include "stitch/analysis/continuity.hpp"
#include "stitch/analysis/unfold_tubes.hpp"
#include "stitch/eval/surface.hpp"
#include "stitch/mesh/limits.hpp"
#include "stitch/tess/export.hpp"
#include "stitch/tess/tessellate.hpp"

namespace stitch::python {

namespace {

/// The surface with the mesh snapshot it was built from (tessellation and analysis need both).
struct SurfaceHandle {
  std::shared_ptr<const HalfedgeMesh> mesh;
  std::shared_ptr<const Surface> surface;
  /// What unfold_tubes found (nothing when it was off or no tube folded).
  std::vector<TubeUnfolding> unfolded;
};

SurfaceHandle make_surface(const MeshHandle& mesh, const std::string& method, double kgon_scale,
                           double kgon_rotate, bool regularize, const std::string& construction,
                           bool unfold) {
  const Method m = parse_method(method);
  KgonOptions options = kgon_options(kgon_scale, kgon_rotate, regularize, construction);
  // Copied while the GIL is held: another thread may edit `mesh` meanwhile.
  std::shared_ptr<const HalfedgeMesh> snapshot = mesh.mesh;
  py::gil_scoped_release release;
  std::vector<TubeUnfolding> unfolded;
  if (unfold) {
    UnfoldTubesOptions o;
    o.method = m;
    unfolded = unfold_tubes(*snapshot, options, o);
  }
  auto surface = std::make_shared<const Surface>(*snapshot, m, options);
  return {std::move(snapshot), std::move(surface), std::move(unfolded)};
}

py::list unfolded_tubes(const SurfaceHandle& s) {
  py::list out;
  for (const TubeUnfolding& t : s.unfolded) {
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

TessellationOptions tessellation_options(const SurfaceHandle& s, int resolution, bool welded) {
  check_tessellation_size(*s.mesh, resolution);
  return {resolution, welded};
}

TessellatedMesh run_tessellate(const SurfaceHandle& s, const TessellationOptions& options) {
  py::gil_scoped_release release;
  return tessellate(*s.mesh, *s.surface, options);
}

/// The C++ call alone, in seconds, for bench/bench_python.py to compare with.
double time_tessellate(const SurfaceHandle& s, int resolution, bool welded) {
  const TessellationOptions options = tessellation_options(s, resolution, welded);
  py::gil_scoped_release release;
  const auto start = std::chrono::steady_clock::now();
  const TessellatedMesh result = tessellate(*s.mesh, *s.surface, options);
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

py::object evaluate(const SurfaceHandle& s, py::handle patches, py::handle u, py::handle v) {
  const py::list args = py::module_::import("numpy").attr("broadcast_arrays")(
      checked_kind(patches, "iu", "patches"), checked_kind(u, "fiu", "u"),
      checked_kind(v, "fiu", "v"));
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
    const HalfedgeMesh& mesh = *s.mesh;
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
            s.surface->evaluate(Corner(static_cast<int>(patch[i])), us[i], vs[i]);
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
    r = analyze_continuity(*s.mesh, *s.surface, options);
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

void export_surface(const SurfaceHandle& s, const std::string& path, int resolution, bool welded,
                    bool ascii_ply) {
  const TessellationOptions options = tessellation_options(s, resolution, welded);
  py::gil_scoped_release release;
  if (welded) {
    SurfaceFileOptions file;
    file.ascii_ply = ascii_ply;
    write_smooth_surface(path, *s.mesh, *s.surface, options.resolution, file);
  } else {
    write_surface_samples_ply(path, tessellate(*s.mesh, *s.surface, options));
  }
}

const TessellatedMesh& samples(const py::object& self) {
  return self.cast<const TessellatedMesh&>();
}

}  // namespace

void check_tessellation_size(const HalfedgeMesh& mesh, int resolution) {
  // The command line's range; and TessellatedMesh numbers its samples with int, so their count
  // (at most (resolution + 1)^2 per half-edge) must fit one.
  if (resolution < 1 || resolution > limits::max_resolution)
    throw py::value_error(
        fmt::format("resolution must be 1 to {}, not {}", limits::max_resolution, resolution));
  const double samples =
      static_cast<double>(mesh.halfedge_capacity()) * (resolution + 1) * (resolution + 1);
  if (samples > INT_MAX)
    throw py::value_error(
        fmt::format("resolution {} gives up to {:.0f} samples on {} half-edges, more than the {} a "
                    "tessellation can number",
                    resolution, samples, mesh.halfedge_capacity(), INT_MAX));
}

KgonOptions kgon_options(double scale, double rotate_deg, bool regularize,
                         const std::string& construction) {
  limits::check_range(scale, limits::min_kgon_scale, limits::max_kgon_scale, "kgon_scale");
  limits::check_range(rotate_deg, -limits::max_rotation_deg, limits::max_rotation_deg,
                      "kgon_rotate");
  KgonOptions o;
  o.global.scale = scale;
  o.global.rotate_deg = rotate_deg;
  o.global.regularize = regularize;
  if (construction == "doo-sabin")
    o.construction = KgonConstruction::doo_sabin;
  else if (construction != "openings")
    throw py::value_error(
        fmt::format("kgon_construction must be 'openings' or 'doo-sabin', not '{}'", construction));
  return o;
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
          "(n, 2) float64: each sample's (u, v) in its patch")
      .def_property_readonly(
          "patches", [](const py::object& self) { return view(samples(self).patch, self); },
          "(n,) int32: the patch (corner, half-edge index) each sample lies on")
      .def_property_readonly(
          "levels", [](const py::object& self) { return view(samples(self).level, self); },
          "(n,) int32: hierarchy level of the sub-patch each sample came from")
      .def_property_readonly(
          "quads",
          [](const py::object& self) { return view_rows<int, 4>(samples(self).quads, self); },
          "(m, 4) int32 vertex indices, counter-clockwise seen from the normal side")
      .def("__repr__", [](const TessellatedMesh& t) {
        return fmt::format("<stitch.Tessellation {} vertices, {} quads>", t.num_vertices(),
                           t.quads.size());
      });

  py::class_<SurfaceHandle>(m, "Surface", "The smooth surface of a mesh: one patch per corner.")
      .def(py::init(&make_surface), py::arg("mesh"), py::arg("method") = "mdc", py::kw_only(),
           py::arg("kgon_scale") = 1.0, py::arg("kgon_rotate") = 0.0, py::arg("regularize") = false,
           py::arg("kgon_construction") = "openings", py::arg("unfold_tubes") = true,
           "method: 'mdc' (modified de Casteljau, the paper's), 'asc' (AS&C baseline) or 'cc' "
           "(Catmull-Clark through OpenSubdiv). The K-gon controls apply to every K-gon with "
           "K != 4, as stitch's --kgon-scale, --kgon-rotate (degrees), --regularize and "
           "--kgon-construction. unfold_tubes: where the surface over a face made by inserting "
           "an edge between two faces folds, choose that face's and its bridge's K-gon "
           "controls by a search that checks the surface, as stitch does unless "
           "--no-unfold-tubes (see unfolded_tubes). The surface keeps the mesh as it was "
           "(later edits do not change it).")
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
                             [](const SurfaceHandle& s) { return to_string(s.surface->method()); })
      .def_property_readonly("mesh", [](const SurfaceHandle& s) { return MeshHandle{s.mesh}; })
      .def_property_readonly(
          "patches",
          [](const py::object& self) {
            const auto& corners = self.cast<const SurfaceHandle&>().surface->corners();
            static_assert(sizeof(Corner) == sizeof(int));
            return view(reinterpret_cast<const int*>(corners.data()),
                        {static_cast<py::ssize_t>(corners.size())}, self);
          },
          "(p,) int32: the patch numbers (the mesh's live half-edges)")
      .def(
          "tessellate",
          [](const SurfaceHandle& s, int resolution, bool welded) {
            return py::cast(run_tessellate(s, tessellation_options(s, resolution, welded)));
          },
          py::arg("resolution") = 8, py::arg("welded") = true,
          "Samples every patch on a (resolution + 1)^2 grid. welded: one watertight mesh "
          "sharing samples on patch boundaries; otherwise every patch's own grid.")
      .def("evaluate", &evaluate, py::arg("patches"), py::arg("u"), py::arg("v"),
           "Exact evaluation at (patch, u, v), vectorised: the arguments broadcast against each "
           "other. Returns a namespace of position, du, dv, normal (shape + (3,), float64) and "
           "level (int32).")
      .def("analyze", &analyze, py::kw_only(), py::arg("samples_per_side") = 8,
           "Continuity measured (normal jumps across patch boundaries, G1 at extraordinary "
           "points), as a dict with the keys of `stitch analyze --json`.")
      .def("export", &export_surface, py::arg("path"), py::kw_only(), py::arg("resolution") = 8,
           py::arg("welded") = true, py::arg("ascii_ply") = false,
           "Tessellates and writes as `stitch smooth -o` does. Welded: by extension, "
           "evaluated block by block as it is written (memory does not grow with the "
           "resolution). Unwelded: binary .ply with every sample's position, normal, (u, v) and "
           "patch.")
      .def("_time_tessellate", &time_tessellate, py::arg("resolution"), py::arg("welded") = true,
           "Seconds the C++ tessellate() call takes, result discarded (for benchmarks).")
      .def("__repr__", [](const SurfaceHandle& s) {
        return fmt::format("<stitch.Surface {}, {} patches>", to_string(s.surface->method()),
                           s.surface->corners().size());
      });
}

}  // namespace stitch::python
