// stitch smooth IN -o OUT: the main job, from a mesh to its tessellated smooth surface.
#include <fmt/format.h>

#include <fstream>
#include <memory>

#include "commands.hpp"
#include "exact_output.hpp"
#include "options.hpp"
#include "stitch/analysis/surface_check.hpp"
#include "stitch/eval/uv_surface.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/mesh/limits.hpp"
#include "stitch/tess/adaptive.hpp"
#include "stitch/tess/export.hpp"
#include "stitch/tess/tessellate.hpp"

namespace stitch::cli {

namespace {

struct SmoothArgs {
  InputOptions in;
  std::string out;
  std::string method = "mdc";
  int resolution = 8;
  /// --tolerance (ExactOutputOptions::tolerance) given for a mesh output: adaptive triangles.
  bool adaptive = false;
  bool unwelded = false;
  bool ascii = false;
  bool single_precision = false;
  std::string uv;            ///< smooth, linear or none; empty: smooth when the input has UVs
  double max_memory_gb = 0;  ///< 0: the memory the machine has available
  bool check = false;        ///< check the written surface for folds and self-intersections
  ProgressFlags progress;
  KgonCliOptions kgon;
  ExactOutputOptions exact;
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

/// --check: the triangles as written, checked whole (as stitch check-surface would check the
/// file); a warning, not a failure: the file is what was asked for. `at` names the tessellation.
void warn_if_not_clean(StageReporter& stage, const std::string& out, const TriangleSoup& tris,
                       const std::string& at) {
  stage.begin("checking the surface");
  const SurfaceCheckReport r = check_surface(tris);
  stage.end();
  if (!r.clean())
    fmt::print(stderr, "stitch: warning: {}: the surface is not clean at {}:\n{}\n", out, at,
               r.describe(tris));
}

/// Refuses up front, with the estimate and the limit, a run that would not fit in memory.
void check_memory(const SmoothArgs& a, const HalfedgeMesh& mesh) {
  const std::int64_t limit =
      a.max_memory_gb > 0 ? static_cast<std::int64_t>(a.max_memory_gb * 1e9) : available_memory();
  const std::int64_t need = smooth_memory_estimate(mesh, a.resolution, !a.unwelded, a.out);
  if (limit > 0 && need > limit)
    throw UsageError(fmt::format(
        "smoothing {} ({} corners) at resolution {}{} needs about {:.2f} GB of memory, more than "
        "the {:.2f} GB {}; {}",
        a.in.path, static_cast<int>(mesh.patch_corners().size()), a.resolution,
        a.unwelded ? " unwelded" : "", need / 1e9, limit / 1e9,
        a.max_memory_gb > 0 ? "allowed by --max-memory" : "available",
        a.unwelded || file_extension(a.out) == ".stl"
            ? "write a welded .ply (streamed) or lower --resolution"
            : "the mesh itself is too large for this machine"));
}

void warn(const std::string& path, const std::string& what) {
  fmt::print(stderr, "stitch: warning: {}: {}\n", path, what);
}

/// The UVs to write, or null with a warning saying why the input's are not written.
std::unique_ptr<UvSurface> uv_surface(const SmoothArgs& a, const HalfedgeMesh& mesh,
                                      const KgonOptions& kgons, const BuildReport& report,
                                      StageReporter& stage) {
  if (a.uv == "none") return nullptr;
  if (report.corner_uvs.empty()) {
    if (!a.uv.empty())
      warn(a.in.path, fmt::format("--uv {}: the input has no texture coordinates", a.uv));
    return nullptr;
  }
  const char* lost = nullptr;
  if (is_exact_output(a.out))
    lost = "the exact outputs have no place for texture coordinates";
  else if (!a.unwelded && !surface_file_takes_uvs(a.out))
    lost =
        "a welded .ply, .off or .stl has no place for UVs that differ across a seam (write .obj, "
        ".glb or .gltf, or --unwelded .ply)";
  else if (a.adaptive)
    lost = "--tolerance writes no texture coordinates";
  else if (a.in.fill_holes && report.filled_holes > 0)
    lost = "the faces --fill-holes added have none";
  if (lost) {
    warn(a.out, fmt::format("the input's texture coordinates are not written: {}", lost));
    return nullptr;
  }
  stage.begin("building the UV surface");
  auto uvs = std::make_unique<UvSurface>(mesh, report.corner_uvs,
                                         parse_uv_mode(a.uv.empty() ? "smooth" : a.uv), kgons);
  stage.end();
  for (const std::string& w : uvs->warnings()) warn(a.in.path, w);
  return uvs;
}

void run_smooth(const SmoothArgs& a) {
  // Refuse a bad output name before any work, so nothing is computed for nothing.
  const std::string ext = file_extension(a.out);
  if (a.unwelded && ext != ".ply")
    throw UsageError(
        fmt::format("--unwelded writes PLY (per-sample attributes); '{}' is not .ply", a.out));
  if (!a.unwelded && ext != ".obj" && ext != ".ply" && ext != ".off" && ext != ".stl" &&
      ext != ".glb" && ext != ".gltf" && !is_exact_output(a.out))
    throw UsageError(fmt::format("cannot tell the output format of '{}': use {}", a.out,
                                 smooth_output_extensions()));
  check_exact_outputs(a.out, a.exact);
  if (a.adaptive && (a.unwelded || ext == ".glb" || ext == ".gltf"))
    throw UsageError(fmt::format("--tolerance writes .obj, .ply, .off or .stl, not '{}'{}", a.out,
                                 a.unwelded ? " --unwelded" : ""));

  StageReporter stage(a.progress);
  stage.begin("reading " + a.in.path);
  BuildReport report;
  const HalfedgeMesh mesh =
      load_input(a.in, &report, [&stage](double done) { stage.fraction(done); });
  stage.end();
  check_memory(a, mesh);
  stage.begin(fmt::format("building the {} surface ({} patches)", a.method,
                          static_cast<int>(mesh.patch_corners().size())));
  const Method method = parse_method(a.method);
  const KgonOptions kgons = surface_kgon_options(a.kgon, mesh, method, a.in.path, a.progress.quiet);
  const Surface surface(mesh, method, kgons);
  stage.end();
  const std::unique_ptr<UvSurface> uvs = uv_surface(a, mesh, kgons, report, stage);
  if (const std::string exact = write_exact_outputs(a.out, mesh, surface, a.exact, stage);
      !exact.empty()) {
    fmt::print("wrote {} ({}, method {})\n", a.out, exact, a.method);
    return;
  }
  if (a.adaptive) {
    stage.begin(fmt::format("tessellating to tolerance {}", a.exact.tolerance));
    const AdaptiveMesh adaptive = tessellate_adaptive(mesh, surface, {a.exact.tolerance});
    stage.end();
    stage.begin("writing " + a.out);
    SurfaceFileOptions file;
    file.ascii_ply = a.ascii;
    file.single_precision = a.single_precision;
    write_adaptive_mesh(a.out, adaptive, file);
    stage.end();
    if (a.check)
      warn_if_not_clean(stage, a.out, triangulate(adaptive),
                        fmt::format("tolerance {}", a.exact.tolerance));
    fmt::print(
        "wrote {} ({} vertices, {} triangles, method {}, tolerance {}: {} to {} segments per "
        "patch side)\n",
        a.out, adaptive.num_vertices(), adaptive.triangles.size(), a.method, a.exact.tolerance,
        adaptive.min_rate, adaptive.max_rate);
    return;
  }
  SurfaceFileCounts written;
  if (a.unwelded) {
    stage.begin(fmt::format("tessellating at resolution {}", a.resolution));
    const TessellatedMesh samples = tessellate(mesh, surface, {a.resolution, false});
    stage.end();
    stage.begin("writing " + a.out);
    write_surface_samples_ply(a.out, samples, uvs.get());
    written = {samples.num_vertices(), static_cast<std::int64_t>(samples.quads.size()),
               uvs ? samples.num_vertices() : 0};
  } else {
    // Evaluated block by block as it is written: the tessellation is never held whole.
    stage.begin(fmt::format("tessellating at resolution {} and writing {}", a.resolution, a.out));
    SurfaceFileOptions file;
    file.ascii_ply = a.ascii;
    file.single_precision = a.single_precision;
    file.progress = [&stage](double done) { stage.fraction(done); };
    file.uvs = uvs.get();
    written = write_smooth_surface(a.out, mesh, surface, a.resolution, file);
  }
  stage.end();
  if (a.check) {
    // The same tessellation as written (the streamed writer does not keep it).
    warn_if_not_clean(stage, a.out,
                      triangulate(tessellate(mesh, surface, {a.resolution, true, false})),
                      fmt::format("resolution {}", a.resolution));
  }
  fmt::print("wrote {} ({} vertices, {} quads, {} {}, method {}, resolution {}{})\n", a.out,
             written.vertices, written.quads, static_cast<int>(mesh.patch_corners().size()),
             a.method == "cc" ? "sub-patches" : "bicubic patches", a.method, a.resolution,
             written.texcoords > 0 ? fmt::format(", {} texture coordinates ({} UVs)",
                                                 written.texcoords, to_string(uvs->mode()))
                                   : std::string());
}

}  // namespace

void add_smooth_command(CLI::App& app) {
  auto args = std::make_shared<SmoothArgs>();
  CLI::App* cmd = app.add_subcommand(
      "smooth", "Turn a closed mesh into its smooth surface, tessellated as a polygon mesh");
  add_input_options(cmd, args->in);
  cmd->add_option("-o,--output", args->out,
                  "output mesh: .obj, .ply (binary; the fastest and smallest, best for large "
                  "meshes), .off, .stl, .glb or .gltf (+ .bin); or the exact patches: .json "
                  "(Bezier JSON), .step/.stp or .igs/.iges (B-spline faces)")
      ->required();
  add_method_option(cmd, args->method, false, &args->in);
  CLI::Option* resolution =
      cmd->add_option("--resolution", args->resolution, "segments per patch side")
          ->check(CLI::Range(1, limits::max_resolution))
          ->capture_default_str();
  cmd->add_flag("--unwelded", args->unwelded,
                "write every patch's own grid as binary PLY with double x y z nx ny nz u v and "
                "int patch, to check continuity from the file alone");
  cmd->add_option("--uv", args->uv,
                  "the input's texture coordinates on the surface: smooth (the default when the "
                  "input has them: the UV layout smoothed like the mesh, seams kept), linear "
                  "(bilinear per patch) or none. Written to .obj, .glb/.gltf and --unwelded .ply")
      ->check(CLI::IsMember({"smooth", "linear", "none"}));
  cmd->add_flag("--ascii", args->ascii, "write .ply as text instead of binary");
  cmd->add_flag("--float", args->single_precision,
                "write .ply positions and normals as 32-bit floats (half the size; the default "
                "doubles read back exactly)");
  cmd->add_option("--max-memory", args->max_memory_gb,
                  "refuse up front a run estimated to need more memory than this many GB "
                  "(default: the memory available)")
      ->check(CLI::Range(0.0, 1e6));
  cmd->add_flag(
      "--check", args->check,
      "after writing, check the surface at the written resolution or tolerance for folded, "
      "self-intersecting and degenerate triangles (as stitch check-surface does) and "
      "warn on stderr; the exit status stays 0");
  add_kgon_options(cmd, args->kgon, &args->in);
  add_exact_output_options(cmd, args->exact);
  add_progress_option(cmd, args->progress);
  // One --tolerance, relative to the model size, for both kinds of output: for a mesh output it
  // asks for adaptive triangles instead of a fixed resolution.
  CLI::Option* tolerance = cmd->get_option("--tolerance");
  tolerance->description(tolerance->get_description() +
                         "; for .obj/.ply/.off/.stl: adaptive triangles instead of --resolution, "
                         "segments per patch side from the control nets' flatness (try 1e-3)");
  cmd->callback([args, resolution, tolerance] {
    args->adaptive = tolerance->count() > 0 && !is_exact_output(args->out);
    if (args->adaptive && resolution->count() > 0)
      throw UsageError("--tolerance and --resolution exclude each other for a mesh output");
    run_smooth(*args);
  });
}

}  // namespace stitch::cli
