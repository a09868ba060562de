#include "options.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <map>

#include "stitch/mesh/formats.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/mesh/limits.hpp"
#include "stitch/mesh/validate.hpp"
#include "stitch/project/kgon_controls.hpp"
#include "stitch/project/project_file.hpp"

namespace stitch::cli {

void add_input_options(CLI::App* cmd, InputOptions& in) {
  cmd->add_option("IN", in.path,
                  fmt::format("input mesh ({}), closed or with boundaries (repaired on reading "
                              "unless --strict); or a stitch-modeler project ({}): its mesh, "
                              "K-gon controls and method",
                              extension_list(kMeshReadExtensions), kProjectExtensions.front()))
      ->required();
  cmd->add_flag("--fill-holes", in.fill_holes,
                "close every boundary loop with one face instead of keeping it as a boundary");
  cmd->add_flag("--strict", in.strict,
                "refuse a mesh that is not an oriented manifold as it is, listing its defects, "
                "instead of repairing it (mixed winding, non-manifold edges and vertices, "
                "repeated vertices, degenerate and duplicate faces)");
}

HalfedgeMesh load_input(const InputOptions& in, BuildReport* report_out,
                        const std::function<void(double)>& progress) {
  BuildOptions opt;
  opt.fill_holes = in.fill_holes;
  opt.repair = !in.strict;
  // The topology operators make 2-sided faces, and edited meshes must read back; they are
  // smoothed with a warning (see docs/method.md).
  opt.allow_two_gons = true;
  BuildReport local;
  BuildReport& report = report_out ? *report_out : local;
  std::vector<std::string> warnings;
  HalfedgeMesh mesh;
  if (is_project_path(in.path)) {
    ProjectFile project = read_project_file(in.path, opt, &report);
    mesh = std::move(project.mesh);
    if (in.kgon) {
      in.kgon->from_input = std::move(project.kgons);
      in.kgon->input_has_global = true;
    }
    if (in.method && project.method && !(in.method_option && in.method_option->count() > 0))
      *in.method = to_string(*project.method);
  } else {
    mesh = read_mesh(in.path, opt, &report, &warnings, progress);
  }
  if (in.kgon && !in.kgon->controls_path.empty())
    read_kgon_controls(in.kgon->controls_path, mesh, in.kgon->from_input);
  warnings.insert(warnings.end(), report.warnings.begin(), report.warnings.end());
  for (Vertex v : mesh.vertices())
    if (mesh.valence(v) == 2 && vertex_kind(mesh, v, KgonOptions{}) == VertexKind::smooth)
      warnings.push_back(fmt::format(
          "vertex {} has valence 2: its K-gon is a 2-gon with no plane; the surface there is "
          "finite but its normal is taken from the faces around it",
          v.idx + 1));
  for (Face f : mesh.surface_faces())
    if (mesh.degree(f) == 2)
      warnings.push_back(fmt::format(
          "face {} has 2 sides: its K-gon has no plane; the normal there comes from the faces "
          "around it",
          f.idx + 1));
  for (const std::string& w : warnings) fmt::print(stderr, "stitch: warning: {}: {}\n", in.path, w);
  return mesh;
}

CLI::Validator finite_range(double lo, double hi) {
  return CLI::Validator(
      [lo, hi](const std::string& text) -> std::string {
        double value = 0;
        if (!CLI::detail::lexical_cast(text, value))
          return fmt::format("'{}' is not a number", limits::quoted(text));
        if (!(value >= lo && value <= hi))
          return fmt::format("{} is not a finite number from {:g} to {:g}", limits::quoted(text),
                             lo, hi);
        return {};
      },
      fmt::format("NUMBER in [{:g}, {:g}]", lo, hi));
}

void add_kgon_options(CLI::App* cmd, KgonCliOptions& k, InputOptions* in) {
  if (in) in->kgon = &k;
  k.scale_option =
      cmd->add_option(
             "--kgon-scale", k.scale,
             fmt::format("scale every K-gon with K != 4 about its centroid (default 1, from "
                         "{:g} to {:g})",
                         limits::min_kgon_scale, limits::max_kgon_scale))
          ->check(finite_range(limits::min_kgon_scale, limits::max_kgon_scale));
  k.rotate_option =
      cmd->add_option(
             "--kgon-rotate", k.rotate_deg,
             fmt::format("rotate every K-gon with K != 4 in its plane, degrees (default 0, "
                         "at most {:g} either way)",
                         limits::max_rotation_deg))
          ->check(finite_range(-limits::max_rotation_deg, limits::max_rotation_deg));
  k.regularize_option =
      cmd->add_flag("--regularize", k.regularize,
                    "replace every K-gon with K != 4 by its best-fitting affinely regular polygon "
                    "(makes star-shaped K-gons convex)");
  cmd->add_option("--kgon-controls", k.controls_path,
                  fmt::format("a JSON file of per-element K-gon controls (face, vertex or edge: "
                              "{}; docs/modeler.md); they replace those of a project ({}) input "
                              "for the same elements",
                              kgon_control_field_names(), kProjectExtensions.front()));
  cmd->add_option("--kgon-construction", k.construction, choice_help(kgon_construction_table()))
      ->check(choice_validator(kgon_construction_table()))
      ->capture_default_str();
  cmd->add_flag_callback(
      "--no-unfold-tubes", [&k] { k.unfold_tubes = false; },
      "keep the fitted K-gons of every tube made by inserting an edge between "
      "two faces; by default, where that surface folds, the face's and the "
      "bridge's K-gon controls are chosen by a search that checks the surface "
      "(docs/method.md)");
  cmd->add_option("--boundary", k.boundary, choice_help(boundary_table()))
      ->check(choice_validator(boundary_table()))
      ->capture_default_str();
  k.sharp_from_option =
      cmd->add_option(
             "--sharp-from", k.sharp_from,
             fmt::format(
                 "round semi-sharp crease and corner tags (0 < sharpness < 10) for {} and {}: "
                 "those of at least this sharpness infinitely sharp, smaller ones smooth. "
                 "Without it they are honoured as "
                 "OpenSubdiv means them, by refining the mesh ceil(sharpness) levels, from {} to "
                 "{}, before the patches (docs/method.md); {} honours them itself",
                 to_string(Method::mdc), to_string(Method::asc), min_semi_sharp_levels,
                 max_semi_sharp_levels, to_string(Method::cc)))
          ->check(finite_range(0, 10));
}

KgonOptions to_kgon_options(const KgonCliOptions& k) {
  KgonOptions o = k.from_input;
  // Without a project the flags are the global control; with one, each flag given replaces
  // the project's value and the rest stay as the modeler left them.
  auto use_flag = [&](const CLI::Option* flag) {
    return !k.input_has_global || (flag != nullptr && flag->count() > 0);
  };
  if (use_flag(k.scale_option)) o.global.scale = k.scale;
  if (use_flag(k.rotate_option)) o.global.rotate_deg = k.rotate_deg;
  if (use_flag(k.regularize_option)) o.global.regularize = k.regularize;
  o.construction = parse_choice(kgon_construction_table(), k.construction, "K-gon construction");
  o.sharp_from = k.sharp_from;
  o.boundary = parse_choice(boundary_table(), k.boundary, "boundary rule");
  return o;
}

SurfaceSpec surface_spec(const KgonCliOptions& k, Method method) {
  const bool rounded = k.sharp_from_option != nullptr && k.sharp_from_option->count() > 0;
  return {method, to_kgon_options(k), k.unfold_tubes,
          rounded ? SemiSharp::round : SemiSharp::refine};
}

BuiltSurface build_cli_surface(const KgonCliOptions& k, const HalfedgeMesh& mesh, Method method,
                               const std::string& where, bool quiet, const CornerUvs* uvs) {
  SurfaceSpec spec = surface_spec(k, method);
  spec.uvs = uvs;
  BuiltSurface built = build_surface(mesh, spec);
  report_unfolded_tubes(built.tubes, built.mesh(mesh), where, quiet);
  // The method named: analyze and compare build several surfaces.
  if (!quiet && built.refinement.levels > 0)
    fmt::print(stderr, "stitch: note: {}: {} (method {}); --sharp-from rounds them instead\n",
               where, built.refinement.summary(), to_string(method));
  return built;
}

void report_unfolded_tubes(const std::vector<TubeUnfolding>& tubes, const HalfedgeMesh& mesh,
                           const std::string& where, bool quiet) {
  for (const TubeUnfolding& t : tubes) {
    if (!t.unfolded())
      fmt::print(stderr, "stitch: warning: {}: {}; see docs/method.md, \"Tubes that still fold\"\n",
                 where, describe(mesh, t));
    else if (!quiet)
      fmt::print(stderr, "stitch: note: {}: {}; --no-unfold-tubes keeps the fitted ones\n", where,
                 describe(mesh, t));
  }
}

void add_method_option(CLI::App* cmd, std::string& method, bool allow_all, InputOptions* in) {
  CLI::Option* opt =
      cmd->add_option("--method", method,
                      choice_help(method_table()) + (allow_all ? "; all: every method" : "") +
                          fmt::format("; a project's ({}) own method replaces the default",
                                      kProjectExtensions.front()));
  std::vector<std::string> names;
  for (const Choice<Method>& c : method_table()) names.emplace_back(c.name);
  if (allow_all) names.emplace_back("all");
  opt->check(CLI::IsMember(names));
  opt->capture_default_str();
  if (in) {
    in->method = &method;
    in->method_option = opt;
  }
}

bool stderr_is_terminal() {
  return isatty(fileno(stderr)) != 0;
}

StageReporter::StageReporter(const ProgressFlags& flags)
    : enabled_(!flags.quiet && (flags.progress || stderr_is_terminal())),
      terminal_(enabled_ && stderr_is_terminal()),
      quiet_(flags.quiet) {}

void StageReporter::begin(const std::string& stage) {
  start_ = std::chrono::steady_clock::now();
  stage_ = stage;
  percent_ = -1;
  open_ = enabled_;
  if (enabled_) fmt::print(stderr, "stitch: {}...", stage);
}

void StageReporter::note(const std::string& line) {
  if (quiet_) return;
  // On a terminal the stage's line is erased and drawn again below the note; in a log the note
  // starts a line of its own.
  if (open_) fmt::print(stderr, "{}", terminal_ ? "\r\x1b[K" : "\n");
  fmt::print(stderr, "stitch: {}\n", line);
  if (open_) {
    fmt::print(stderr, "stitch: {}...", stage_);
    if (percent_ >= 0) fmt::print(stderr, " {:3d}%", percent_);
  }
}

void StageReporter::fraction(double done) {
  if (!terminal_) return;
  const int percent = static_cast<int>(std::clamp(done, 0.0, 1.0) * 100);
  if (percent == percent_) return;
  percent_ = percent;
  // Redraw the stage line in place: carriage return, text, erase to the end of the line.
  fmt::print(stderr, "\rstitch: {}... {:3d}%\x1b[K", stage_, percent);
  std::fflush(stderr);
}

void StageReporter::end() {
  open_ = false;
  if (!enabled_) return;
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  if (percent_ >= 0)
    fmt::print(stderr, "\rstitch: {}... {:.2f} s\x1b[K\n", stage_, s);
  else
    fmt::print(stderr, " {:.2f} s\n", s);
}

void add_progress_option(CLI::App* cmd, ProgressFlags& flags) {
  cmd->add_flag("--progress", flags.progress,
                "print each stage and its time on stderr (default when stderr is a terminal)");
  cmd->add_flag("-q,--quiet", flags.quiet, "print nothing on stderr but errors and warnings");
}

}  // namespace stitch::cli
