// stitch smooth IN -o OUT: the main job, from a mesh to its smooth surface, tessellated or exact,
// in the format the output's extension names (the library's table of output formats).
#include <fmt/format.h>

#include <fstream>
#include <memory>

#include "commands.hpp"
#include "options.hpp"
#include "stitch/analysis/surface_check.hpp"
#include "stitch/eval/uv_surface.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/mesh/limits.hpp"
#include "stitch/output/output.hpp"
#include "stitch/tess/adaptive.hpp"
#include "stitch/tess/tessellate.hpp"

namespace stitch::cli {

namespace {

struct SmoothArgs {
  InputOptions in;
  std::string out;
  std::string method{method_table().front().name};
  std::string uv;  ///< a UV mode, or none; empty: the first mode when the input has UVs
  std::string packing{face_packing_table().front().name};
  std::string patches;       ///< --patches: Bézier JSON besides the main output
  double max_memory_gb = 0;  ///< 0: the memory the machine has available
  bool check = false;        ///< check the written surface for folds and self-intersections
  OutputSpec spec;
  ProgressFlags progress;
  KgonCliOptions kgon;
};

/// The machine's available memory in bytes (MemAvailable), or 0 when it cannot be told.
std::int64_t available_memory() {
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  std::int64_t kilobytes = 0;
  std::string unit;
  while (meminfo >> key >> kilobytes >> unit)
    if (key == "MemAvailable:") return kilobytes * 1024;
  return 0;
}

void warn(const std::string& path, const std::string& what) {
  fmt::print(stderr, "stitch: warning: {}: {}\n", path, what);
}

/// --check: the triangles as written (as stitch check-surface would check the file, and knowing
/// the creases); a warning, not a failure: the file is what was asked for.
void warn_if_not_clean(StageReporter& stage, const SmoothArgs& a, const HalfedgeMesh& mesh,
                       const Surface& surface) {
  stage.begin("checking the surface");
  const bool adaptive = a.spec.adaptive_tolerance > 0;
  SurfaceCheckOptions options;
  options.progress = [&stage](double done) { stage.fraction(done); };
  std::string problems;
  if (adaptive) {
    // The same triangles as written (the writer does not keep them).
    const TriangleSoup tris =
        triangulate(tessellate_adaptive(mesh, surface, {a.spec.adaptive_tolerance}));
    const SurfaceCheckReport r = check_surface(tris, options);
    if (!r.clean()) problems = r.describe(tris);
  } else {
    // The tessellation as written, a region at a time, knowing the surface's creases.
    const SurfaceCheckReport r = check_surface(mesh, surface, a.spec.resolution, options);
    if (!r.clean()) problems = r.describe_quads();
  }
  stage.end();
  if (!problems.empty())
    warn(a.out, fmt::format("the surface is not clean at {}:\n{}",
                            adaptive ? fmt::format("tolerance {}", a.spec.adaptive_tolerance)
                                     : fmt::format("resolution {}", a.spec.resolution),
                            problems));
}

/// Refuses up front, with the estimate and the limit, a run that would not fit in memory.
void check_memory(const SmoothArgs& a, const HalfedgeMesh& mesh, const OutputFormat& format) {
  const std::int64_t limit =
      a.max_memory_gb > 0 ? static_cast<std::int64_t>(a.max_memory_gb * 1e9) : available_memory();
  const std::int64_t need = output_memory_estimate(mesh, format, a.spec);
  if (limit > 0 && need > limit)
    throw UsageError(fmt::format(
        "smoothing {} ({} corners) at resolution {}{} needs about {:.2f} GB of memory, more than "
        "the {:.2f} GB {}; {}",
        a.in.path, static_cast<int>(mesh.patch_corners().size()), a.spec.resolution,
        a.spec.unwelded ? " unwelded" : "", need / 1e9, limit / 1e9,
        a.max_memory_gb > 0 ? "allowed by --max-memory" : "available",
        output_streams(format, a.spec)
            ? "the mesh itself is too large for this machine"
            : fmt::format("write a welded {} (streamed){} or lower --resolution",
                          output_formats().front().extensions[0],
                          a.spec.uvs ? ", or without texture coordinates (--uv none)" : "")));
}

/// The UVs to write, or null with a warning saying why the input's are not written.
std::unique_ptr<UvSurface> uv_surface(const SmoothArgs& a, const HalfedgeMesh& mesh,
                                      const KgonOptions& kgons, const BuildReport& report,
                                      const OutputFormat& format, StageReporter& stage) {
  if (a.uv == "none") return nullptr;
  if (report.corner_uvs.empty()) {
    if (!a.uv.empty())
      warn(a.in.path, fmt::format("--uv {}: the input has no texture coordinates", a.uv));
    return nullptr;
  }
  std::string lost;
  if (format.kind == OutputKind::exact)
    lost = "the exact outputs have no place for texture coordinates";
  else if (a.spec.adaptive_tolerance > 0)
    lost = "--tolerance writes no texture coordinates";
  else if (!writes_uvs(format, a.spec))
    lost = fmt::format(
        "a welded {} has no place for UVs that differ across a seam (write {}, or --unwelded {})",
        format.extensions[0], output_extensions(OutputKind::tessellated), format.extensions[0]);
  else if (a.in.fill_holes && report.filled_holes > 0)
    lost = "the faces --fill-holes added have none";
  if (!lost.empty()) {
    warn(a.out, "the input's texture coordinates are not written: " + lost);
    return nullptr;
  }
  stage.begin("building the UV surface");
  auto uvs = std::make_unique<UvSurface>(
      mesh, report.corner_uvs, a.uv.empty() ? uv_mode_table().front().value : parse_uv_mode(a.uv),
      kgons);
  stage.end();
  for (const std::string& w : uvs->warnings()) warn(a.in.path, w);
  return uvs;
}

void run_smooth(SmoothArgs& a) {
  // Refuse a bad output request before any work, so nothing is computed for nothing.
  a.spec.packing = parse_choice(face_packing_table(), a.packing, "face packing");
  check_output(a.out, a.spec);
  const OutputFormat& format = output_format(a.out);
  OutputSpec patches_spec = a.spec;
  patches_spec.adaptive_tolerance = 0;
  if (!a.patches.empty()) {
    // The exact format written without OpenCASCADE: Bézier JSON.
    const OutputFormat* f = find_output_format(a.patches);
    if (!f || f->kind != OutputKind::exact || f->needs_cad)
      throw UsageError(
          fmt::format("--patches writes Bezier JSON; '{}' is not a Bezier JSON name", a.patches));
    check_output(a.patches, patches_spec);
  }

  StageReporter stage(a.progress);
  stage.begin("reading " + a.in.path);
  BuildReport report;
  const HalfedgeMesh mesh =
      load_input(a.in, &report, [&stage](double done) { stage.fraction(done); });
  stage.end();
  check_memory(a, mesh, format);
  const Method method = parse_method(a.method);
  stage.begin(fmt::format("building the {} surface ({} patches)", a.method,
                          static_cast<int>(mesh.patch_corners().size())));
  const BuiltSurface built =
      build_cli_surface(a.kgon, mesh, method, a.in.path, a.progress.quiet, &report.corner_uvs);
  stage.end();
  // Refined for semi-sharp tags, the surface's patches are the refined mesh's corners, and the
  // texture coordinates were refined with it.
  const HalfedgeMesh& surface_mesh = built.mesh(mesh);
  if (built.refined) {
    check_memory(a, surface_mesh, format);
    report.corner_uvs = built.refined->uvs;
  }
  const std::unique_ptr<UvSurface> uvs =
      uv_surface(a, surface_mesh, built.kgons, report, format, stage);
  a.spec.uvs = uvs.get();
  if (uvs) check_memory(a, surface_mesh, format);  // glTF holds a tessellation with UVs whole
  a.spec.progress = [&stage](double done) { stage.fraction(done); };
  a.spec.note = [&stage](const std::string& line) { stage.note(line); };
  if (!a.patches.empty()) {
    stage.begin("writing " + a.patches);
    patches_spec.note = a.spec.note;
    write_surface(a.patches, mesh, built, patches_spec);
    stage.end();
  }
  stage.begin(
      format.kind == OutputKind::exact ? "writing " + a.out
      : a.spec.adaptive_tolerance > 0
          ? fmt::format("tessellating to tolerance {} and writing {}", a.spec.adaptive_tolerance,
                        a.out)
          : fmt::format("tessellating at resolution {} and writing {}", a.spec.resolution, a.out));
  const OutputReport written = write_surface(a.out, mesh, built, a.spec);
  stage.end();
  if (a.check && format.kind == OutputKind::tessellated)
    warn_if_not_clean(stage, a, surface_mesh, built.surface);
  fmt::print("wrote {} ({})\n", a.out, written.summary);
}

/// --help's account of every output format and its memory model, from the table.
std::string formats_help() {
  std::string out = "Output formats, by extension (the memory each holds besides the mesh):\n";
  for (const OutputFormat& f : output_formats()) {
    std::string exts;
    for (std::string_view e : f.extensions)
      if (!e.empty()) exts += (exts.empty() ? "" : " ") + std::string(e);
    out += fmt::format("  {:<16} {}: {}; {}\n", exts, f.name, f.help, describe(f.memory));
  }
  return out;
}

}  // namespace

void add_smooth_command(CLI::App& app) {
  auto args = std::make_shared<SmoothArgs>();
  CLI::App* cmd = app.add_subcommand(
      "smooth",
      "Turn a mesh (closed or with boundaries) into its smooth surface: a tessellated polygon "
      "mesh, or the exact patches as Bezier JSON, STEP or IGES. Memory: the mesh and its "
      "surface, and what the format holds (below; the streamed ones do not grow with "
      "--resolution)");
  cmd->footer(formats_help());
  add_input_options(cmd, args->in);
  cmd->add_option(
         "-o,--output", args->out,
         fmt::format("output file; its extension names the format: {}", output_extensions()))
      ->required();
  add_method_option(cmd, args->method, false, &args->in);
  CLI::Option* resolution = cmd->add_option("--resolution", args->spec.resolution,
                                            "mesh outputs: segments per patch side")
                                ->check(CLI::Range(1, limits::max_resolution))
                                ->capture_default_str();
  cmd->add_flag("--unwelded", args->spec.unwelded,
                "every patch's own grid, with double x y z nx ny nz u v and int patch, to check "
                "continuity from the file alone");
  cmd->add_option(
         "--uv", args->uv,
         "the input's texture coordinates on the surface: " + choice_help(uv_mode_table()) +
             "; none. The first is the default when the input has them; written where "
             "the format has a place for them")
      ->check(CLI::IsMember([] {
        std::vector<std::string> names;
        for (const Choice<UvMode>& c : uv_mode_table()) names.emplace_back(c.name);
        names.emplace_back("none");
        return names;
      }()));
  cmd->add_flag("--ascii", args->spec.ascii, "write binary PLY as text instead");
  cmd->add_flag("--float", args->spec.single_precision,
                "write PLY positions and normals as 32-bit floats (half the size; the default "
                "doubles read back exactly)");
  cmd->add_option("--max-memory", args->max_memory_gb,
                  "refuse up front a run estimated to need more memory than this many GB "
                  "(default: the memory available)")
      ->check(CLI::Range(0.0, 1e6));
  cmd->add_flag(
      "--check", args->check,
      "after writing a mesh, check the surface at the written resolution or tolerance for "
      "folded, self-intersecting and degenerate triangles (as stitch check-surface does, but "
      "knowing the mesh's infinitely sharp creases and cone points, where triangles may meet at "
      "any angle) and warn on stderr; the exit status stays 0. In bounded memory: the patches "
      "are evaluated again a region of space at a time");
  add_kgon_options(cmd, args->kgon, &args->in);
  // One --tolerance, relative to the model size, for both kinds of output: for a mesh output it
  // asks for adaptive triangles instead of a fixed resolution.
  CLI::Option* tolerance = cmd->add_option(
      "--tolerance", args->spec.patches.tolerance,
      fmt::format("exact outputs: largest distance of the innermost cells at extraordinary points "
                  "from the exact surface, relative to the model size (> 0, default {:g}); mesh "
                  "outputs: adaptive triangles instead of --resolution, segments per patch side "
                  "from the control nets' flatness (try 1e-3)",
                  PatchSetOptions{}.tolerance));
  cmd->add_option("--angle-tolerance", args->spec.patches.angle_tolerance_deg,
                  fmt::format("exact outputs: largest angle between faces along a shared edge, "
                              "degrees: those cells' normals within half of it of the surface's "
                              "(> 0, default {:g})",
                              PatchSetOptions{}.angle_tolerance_deg));
  cmd->add_option("--faces", args->packing, "STEP and IGES: " + choice_help(face_packing_table()))
      ->check(choice_validator(face_packing_table()))
      ->capture_default_str();
  cmd->add_option(
         "--units", args->spec.units,
         "STEP and IGES: the length unit declared (coordinates are not scaled): " + output_units())
      ->capture_default_str();
  cmd->add_flag("--kgons", args->spec.kgons, "Bezier JSON: add every K-gon");
  cmd->add_option("--patches", args->patches,
                  "also write the Bezier patches as JSON (docs/formats.md) to this file");
  add_progress_option(cmd, args->progress);
  cmd->callback([args, resolution, tolerance] {
    if (tolerance->count() > 0)
      set_tolerance(args->spec, output_format(args->out), args->spec.patches.tolerance,
                    resolution->count() > 0);
    run_smooth(*args);
  });
}

}  // namespace stitch::cli
