// stitch check-surface MESH [--json]: self-intersections, folds and degenerate triangles of a
// (tessellated) surface. Exit status 1 when it finds any.
#include <fmt/format.h>

#include <memory>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "stitch/analysis/surface_check.hpp"
#include "stitch/mesh/io.hpp"

namespace stitch::cli {

namespace {

struct CheckSurfaceArgs {
  std::string path;
  bool json = false;
  SurfaceCheckOptions options;
};

void run_check_surface(const CheckSurfaceArgs& a) {
  std::vector<std::string> warnings;
  const PolygonSoup polygons = read_polygon_soup(a.path, &warnings);
  for (const std::string& w : warnings) fmt::print(stderr, "stitch: warning: {}: {}\n", a.path, w);
  const TriangleSoup soup = triangulate(polygons);
  const SurfaceCheckReport r = check_surface(soup, a.options);
  if (a.json) {
    nlohmann::json j;
    j["file"] = a.path;
    j["clean"] = r.clean();
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
    fmt::print("{}\n", j.dump(2));
  } else {
    fmt::print("{}: {}{}", a.path, r.clean() ? "clean, " : "PROBLEMS, ", r.describe(soup));
  }
  if (!r.clean()) throw ExitStatus(1, "");
}

}  // namespace

void add_check_surface_command(CLI::App& app) {
  auto args = std::make_shared<CheckSurfaceArgs>();
  auto* cmd = app.add_subcommand(
      "check-surface",
      "report self-intersecting, folded and degenerate triangles of a surface mesh (polygons are "
      "fanned into triangles); exit status 1 when there are any");
  cmd->add_option("MESH", args->path, "surface mesh (.obj, .off, .ply)")->required();
  cmd->add_flag("--json", args->json, "print the report as JSON");
  cmd->add_option("--fold-angle", args->options.fold_angle_deg,
                  "adjacent triangles fold when their normals differ by more than this, degrees")
      ->check(CLI::Range(0.0, 180.0))
      ->capture_default_str();
  cmd->callback([args] { run_check_surface(*args); });
}

}  // namespace stitch::cli
