#include "stitch/analysis/sectors.hpp"

namespace stitch {

namespace {

bool marked(const std::vector<std::uint8_t>& sharp, Edge e) {
  return static_cast<size_t>(e.idx) < sharp.size() && sharp[static_cast<size_t>(e.idx)] != 0;
}

}  // namespace

std::vector<std::uint8_t> sharp_edges(const HalfedgeMesh& mesh, const Surface& surface) {
  std::vector<std::uint8_t> sharp(static_cast<size_t>(mesh.edge_capacity()), 0);
  if (!mesh.has_features()) return sharp;
  const KgonSet& kgons = surface.bezier().kgons;
  for (Edge e : mesh.edges())
    sharp[static_cast<size_t>(e.idx)] =
        surface.method() == Method::cc ? mesh.is_sharp(e) : kgons.sharp(e) || mesh.is_boundary(e);
  return sharp;
}

int sharp_spokes(const HalfedgeMesh& mesh, Vertex v, const std::vector<std::uint8_t>& sharp) {
  int count = 0;
  for (Halfedge h : mesh.vertex_fan(v)) count += marked(sharp, HalfedgeMesh::edge(h)) ? 1 : 0;
  return count;
}

std::vector<std::vector<Corner>> vertex_sectors(const HalfedgeMesh& mesh, Vertex v,
                                                const std::vector<std::uint8_t>& sharp) {
  const std::vector<Halfedge> fan = mesh.vertex_fan(v);
  const int n = static_cast<int>(fan.size());
  std::vector<int> spokes;
  for (int j = 0; j < n; ++j)
    if (marked(sharp, HalfedgeMesh::edge(fan[j]))) spokes.push_back(j);
  std::vector<std::vector<Corner>> sectors;
  if (spokes.size() < 2) {
    std::vector<Corner> all;
    for (Halfedge h : fan)
      if (!mesh.is_hole(h)) all.push_back(h);
    if (!all.empty()) sectors.push_back(std::move(all));
    return sectors;
  }
  for (size_t s = 0; s < spokes.size(); ++s) {
    const int end = spokes[(s + 1) % spokes.size()];
    std::vector<Corner> sector;
    for (int j = spokes[s];; j = (j + 1) % n) {
      if (!mesh.is_hole(fan[j])) sector.push_back(fan[j]);
      if ((j + 1) % n == end) break;
    }
    if (!sector.empty()) sectors.push_back(std::move(sector));
  }
  return sectors;
}

}  // namespace stitch
