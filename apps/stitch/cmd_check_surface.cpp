// stitch check-surface MESH [--json]: self-intersections, folds and degenerate triangles of a
// (tessellated) surface. Exit status 1 when it finds any.
#include <fmt/format.h>

#include <memory>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "options.hpp"
#include "stitch/analysis/surface_check.hpp"
#include "stitch/mesh/formats.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/mesh/limits.hpp"

namespace stitch::cli {

namespace {

struct CheckSurfaceArgs {
  std::string path;
  bool json = false;
  SurfaceCheckOptions options;
  std::vector<double> through;  ///< x1 y1 z1 x2 y2 z2: a segment that must meet no triangle
  ProgressFlags progress;
};

void run_check_surface(const CheckSurfaceArgs& a) {
  StageReporter stage(a.progress);
  stage.begin("reading " + a.path);
  std::vector<std::string> warnings;
  const PolygonSoup polygons =
      read_polygon_soup(a.path, &warnings, [&stage](double done) { stage.fraction(done); });
  stage.end();
  for (const std::string& w : warnings) fmt::print(stderr, "stitch: warning: {}: {}\n", a.path, w);
  stage.begin(fmt::format("checking {} polygons", polygons.faces.size()));
  const TriangleSoup soup = triangulate(polygons);
  SurfaceCheckOptions options = a.options;
  options.progress = [&stage](double done) { stage.fraction(done); };
  const SurfaceCheckReport r = check_surface(soup, options);
  stage.end();
  std::vector<SegmentHit> hits;
  if (!a.through.empty())
    hits = segment_hits(soup, Vec3(a.through[0], a.through[1], a.through[2]),
                        Vec3(a.through[3], a.through[4], a.through[5]));
  const bool ok = r.clean() && hits.empty();
  if (a.json) {
    nlohmann::json j;
    j["file"] = a.path;
    j["clean"] = ok;
    j["triangles"] = r.triangles;
    j["self_intersections"] = r.self_intersections;
    j["folds"] = r.folds;
    j["degenerate"] = r.degenerate;
    j["inconsistent_edges"] = r.inconsistent_edges;
    auto pairs = [&](const std::vector<std::array<int, 2>>& list) {
      nlohmann::json out = nlohmann::json::array();
      for (const auto& p : list)
        out.push_back({{"triangles", {p[0] + 1, p[1] + 1}},
                       {"faces", {soup.source[p[0]] + 1, soup.source[p[1]] + 1}}});
      return out;
    };
    j["intersecting_pairs"] = pairs(r.intersecting_pairs);
    j["folded_pairs"] = pairs(r.folded_pairs);
    j["degenerate_triangles"] = nlohmann::json::array();
    for (int t : r.degenerate_triangles)
      j["degenerate_triangles"].push_back({{"triangle", t + 1}, {"face", soup.source[t] + 1}});
    if (!a.through.empty()) {
      j["segment_hits"] = nlohmann::json::array();
      for (const SegmentHit& h : hits)
        j["segment_hits"].push_back(
            {{"triangle", h.triangle + 1}, {"face", soup.source[h.triangle] + 1}, {"t", h.t}});
    }
    fmt::print("{}\n", j.dump(2));
  } else {
    fmt::print("{}: {}{}", a.path, ok ? "clean, " : "PROBLEMS, ", r.describe(soup));
    if (!a.through.empty()) {
      fmt::print("  segment: {} hit(s)\n", hits.size());
      for (size_t i = 0; i < hits.size() && i < 10; ++i)
        fmt::print("  segment meets triangle {} (of polygon {}) at t = {:.6g}\n",
                   hits[i].triangle + 1, soup.source[hits[i].triangle] + 1, hits[i].t);
    }
  }
  if (!ok) throw ExitStatus(1, "");
}

}  // namespace

void add_check_surface_command(CLI::App& app) {
  auto args = std::make_shared<CheckSurfaceArgs>();
  auto* cmd = app.add_subcommand(
      "check-surface",
      "report self-intersecting, folded and degenerate triangles of a surface mesh (quads are "
      "split along their shorter diagonal, other polygons fanned); exit status 1 when there are "
      "any. Memory: the file's polygons and their triangles, checked a region of space at a time "
      "on "
      "every core");
  cmd->add_option("MESH", args->path, "surface mesh (" + extension_list(kMeshReadExtensions) + ")")
      ->required();
  cmd->add_flag("--json", args->json, "print the report as JSON");
  cmd->add_option("--fold-angle", args->options.fold_angle_deg,
                  "adjacent triangles fold when their normals differ by more than this, degrees "
                  "(a file marks no creases: faces meeting at a right angle pass, sharper creases "
                  "count; stitch smooth --check knows the mesh's creases)")
      ->check(finite_range(0.0, 180.0))
      ->capture_default_str();
  cmd->add_option("--through", args->through,
                  "X1 Y1 Z1 X2 Y2 Z2: a segment that must pass without meeting the surface (e.g. "
                  "the axis of a hole); hits count as problems")
      ->expected(6)
      ->check(finite_range(-limits::max_coordinate, limits::max_coordinate));
  add_progress_option(cmd, args->progress);
  cmd->callback([args] { run_check_surface(*args); });
}

}  // namespace stitch::cli
