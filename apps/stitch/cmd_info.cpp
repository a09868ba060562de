// stitch info IN: what the mesh is made of, topologically.
#include <fmt/format.h>

#include <memory>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "options.hpp"
#include "stitch/mesh/validate.hpp"

namespace stitch::cli {

namespace {

struct InfoArgs {
  InputOptions in;
  bool json = false;
};

std::string histogram(const std::map<int, int>& h) {
  std::string s;
  for (const auto& [k, n] : h) s += fmt::format("{}{}: {}", s.empty() ? "" : ", ", k, n);
  return s;
}

void run_info(const InfoArgs& a) {
  const HalfedgeMesh mesh = load_input(a.in);
  const TopologyStats t = topology_stats(mesh);
  Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
  for (Vertex v : mesh.vertices()) {
    lo = lo.cwiseMin(mesh.position(v));
    hi = hi.cwiseMax(mesh.position(v));
  }
  std::vector<int> ev_vertices, ev_faces;
  for (Vertex v : mesh.vertices())
    if (mesh.valence(v) != 4) ev_vertices.push_back(v.idx + 1);
  for (Face f : mesh.faces())
    if (mesh.degree(f) != 4) ev_faces.push_back(f.idx + 1);

  if (a.json) {
    nlohmann::json j;
    j["file"] = a.in.path;
    j["vertices"] = t.vertices;
    j["edges"] = t.edges;
    j["faces"] = t.faces;
    j["components"] = t.components;
    j["euler_characteristic"] = t.euler;
    j["genus"] = t.genus;
    j["patches"] = mesh.num_halfedges();
    for (const auto& [k, n] : t.valence_histogram) j["valence_histogram"][std::to_string(k)] = n;
    for (const auto& [k, n] : t.degree_histogram) j["degree_histogram"][std::to_string(k)] = n;
    j["extraordinary_vertices"] = ev_vertices;
    j["extraordinary_faces"] = ev_faces;
    j["bounding_box"] = {{lo.x(), lo.y(), lo.z()}, {hi.x(), hi.y(), hi.z()}};
    fmt::print("{}\n", j.dump(2));
    return;
  }
  fmt::print("{}\n", a.in.path);
  fmt::print("  vertices {}, edges {}, faces {}\n", t.vertices, t.edges, t.faces);
  fmt::print("  components {}, Euler characteristic {}, genus {}\n", t.components, t.euler,
             t.genus);
  fmt::print("  bicubic patches (one per corner) {}\n", mesh.num_halfedges());
  fmt::print("  valence histogram  {}\n", histogram(t.valence_histogram));
  fmt::print("  face degree histogram  {}\n", histogram(t.degree_histogram));
  fmt::print("  extraordinary points: {} vertices (valence != 4), {} faces (degree != 4)\n",
             ev_vertices.size(), ev_faces.size());
  fmt::print("  bounding box ({:.6g}, {:.6g}, {:.6g}) - ({:.6g}, {:.6g}, {:.6g})\n", lo.x(), lo.y(),
             lo.z(), hi.x(), hi.y(), hi.z());
}

}  // namespace

void add_info_command(CLI::App& app) {
  auto args = std::make_shared<InfoArgs>();
  CLI::App* cmd = app.add_subcommand(
      "info", "Counts, genus, valence and face-degree histograms, extraordinary points");
  add_input_options(cmd, args->in);
  cmd->add_flag("--json", args->json, "print JSON");
  cmd->callback([args] { run_info(*args); });
}

}  // namespace stitch::cli
