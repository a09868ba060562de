// stitch smooth IN -o OUT: the main job, from a mesh to its tessellated smooth surface.
#include <fmt/format.h>

#include <memory>

#include "commands.hpp"
#include "options.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/tess/export.hpp"
#include "stitch/tess/tessellate.hpp"

namespace stitch::cli {

namespace {

struct SmoothArgs {
  InputOptions in;
  std::string out;
  std::string method = "mdc";
  int resolution = 8;
  bool unwelded = false;
  bool progress = false;
  KgonCliOptions kgon;
};

void run_smooth(const SmoothArgs& a) {
  // Refuse a bad output name before any work, so nothing is computed for nothing.
  const std::string ext = file_extension(a.out);
  if (a.unwelded && ext != ".ply")
    throw MeshError(
        fmt::format("--unwelded writes PLY (per-sample attributes); '{}' is not .ply", a.out));
  if (!a.unwelded && ext != ".obj" && ext != ".ply" && ext != ".off" && ext != ".stl")
    throw MeshError(
        fmt::format("cannot tell the output format of '{}': use .obj, .ply, .off or .stl", a.out));

  StageReporter stage(a.progress || stderr_is_terminal());
  stage.begin("reading " + a.in.path);
  const HalfedgeMesh mesh = load_input(a.in);
  stage.end();
  stage.begin(fmt::format("building the {} surface ({} patches)", a.method, mesh.num_halfedges()));
  const Surface surface(mesh, parse_method(a.method), to_kgon_options(a.kgon));
  stage.end();
  stage.begin(fmt::format("tessellating at resolution {}", a.resolution));
  const SurfaceMesh result = tessellate(mesh, surface, {a.resolution, !a.unwelded});
  stage.end();
  stage.begin("writing " + a.out);
  if (a.unwelded)
    write_surface_samples_ply(a.out, result);
  else
    write_surface_mesh(a.out, result);
  stage.end();
  fmt::print("wrote {} ({} vertices, {} quads, {} {}, method {}, resolution {})\n", a.out,
             result.num_vertices(), result.quads.size(), mesh.num_halfedges(),
             a.method == "cc" ? "sub-patches" : "bicubic patches", a.method, a.resolution);
}

}  // namespace

void add_smooth_command(CLI::App& app) {
  auto args = std::make_shared<SmoothArgs>();
  CLI::App* cmd = app.add_subcommand(
      "smooth", "Turn a closed mesh into its smooth surface, tessellated as a polygon mesh");
  add_input_options(cmd, args->in);
  cmd->add_option("-o,--output", args->out, "output mesh: .obj, .ply, .off or .stl")->required();
  add_method_option(cmd, args->method);
  cmd->add_option("--resolution", args->resolution, "segments per patch side")
      ->check(CLI::Range(1, 1024))
      ->capture_default_str();
  cmd->add_flag("--unwelded", args->unwelded,
                "write every patch's own grid as binary PLY with double x y z nx ny nz u v and "
                "int patch, to check continuity from the file alone");
  add_kgon_options(cmd, args->kgon);
  add_progress_option(cmd, args->progress);
  cmd->callback([args] { run_smooth(*args); });
}

}  // namespace stitch::cli
