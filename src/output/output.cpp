// stitch's headers before OCCT's (OCCT defines a macro Handle, see cad.hpp)
// clang-format off
#include "stitch/output/output.hpp"

#include "stitch/error.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/tess/adaptive.hpp"
#include "stitch/tess/bezier_json.hpp"
#include "stitch/tess/export.hpp"
#if STITCH_WITH_CAD
#include "stitch/cad/cad.hpp"
#endif
// clang-format on

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace stitch {

namespace {

/// What every tessellated file reports: its counts, the patches, the method and the sampling.
std::string mesh_summary(const HalfedgeMesh& mesh, const Surface& surface, const OutputSpec& spec,
                         std::int64_t vertices, std::int64_t quads, std::int64_t texcoords) {
  return fmt::format("{} vertices, {} quads, {} {}, method {}, resolution {}{}", vertices, quads,
                     static_cast<int>(mesh.patch_corners().size()),
                     surface.method() == Method::cc ? "sub-patches" : "bicubic patches",
                     to_string(surface.method()), spec.resolution,
                     texcoords > 0 ? fmt::format(", {} texture coordinates ({} UVs)", texcoords,
                                                 to_string(spec.uvs->mode()))
                                   : std::string());
}

SurfaceFileOptions file_options(const OutputSpec& spec, const OutputFormat& format) {
  SurfaceFileOptions file;
  file.ascii_ply = spec.ascii;
  file.single_precision = spec.single_precision;
  file.progress = spec.progress;
  file.uvs = format.uvs ? spec.uvs : nullptr;
  return file;
}

/// The tessellated formats: uniform and streamed (welded), per patch (unwelded), or adaptive.
OutputReport write_mesh(const std::string& path, const HalfedgeMesh& mesh, const Surface& surface,
                        const OutputSpec& spec, const OutputFormat& format) {
  OutputReport r;
  const MeshFileFormat mesh_format = format.mesh_format.value();
  if (spec.adaptive_tolerance > 0) {
    const AdaptiveMesh adaptive = tessellate_adaptive(mesh, surface, {spec.adaptive_tolerance});
    write_adaptive_mesh(path, mesh_format, adaptive, file_options(spec, format));
    r.vertices = adaptive.num_vertices();
    r.faces = static_cast<std::int64_t>(adaptive.triangles.size());
    r.summary = fmt::format(
        "{} vertices, {} triangles, method {}, tolerance {}: {} to {} segments per patch side",
        r.vertices, r.faces, to_string(surface.method()), spec.adaptive_tolerance,
        adaptive.min_rate, adaptive.max_rate);
    return r;
  }
  if (spec.unwelded) {
    const TessellatedMesh samples = tessellate(
        mesh, surface, {.resolution = spec.resolution, .welded = false, .uv = true, .patch = true});
    write_surface_samples_ply(path, samples, spec.uvs);
    r.vertices = samples.num_vertices();
    r.faces = static_cast<std::int64_t>(samples.quads.size());
    r.texcoords = spec.uvs ? r.vertices : 0;
  } else {
    const SurfaceFileCounts c = write_smooth_surface(path, mesh_format, mesh, surface,
                                                     spec.resolution, file_options(spec, format));
    r.vertices = c.vertices;
    r.faces = c.quads;
    r.texcoords = c.texcoords;
  }
  r.summary = mesh_summary(mesh, surface, spec, r.vertices, r.faces, r.texcoords);
  return r;
}

/// The patch set for an exact format, with its depth and deviations told as notes; its progress
/// is the first `share` of the whole.
PatchSet patch_set(const HalfedgeMesh& mesh, const Surface& surface, const OutputSpec& spec,
                   double share) {
  PatchSet set = bezier_patches(mesh, surface, spec.patches, [&](double done) {
    if (spec.progress) spec.progress(share * done);
  });
  if (!spec.note) return set;
  spec.note(fmt::format(
      "{} Bezier patches ({} exact, {} innermost cells at extraordinary points), depth {}",
      set.patches.size(), set.num_exact(), set.patches.size() - set.num_exact(), set.depth));
  spec.note(fmt::format(
      "largest deviation from the surface: {:.3g} ({:.3g} of the model size {:.6g}; asked "
      "{:.3g}), normal {:.3g} degrees (asked {:.3g}: half the {:.3g} between faces)",
      set.max_position_deviation,
      set.model_size > 0 ? set.max_position_deviation / set.model_size : 0.0, set.model_size,
      set.tolerance, set.max_normal_deviation_deg, set.cell_angle_tolerance_deg(),
      set.angle_tolerance_deg));
  if (!set.points_without_normal.empty()) {
    constexpr size_t kNamed = 8;
    std::string where;
    for (size_t i = 0; i < set.points_without_normal.size() && i < kNamed; ++i)
      where += fmt::format("{}{} ({:.3g} degrees)", i ? ", " : "",
                           describe(mesh, set.points_without_normal[i]),
                           set.points_without_normal[i].angle_deg);
    if (set.points_without_normal.size() > kNamed)
      where += fmt::format(", ... ({} more)", set.points_without_normal.size() - kNamed);
    spec.note(fmt::format(
        "the angle tolerance is not applied at {} point(s) where the surface has no tangent "
        "plane (cone points of creases and corners, valence-2 vertices, folds): {}",
        set.points_without_normal.size(), where));
  }
  return set;
}

OutputReport write_bezier(const std::string& path, const HalfedgeMesh& mesh, const Surface& surface,
                          const OutputSpec& spec, const OutputFormat&) {
  const PatchSet set = patch_set(mesh, surface, spec, 0.8);
  write_bezier_json(path, set, spec.kgons ? &surface.bezier().kgons : nullptr);
  if (spec.progress) spec.progress(1.0);
  OutputReport r;
  r.faces = static_cast<std::int64_t>(set.patches.size());
  r.summary = fmt::format("{} Bezier patches, depth {}, method {}", set.patches.size(), set.depth,
                          to_string(surface.method()));
  return r;
}

#if STITCH_WITH_CAD
OutputReport write_cad_file(const std::string& path, const HalfedgeMesh& mesh,
                            const Surface& surface, const OutputSpec& spec,
                            const OutputFormat& format, cad::CadFormat cad_format) {
  // The patch set takes about a fifth of the whole, the faces and the file the rest.
  constexpr double kPatchShare = 0.2;
  const PatchSet set = patch_set(mesh, surface, spec, kPatchShare);
  const cad::CadEstimate e =
      cad::estimate_cad(mesh, surface, set, spec.packing, cad_format, spec.control);
  if (spec.note)
    spec.note(fmt::format(
        "writing {} {} ({} B-spline faces, about {} poles and {:.1f} MB{})", path, format.name,
        e.faces, e.poles, e.bytes / 1e6,
        e.seconds >= 30 ? fmt::format("; this takes about {:.0f} s", e.seconds) : std::string()));
  cad::quiet_opencascade();
  cad::CadOptions options;
  options.units = spec.units;
  options.packing = spec.packing;
  options.control = spec.control;
  options.angle_tolerance_deg = spec.patches.angle_tolerance_deg;
  if (spec.progress)
    options.progress = [&](double done) { spec.progress(kPatchShare + (1 - kPatchShare) * done); };
  const cad::CadReport c = cad::write_cad(path, cad_format, mesh, surface, set, options);
  OutputReport r;
  r.faces = c.faces;
  r.summary = fmt::format(
      "{} B-spline faces ({}), {} poles, knots {} removed/{} C2/{} C1/{} C0, {} shell(s), {} "
      "solid(s){}, {} free edges, {} smooth edges ({} G1, largest angle {:.3g} degrees), {} "
      "sharp edges, units {}, method {}",
      c.faces, choice_name(face_packing_table(), spec.packing), c.poles, c.knots[0], c.knots[1],
      c.knots[2], c.knots[3], c.shells, c.solids,
      c.volume > 0 ? fmt::format(", volume {:.9g}", c.volume) : std::string(), c.free_edges,
      c.smooth_edges, c.g1_edges, c.max_smooth_angle_deg, c.sharp_edges, spec.units,
      to_string(surface.method()));
  return r;
}

OutputReport write_step(const std::string& path, const HalfedgeMesh& mesh, const Surface& surface,
                        const OutputSpec& spec, const OutputFormat& format) {
  return write_cad_file(path, mesh, surface, spec, format, cad::CadFormat::step);
}

OutputReport write_iges(const std::string& path, const HalfedgeMesh& mesh, const Surface& surface,
                        const OutputSpec& spec, const OutputFormat& format) {
  return write_cad_file(path, mesh, surface, spec, format, cad::CadFormat::iges);
}
#else
/// check_output refuses STEP and IGES before any work in a build without OpenCASCADE.
OutputReport write_step(const std::string& path, const HalfedgeMesh&, const Surface&,
                        const OutputSpec&, const OutputFormat&) {
  throw OutputError(fmt::format(
      "cannot write '{}': this stitch was built without OpenCASCADE (STITCH_BUILD_CAD=OFF)", path));
}
constexpr auto write_iges = write_step;
#endif

bool ends_with(std::string_view text, std::string_view end) {
  if (end.size() > text.size()) return false;
  return std::equal(end.rbegin(), end.rend(), text.rbegin(), [](char a, char b) {
    return a == static_cast<char>(std::tolower(static_cast<unsigned char>(b)));
  });
}

}  // namespace

std::span<const OutputFormat> output_formats() {
  using K = OutputKind;
  using M = MemoryModel;
  static const OutputFormat kFormats[] = {
      {.name = "binary PLY",
       .extensions = {".ply", ""},
       .mesh_format = MeshFileFormat::ply,
       .unwelded = true,
       .adaptive = true,
       .help = "double x y z nx ny nz (or text, or floats); the fastest and smallest; unwelded: "
               "every patch's own grid with its (u, v), patch and texture coordinates",
       .write = write_mesh},
      {.name = "Wavefront OBJ",
       .extensions = {".obj", ""},
       .mesh_format = MeshFileFormat::obj,
       .uvs = true,
       .adaptive = true,
       .help = "positions, normals and texture coordinates (seams kept)",
       .write = write_mesh},
      {.name = "OFF",
       .extensions = {".off", ""},
       .mesh_format = MeshFileFormat::off,
       .adaptive = true,
       .help = "positions and faces only",
       .write = write_mesh},
      {.name = "binary STL",
       .extensions = {".stl", ""},
       .mesh_format = MeshFileFormat::stl,
       .adaptive = true,
       .help = "triangles with facet normals",
       .write = write_mesh},
      {.name = "glTF 2.0 binary",
       .extensions = {".glb", ""},
       .mesh_format = MeshFileFormat::glb,
       .uvs = true,
       .help = "positions, normals, TEXCOORD_0 (vertices split at seams, for which the "
               "tessellation is held whole)",
       .write = write_mesh},
      {.name = "glTF 2.0",
       .extensions = {".gltf", ""},
       .mesh_format = MeshFileFormat::gltf,
       .uvs = true,
       .help = "as .glb, with the buffer in a .bin beside it (no 4 GB limit)",
       .write = write_mesh},
      {.name = "Bezier JSON",
       .extensions = {".bez.json", ".json"},
       .kind = K::exact,
       .memory = M::patch_set,
       .help = "the patches of the hierarchy as data (docs/formats.md)",
       .write = write_bezier},
      {.name = "STEP AP214",
       .extensions = {".step", ".stp"},
       .kind = K::exact,
       .needs_cad = true,
       .memory = M::cad_model,
       .help = "B-spline faces named after their control faces, joined into shells and solids",
       .write = write_step},
      {.name = "IGES 5.3",
       .extensions = {".igs", ".iges"},
       .kind = K::exact,
       .needs_cad = true,
       .memory = M::cad_model,
       .help = "B-spline faces named after their control faces, joined into shells and solids",
       .write = write_iges},
  };
  return kFormats;
}

const OutputFormat* find_output_format(std::string_view path,
                                       std::span<const OutputFormat> formats) {
  // The longest extension that matches, so that x.bez.json is Bézier JSON, not plain .json.
  const OutputFormat* best = nullptr;
  size_t best_length = 0;
  for (const OutputFormat& f : formats)
    for (std::string_view ext : f.extensions)
      if (!ext.empty() && ext.size() > best_length && ends_with(path, ext)) {
        best = &f;
        best_length = ext.size();
      }
  return best;
}

const OutputFormat& output_format(const std::string& path, std::span<const OutputFormat> formats) {
  if (const OutputFormat* f = find_output_format(path, formats)) return *f;
  throw UsageError(fmt::format("cannot tell the output format of '{}': use {}", path,
                               output_extensions(std::nullopt, formats)));
}

std::string output_extensions(std::optional<OutputKind> kind,
                              std::span<const OutputFormat> formats) {
  std::string out;
  for (const OutputFormat& f : formats) {
    if (kind && f.kind != *kind) continue;
    for (std::string_view ext : f.extensions)
      if (!ext.empty()) out += (out.empty() ? "" : ", ") + std::string(ext);
  }
  return out;
}

std::string output_units() {
#if STITCH_WITH_CAD
  return cad::kCadUnits;
#else
  return "";
#endif
}

std::string_view describe(MemoryModel memory) {
  switch (memory) {
    case MemoryModel::streamed:
      return "written block by block as it is evaluated: memory does not grow with the resolution";
    case MemoryModel::whole:
      return "holds the whole tessellation and the file's buffer";
    case MemoryModel::patch_set:
      return "holds the patches of the hierarchy";
    case MemoryModel::cad_model:
      return "holds the patches and OpenCASCADE's model of the file";
  }
  return "";
}

void set_tolerance(OutputSpec& spec, const OutputFormat& format, double tolerance,
                   bool resolution_given) {
  if (!(tolerance > 0) || !std::isfinite(tolerance))
    throw UsageError(fmt::format("the tolerance must be a number > 0, not {}", tolerance));
  spec.patches.tolerance = tolerance;
  if (format.kind != OutputKind::tessellated) return;
  if (resolution_given)
    throw UsageError("a tolerance and a resolution exclude each other for a mesh output");
  if (!format.adaptive)
    throw UsageError(
        fmt::format("a tolerance asks a mesh output for adaptive triangles, which {} does not take",
                    format.name));
  spec.adaptive_tolerance = tolerance;
}

bool writes_uvs(const OutputFormat& format, const OutputSpec& spec) {
  return format.kind == OutputKind::tessellated && spec.adaptive_tolerance == 0 &&
         (format.uvs || (spec.unwelded && format.unwelded));
}

void check_output(const std::string& path, const OutputSpec& spec,
                  std::span<const OutputFormat> formats) {
  const OutputFormat& format = output_format(path, formats);
  const auto takers = [&](bool OutputFormat::*trait) {
    std::string out;
    for (const OutputFormat& f : formats)
      if (f.*trait)
        out += fmt::format("{}{} ({})", out.empty() ? "" : ", ", f.name, f.extensions[0]);
    return out;
  };
  if (spec.unwelded && !format.unwelded)
    throw UsageError(fmt::format("unwelded samples are written to {} only; '{}' is not",
                                 takers(&OutputFormat::unwelded), path));
  if (spec.adaptive_tolerance > 0 && !format.adaptive)
    throw UsageError(fmt::format("adaptive triangles are written to {} only, not '{}'",
                                 takers(&OutputFormat::adaptive), path));
  if (spec.adaptive_tolerance > 0 && spec.unwelded)
    throw UsageError("adaptive triangles are welded; they cannot be written unwelded");
  if (format.kind == OutputKind::exact) {
    for (const double t : {spec.patches.tolerance, spec.patches.angle_tolerance_deg})
      if (!(t > 0) || !std::isfinite(t))
        throw UsageError(
            fmt::format("the tolerances of '{}' must be numbers > 0 (got {})", path, t));
  }
  if (format.needs_cad) {
#if STITCH_WITH_CAD
    cad::check_units(spec.units);
#else
    throw OutputError(fmt::format(
        "cannot write '{}': this stitch was built without OpenCASCADE (STITCH_BUILD_CAD=OFF)",
        path));
#endif
  }
  check_output_path(path);
}

OutputReport write_surface(const std::string& path, const HalfedgeMesh& mesh,
                           const Surface& surface, const OutputSpec& spec,
                           std::span<const OutputFormat> formats) {
  check_output(path, spec, formats);
  const OutputFormat& format = output_format(path, formats);
  if (format.kind == OutputKind::exact && surface.method() == Method::cc)
    throw UsageError(fmt::format(
        "cannot write '{}': the {} surface is not a set of Bezier patches; use {} or {}", path,
        to_string(Method::cc), to_string(Method::mdc), to_string(Method::asc)));
  return format.write(path, mesh, surface, spec, format);
}

OutputReport write_surface(const std::string& path, const HalfedgeMesh& input,
                           const BuiltSurface& built, OutputSpec spec,
                           std::span<const OutputFormat> formats) {
  std::optional<ControlMesh> control;
  const OutputFormat* format = find_output_format(path, formats);
  if (built.refined && !spec.control && format && format->kind == OutputKind::exact) {
    control = control_mesh(input, *built.refined);
    spec.control = &*control;
  }
  return write_surface(path, built.mesh(input), built.surface, spec, formats);
}

bool output_streams(const OutputFormat& format, const OutputSpec& spec) {
  return format.kind == OutputKind::tessellated && format.memory == MemoryModel::streamed &&
         !spec.unwelded && spec.adaptive_tolerance == 0 &&
         !(spec.uvs && format.mesh_format && is_gltf(*format.mesh_format));
}

std::int64_t output_memory_estimate(const HalfedgeMesh& mesh, const OutputFormat& format,
                                    const OutputSpec& spec) {
  // Measured peak resident size of `stitch smooth` to binary PLY divided by the corners: 806
  // bytes at 100k and 1M faces (mesh, K-gons, 16-point nets, the input file's text); rounded up.
  constexpr std::int64_t kBytesPerCorner = 1024;
  const auto corners = static_cast<std::int64_t>(mesh.num_halfedges());
  const std::int64_t n = spec.resolution;
  std::int64_t bytes = kBytesPerCorner * corners;
  if (format.kind == OutputKind::exact || spec.adaptive_tolerance > 0) return bytes;
  if (output_streams(format, spec)) return bytes;
  if (spec.unwelded)  // positions, normals, uv, patch and level per sample, 4 ints per quad
    return bytes + corners * ((n + 1) * (n + 1) * 72 + n * n * 16);
  if (format.mesh_format && is_gltf(*format.mesh_format) && spec.uvs)
    // Split at seams over the whole tessellation (about n^2 vertices and quads per corner): the
    // welded one (48 bytes per vertex and a 4-byte chain head, 16 per quad), every patch's grid
    // of UVs (16 bytes per sample), the split copies (48 + 16 + 4 per vertex, 16 per quad).
    return bytes + corners * ((n + 1) * (n + 1) * 16 + n * n * (68 + 84));
  // The tessellation, then its buffer.
  return bytes + corners * n * n * (48 + 16) * 2;
}

}  // namespace stitch
