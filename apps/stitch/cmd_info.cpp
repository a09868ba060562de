// stitch info IN: what the mesh is made of, topologically.
#include <fmt/format.h>

#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "commands.hpp"
#include "options.hpp"
#include "stitch/eval/surface.hpp"
#include "stitch/mesh/repair.hpp"
#include "stitch/mesh/validate.hpp"
#include "stitch/output/output.hpp"
#include "stitch/tess/patches.hpp"

namespace stitch::cli {

namespace {

struct InfoArgs {
  InputOptions in;
  bool json = false;
  bool repair_report = false;
  bool patches = false;
  std::string method{method_table().front().name};
  PatchSetOptions patch_set;
  KgonCliOptions kgon;
};

std::string histogram(const std::map<int, int>& h) {
  std::string s;
  for (const auto& [k, n] : h) s += fmt::format("{}{}: {}", s.empty() ? "" : ", ", k, n);
  return s;
}

void run_info(const InfoArgs& a) {
  BuildReport report;
  const HalfedgeMesh mesh = load_input(a.in, &report);
  if (a.repair_report) {
    fmt::print("{}\n", to_json(report.repair));
    return;
  }
  const TopologyStats t = topology_stats(mesh);
  Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
  for (Vertex v : mesh.vertices()) {
    lo = lo.cwiseMin(mesh.position(v));
    hi = hi.cwiseMax(mesh.position(v));
  }
  std::vector<int> ev_vertices, ev_faces;
  for (Vertex v : mesh.vertices())
    if (mesh.valence(v) != 4) ev_vertices.push_back(v.idx + 1);
  // Holes make no patches, so they are no extraordinary points.
  for (Face f : mesh.surface_faces())
    if (mesh.degree(f) != 4) ev_faces.push_back(f.idx + 1);
  // Semi-sharp tags are counted apart: mdc and asc honour them by refining the mesh first.
  int sharp_edges = 0, semi_sharp_edges = 0, sharp_corners = 0, semi_sharp_corners = 0;
  for (Edge e : mesh.edges())
    if (!mesh.is_boundary(e) && mesh.sharpness(e) > 0)
      ++(mesh.sharpness(e) >= infinitely_sharp ? sharp_edges : semi_sharp_edges);
  for (Vertex v : mesh.vertices())
    if (mesh.sharpness(v) > 0)
      ++(mesh.sharpness(v) >= infinitely_sharp ? sharp_corners : semi_sharp_corners);
  const size_t patches = mesh.patch_corners().size();

  const Method method = parse_method(a.method);
  const SemiSharpRefinement refinement = semi_sharp_refinement(mesh, surface_spec(a.kgon, method));
  std::optional<PatchSet> set;
  if (a.patches) {
    const BuiltSurface built = build_cli_surface(a.kgon, mesh, method, a.in.path);
    set = bezier_patches(built.mesh(mesh), built.surface, a.patch_set);
  }

  if (a.json) {
    nlohmann::json j;
    j["file"] = a.in.path;
    j["vertices"] = t.vertices;
    j["edges"] = t.edges;
    j["faces"] = t.faces;
    j["boundary_loops"] = t.boundary_loops;
    j["crease_edges"] = {{"infinitely_sharp", sharp_edges}, {"semi_sharp", semi_sharp_edges}};
    j["corner_vertices"] = {{"infinitely_sharp", sharp_corners},
                            {"semi_sharp", semi_sharp_corners}};
    j["components"] = t.components;
    j["euler_characteristic"] = t.euler;
    j["genus"] = t.genus;
    j["patches"] = patches;
    j["semi_sharp_refinement"] = {
        {"method", a.method},
        {"levels", refinement.levels},
        {"levels_wanted", refinement.levels_wanted},
        {"largest_tag", refinement.largest_tag},
        {"faces", refinement.levels > 0 ? refinement.faces : t.faces},
        {"patches", refinement.levels > 0 ? refinement.patches : static_cast<long long>(patches)}};
    for (const auto& [k, n] : t.valence_histogram) j["valence_histogram"][std::to_string(k)] = n;
    for (const auto& [k, n] : t.degree_histogram) j["degree_histogram"][std::to_string(k)] = n;
    j["extraordinary_vertices"] = ev_vertices;
    j["extraordinary_faces"] = ev_faces;
    j["bounding_box"] = {{lo.x(), lo.y(), lo.z()}, {hi.x(), hi.y(), hi.z()}};
    j["repairs"] = nlohmann::json::object();
    for (const auto& [kind, n] : report.repair.counts()) j["repairs"][std::string(kind)] = n;
    if (set)
      j["bezier_patch_set"] = {{"method", a.method},
                               {"tolerance", set->tolerance},
                               {"angle_tolerance_deg", set->angle_tolerance_deg},
                               {"patches", set->patches.size()},
                               {"exact_patches", set->num_exact()},
                               {"depth", set->depth},
                               {"model_size", set->model_size},
                               {"max_position_deviation", set->max_position_deviation},
                               {"max_normal_deviation_deg", set->max_normal_deviation_deg}};
    fmt::print("{}\n", j.dump(2));
    return;
  }
  fmt::print("{}\n", a.in.path);
  fmt::print("  vertices {}, edges {}, faces {}\n", t.vertices, t.edges, t.faces);
  fmt::print("  components {}, Euler characteristic {}, genus {}\n", t.components, t.euler,
             t.genus);
  fmt::print("  boundary loops {}\n", t.boundary_loops);
  fmt::print(
      "  crease edges {} ({} infinitely sharp, {} semi-sharp), corner vertices {} ({} "
      "infinitely sharp, {} semi-sharp)\n",
      sharp_edges + semi_sharp_edges, sharp_edges, semi_sharp_edges,
      sharp_corners + semi_sharp_corners, sharp_corners, semi_sharp_corners);
  fmt::print("  bicubic patches (one per corner, holes excepted) {}\n", patches);
  if (refinement.levels > 0)
    fmt::print("  {} (method {}; --sharp-from rounds them instead)\n", refinement.summary(),
               a.method);
  fmt::print("  valence histogram  {}\n", histogram(t.valence_histogram));
  fmt::print("  face degree histogram  {}\n", histogram(t.degree_histogram));
  fmt::print("  extraordinary points: {} vertices (valence != 4), {} faces (degree != 4)\n",
             ev_vertices.size(), ev_faces.size());
  fmt::print("  bounding box ({:.6g}, {:.6g}, {:.6g}) - ({:.6g}, {:.6g}, {:.6g})\n", lo.x(), lo.y(),
             lo.z(), hi.x(), hi.y(), hi.z());
  // The defects repaired on reading, counted (the warnings name them; --repair-report lists each).
  std::string repairs;
  for (const auto& [kind, n] : report.repair.counts())
    repairs += fmt::format("{}{} {}", repairs.empty() ? "" : ", ", n, kind);
  fmt::print("  repaired on reading  {}\n", repairs.empty() ? "nothing" : repairs);
  if (!set) return;
  // What `stitch smooth -o X.step/.igs/.bez.json` would write, without writing it.
  fmt::print(
      "  Bezier patch set ({}, tolerance {:.3g} of the model size, {:.3g} degrees)  {} "
      "patches ({} exact, {} innermost cells at extraordinary points), depth {}\n",
      a.method, set->tolerance, set->angle_tolerance_deg, set->patches.size(), set->num_exact(),
      set->patches.size() - set->num_exact(), set->depth);
  fmt::print(
      "  largest deviation from the surface  {:.3g} ({:.3g} of the model size {:.6g}), "
      "normal {:.3g} degrees\n",
      set->max_position_deviation,
      set->model_size > 0 ? set->max_position_deviation / set->model_size : 0.0, set->model_size,
      set->max_normal_deviation_deg);
}

}  // namespace

void add_info_command(CLI::App& app) {
  auto args = std::make_shared<InfoArgs>();
  CLI::App* cmd = app.add_subcommand(
      "info", "Counts, genus, valence and face-degree histograms, extraordinary points");
  add_input_options(cmd, args->in);
  cmd->add_flag("--json", args->json, "print JSON");
  cmd->add_flag("--repair-report", args->repair_report,
                "print only what was repaired on reading, every change, as JSON (see "
                "docs/formats.md)");
  cmd->add_flag("--patches", args->patches,
                fmt::format("also expand the Bezier patch set that the exact outputs ({}) hold "
                            "and report its depth, patch count and largest deviation from "
                            "exact evaluation",
                            output_extensions(OutputKind::exact)));
  add_method_option(cmd, args->method, false, &args->in);
  cmd->add_option("--tolerance", args->patch_set.tolerance,
                  "with --patches: largest distance of the innermost cells from the exact "
                  "surface, relative to the model size")
      ->capture_default_str();
  cmd->add_option("--angle-tolerance", args->patch_set.angle_tolerance_deg,
                  "with --patches: largest angle between faces along a shared edge, degrees "
                  "(those cells' normals within half of it of the surface's)")
      ->capture_default_str();
  add_kgon_options(cmd, args->kgon, &args->in);
  cmd->callback([args] { run_info(*args); });
}

}  // namespace stitch::cli
