#include "exact_output.hpp"

#include <fmt/format.h>

#include <cstdio>

#include "stitch/mesh/io.hpp"
#include "stitch/tess/bezier_json.hpp"
#include "stitch/tess/export.hpp"
#include "stitch/tess/patches.hpp"
#if STITCH_WITH_CAD
#include "stitch/cad/cad.hpp"
#endif

namespace stitch::cli {

namespace {

bool is_cad(const std::string& ext) {
  return ext == ".step" || ext == ".stp" || ext == ".igs" || ext == ".iges";
}

void report(const HalfedgeMesh& mesh, const PatchSet& set) {
  fmt::print(stderr,
             "stitch: {} Bezier patches ({} exact, {} innermost cells at extraordinary points), "
             "depth {}\n",
             set.patches.size(), set.num_exact(), set.patches.size() - set.num_exact(), set.depth);
  fmt::print(stderr,
             "stitch: largest deviation from exact evaluation: {:.3g} ({:.3g} of the model size "
             "{:.6g}; asked {:.3g}), normal {:.3g} degrees (asked {:.3g})\n",
             set.max_position_deviation,
             set.model_size > 0 ? set.max_position_deviation / set.model_size : 0.0, set.model_size,
             set.tolerance, set.max_normal_deviation_deg, set.angle_tolerance_deg);
  if (!set.points_without_normal.empty()) {
    std::string where;
    for (size_t i = 0; i < set.points_without_normal.size() && i < 8; ++i)
      where += fmt::format("{}{} ({:.3g} degrees)", i ? ", " : "",
                           describe(mesh, set.points_without_normal[i]),
                           set.points_without_normal[i].angle_deg);
    if (set.points_without_normal.size() > 8)
      where += fmt::format(", ... ({} more)", set.points_without_normal.size() - 8);
    fmt::print(stderr,
               "stitch: note: the angle tolerance is not applied at {} point(s) where the surface "
               "has no tangent plane (cone points of creases and corners, valence-2 vertices, "
               "folds): {}\n",
               set.points_without_normal.size(), where);
  }
}

}  // namespace

void add_exact_output_options(CLI::App* cmd, ExactOutputOptions& options) {
  // No range checks here: the library refuses a tolerance <= 0 with its own message.
  cmd->add_option("--tolerance", options.tolerance,
                  "for .json/.step/.igs: largest distance of the innermost cells at extraordinary "
                  "points from the exact surface, relative to the model size (> 0)")
      ->capture_default_str();
  cmd->add_option("--angle-tolerance", options.angle_tolerance_deg,
                  "for .json/.step/.igs: largest normal deviation of those cells, degrees (> 0)")
      ->capture_default_str();
  cmd->add_option("--units", options.units,
                  "length unit declared in .step/.igs (coordinates are not scaled): mm, cm, m, "
                  "in, ft")
      ->capture_default_str();
  cmd->add_flag("--kgons", options.kgons, "Bezier JSON: add every K-gon");
  cmd->add_option("--patches", options.patches,
                  "also write the Bezier patches as JSON (docs/formats.md) to this .json file");
}

bool is_exact_output(const std::string& path) {
  const std::string ext = file_extension(path);
  return ext == ".json" || is_cad(ext);
}

std::string smooth_output_extensions() {
  return fmt::format("{}, .json (Bezier patches), .step, .stp, .igs, .iges",
                     extension_list(kSurfaceMeshExtensions));
}

void check_exact_outputs(const std::string& out, const ExactOutputOptions& options) {
  if (!options.patches.empty() && file_extension(options.patches) != ".json")
    throw UsageError(fmt::format("--patches writes JSON; '{}' is not .json", options.patches));
  if (!is_cad(file_extension(out))) return;
#if STITCH_WITH_CAD
  cad::check_units(options.units);
#else
  throw OutputError(fmt::format(
      "cannot write '{}': this stitch was built without OpenCASCADE (STITCH_BUILD_CAD=OFF)", out));
#endif
}

std::string write_exact_outputs(const std::string& out, const HalfedgeMesh& mesh,
                                const Surface& surface, const ExactOutputOptions& options,
                                StageReporter& stage) {
  const bool exact_out = is_exact_output(out);
  if (!exact_out && options.patches.empty()) return "";
  stage.begin("expanding the Bezier patches");
  const PatchSet set =
      bezier_patches(mesh, surface, {options.tolerance, options.angle_tolerance_deg});
  stage.end();
  report(mesh, set);
  const KgonSet* kgons = options.kgons ? &surface.bezier().kgons : nullptr;
  if (!options.patches.empty()) {
    stage.begin("writing " + options.patches);
    write_bezier_json(options.patches, set, kgons);
    stage.end();
  }
  if (!exact_out) return "";
  stage.begin("writing " + out);
  std::string summary;
  if (file_extension(out) == ".json") {
    write_bezier_json(out, set, kgons);
    summary = fmt::format("{} Bezier patches, depth {}", set.patches.size(), set.depth);
  } else {
#if STITCH_WITH_CAD
    cad::quiet_opencascade();  // stdout is for the summary below
    cad::CadOptions cad_options;
    cad_options.units = options.units;
    cad_options.angle_tolerance_deg = options.angle_tolerance_deg;
    cad_options.progress = [&stage](double done) { stage.fraction(done); };
    const cad::CadEstimate e =
        cad::estimate_cad(mesh, surface, set, cad_options.packing, *cad::cad_format(out));
    fmt::print(stderr, "stitch: {} B-spline faces, about {} poles and {:.1f} MB\n", e.faces,
               e.poles, e.bytes / 1e6);
    const cad::CadReport r = cad::write_cad(out, mesh, surface, set, cad_options);
    summary = fmt::format(
        "{} B-spline faces, {} poles, knots {} removed/{} C2/{} C1/{} C0, {} shell(s), {} "
        "solid(s), volume {:.6g}, {} free edges, {} smooth edges ({} G1, largest angle {:.3g} "
        "degrees), {} sharp edges, units {}",
        r.faces, r.poles, r.knots[0], r.knots[1], r.knots[2], r.knots[3], r.shells, r.solids,
        r.volume, r.free_edges, r.smooth_edges, r.g1_edges, r.max_smooth_angle_deg, r.sharp_edges,
        options.units);
#endif
  }
  stage.end();
  return summary;
}

}  // namespace stitch::cli
