// stitch render IN -o OUT.png: a picture of the smooth surface (or the input mesh) with
// overlays, headless through EGL.
#include <fmt/format.h>

#include <memory>
#include <optional>

#include "commands.hpp"
#include "options.hpp"
#include "stitch/error.hpp"
#include "stitch/eval/uv_surface.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/mesh/limits.hpp"
#include "stitch/render/gl_context.hpp"
#include "stitch/render/image.hpp"
#include "stitch/render/options.hpp"
#include "stitch/render/scene.hpp"
#include "stitch/tess/tessellate.hpp"

namespace stitch::cli {

namespace {

struct RenderArgs {
  InputOptions in;
  std::string out;
  std::string method{method_table().front().name};
  std::string mode{shading_mode_table().front().name};
  std::string show;
  std::string size = "800x600";
  std::string view;
  std::string up{up_axis_table().front().name};
  std::string eye, target;
  bool focus_ev = false;
  double zoom = 0.6;
  int resolution = kDefaultResolution;
  int stripes = 24;
  int checks = 8;
  std::string uv;  ///< with --mode checker: smooth (when empty) or linear
  std::string draw = "smooth";
  ProgressFlags progress;
  KgonCliOptions kgon;
};

void run_render(const RenderArgs& a) {
  // Every option is checked before any work, so a bad one costs nothing and writes nothing.
  if (file_extension(a.out) != kImageExtension) {
    throw UsageError(fmt::format("the output '{}' must be a {} file", a.out, kImageExtension));
  }
  const ImageSize size = parse_image_size(a.size);
  RenderStyle style;
  style.mode = parse_shading_mode(a.mode);
  style.stripes = a.stripes;
  style.checks = a.checks;
  const bool checker = style.mode == ShadingMode::checker;
  if (!a.uv.empty() && !checker)
    throw UsageError(fmt::format("--uv needs --mode {}", to_string(ShadingMode::checker)));
  const UvMode uv_mode = parse_uv_mode(a.uv.empty() ? "smooth" : a.uv);
  parse_overlays(a.show, style);
  style.draw_surface = a.draw != "none";
  const int camera_choices =
      (!a.view.empty() ? 1 : 0) + (!a.eye.empty() ? 1 : 0) + (a.focus_ev ? 1 : 0);
  if (camera_choices > 1) {
    throw UsageError("choose one camera: --view, --eye/--target or --focus-ev");
  }
  if (!a.target.empty() && a.eye.empty()) {
    throw UsageError("--target needs --eye");
  }
  const View view = parse_view(a.view.empty() ? "iso" : a.view);
  const UpAxis up = parse_choice(up_axis_table(), a.up, "up axis");
  const std::optional<Vec3> eye =
      a.eye.empty() ? std::nullopt : std::optional(parse_point(a.eye, "--eye"));
  const std::optional<Vec3> target =
      a.target.empty() ? std::nullopt : std::optional(parse_point(a.target, "--target"));
  if (eye) limits::check_coordinates(*eye, "--eye");
  if (target) limits::check_coordinates(*target, "--target");

  StageReporter stage(a.progress);
  stage.begin("reading " + a.in.path);
  BuildReport report;
  const HalfedgeMesh mesh = load_input(a.in, &report);
  stage.end();
  if (checker && report.corner_uvs.empty()) {
    throw UsageError(fmt::format("--mode {} needs texture coordinates: {} has none",
                                 to_string(ShadingMode::checker), a.in.path));
  }
  stage.begin(fmt::format("building the {} surface", a.method));
  const Method method = parse_method(a.method);
  const BuiltSurface built =
      build_cli_surface(a.kgon, mesh, method, a.in.path, a.progress.quiet, &report.corner_uvs);
  const Surface& surface = built.surface;
  const KgonOptions& kgons = built.kgons;
  // Refined for semi-sharp tags, the surface (and the control mesh drawn over it) is the
  // refined mesh's, and so are the texture coordinates.
  const HalfedgeMesh& surface_mesh = built.mesh(mesh);
  const CornerUvs& corner_uvs = built.refined ? built.refined->uvs : report.corner_uvs;
  // The tessellation is never held: passed over here for the bounds, then drawn block by block.
  SceneGeometry scene =
      build_scene(surface_mesh, surface, a.resolution, style.overlays, SceneSurface::blocks);
  stage.end();
  std::optional<UvSurface> uvs;
  if (checker) {
    stage.begin("building the texture coordinates' surface");
    uvs.emplace(surface_mesh, corner_uvs, uv_mode, kgons);
    add_texcoords(scene, surface_mesh, corner_uvs, *uvs);
    stage.end();
    for (const std::string& w : uvs->warnings())
      fmt::print(stderr, "stitch: warning: {}: {}\n", a.in.path, w);
  }

  const double aspect = static_cast<double>(size.width) / size.height;
  Camera camera;
  if (a.focus_ev) {
    camera = focus_camera(highest_valence_point(scene.extraordinary), scene, aspect, a.zoom, up);
  } else if (eye) {
    camera = look_at(*eye, target.value_or(scene.bounds.center()), scene.bounds, up);
  } else {
    camera = frame_view(view, scene.bounds, aspect, up);
  }

  stage.begin(fmt::format("tessellating and rendering {}x{}", size.width, size.height));
  const OffscreenContext context;
  Renderer renderer;
  if (a.draw == "input") scene.input = input_faces(surface_mesh);
  upload_scene(renderer, scene, a.draw == "input");
  SurfaceBlocks blocks = surface_blocks(surface_mesh, surface, a.resolution, uvs ? &*uvs : nullptr,
                                        0, [&stage](double done) { stage.fraction(done); });
  blocks.shaded = a.draw == "smooth";
  const Image image = render_image(renderer, camera, style, size.width, size.height, {}, &blocks);
  stage.end();
  write_png(a.out, image);
  fmt::print("wrote {} ({}x{}, method {}, mode {}, {})\n", a.out, size.width, size.height, a.method,
             a.mode,
             a.focus_ev ? "focus on the extraordinary point of highest valence"
             : eye      ? "eye/target"
                        : "view " + to_string(view));
}

}  // namespace

void add_render_command(CLI::App& app) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* cmd = app.add_subcommand(
      "render",
      "Render the smooth surface to a PNG (headless): shading, zebra stripes, "
      "isophotes, levels, patches, a checker through the texture coordinates, with the mesh, "
      "K-gons, nets and extraordinary points. Memory: the mesh and its surface; the tessellation "
      "is evaluated and drawn a block of patches at a time, so it does not grow with "
      "--resolution");
  add_input_options(cmd, args->in);
  cmd->add_option("-o,--output", args->out,
                  fmt::format("output image ({}), written atomically", kImageExtension))
      ->required();
  add_method_option(cmd, args->method, false, &args->in);
  cmd->add_option("--mode", args->mode, choice_help(shading_mode_table()))
      ->check(choice_validator(shading_mode_table()))
      ->capture_default_str();
  cmd->add_option("--show", args->show,
                  "overlays, comma-separated: mesh (input wireframe), kgons, nets (4x4 control "
                  "nets), ev (extraordinary points), tess (the tessellation's quads)");
  cmd->add_option("--size", args->size, "image size WxH")->capture_default_str();
  cmd->add_option("--view", args->view,
                  "front, back, left, right, top, bottom or iso (default), framing the model");
  cmd->add_option("--eye", args->eye,
                  "camera position x,y,z (with --target); the --up axis is up in the image");
  cmd->add_option("--up", args->up,
                  "the world axis up in the image: " + choice_help(up_axis_table()))
      ->check(choice_validator(up_axis_table()))
      ->capture_default_str();
  cmd->add_option("--target", args->target,
                  "point looked at, x,y,z (default: the centre of the model)");
  cmd->add_flag("--focus-ev", args->focus_ev,
                "close-up of the extraordinary point of highest valence, seen along its normal "
                "tilted by 30 degrees");
  cmd->add_option("--zoom", args->zoom,
                  "with --focus-ev: radius of the region shown around the point, in patch sizes")
      ->check(finite_range(kMinZoom, kMaxZoom))
      ->capture_default_str();
  cmd->add_option("--resolution", args->resolution, "segments per patch side")
      ->check(CLI::Range(1, limits::max_resolution))
      ->capture_default_str();
  cmd->add_option("--stripes", args->stripes,
                  "zebra stripes around the full circle of reflected directions, or isophote "
                  "bands from 0 to 180 degrees")
      ->check(CLI::Range(2, 512))
      ->capture_default_str();
  cmd->add_option("--checks", args->checks,
                  "with --mode " + to_string(ShadingMode::checker) +
                      ": squares along each side of the texture's unit square")
      ->check(CLI::Range(1, 4096))
      ->capture_default_str();
  cmd->add_option("--uv", args->uv,
                  "with --mode " + to_string(ShadingMode::checker) +
                      ": smooth (default: the UV layout smoothed like the mesh, "
                      "seams kept) or linear (bilinear per patch)")
      ->check(CLI::IsMember({"smooth", "linear"}));
  cmd->add_option("--draw", args->draw,
                  "what is shaded: smooth (the surface), input (the input polygons, flat) or "
                  "none (overlays only)")
      ->check(CLI::IsMember({"smooth", "input", "none"}))
      ->capture_default_str();
  add_kgon_options(cmd, args->kgon, &args->in);
  add_progress_option(cmd, args->progress);
  cmd->callback([args] { run_render(*args); });
}

}  // namespace stitch::cli
