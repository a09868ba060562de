#include "stitch/mesh/build.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "stitch/mesh/validate.hpp"

namespace stitch {

namespace {

std::string where_face(const PolygonSoup& soup, int f) {
  std::string s = fmt::format("face {}", f + 1);
  if (f < static_cast<int>(soup.face_lines.size()) && soup.face_lines[f] > 0)
    s += fmt::format(" ({}line {})", soup.source.empty() ? "" : soup.source + ", ",
                     soup.face_lines[f]);
  return s;
}

std::string where_vertex(const PolygonSoup& soup, int v) {
  std::string s = fmt::format("vertex {}", v + 1);
  if (v < static_cast<int>(soup.vertex_lines.size()) && soup.vertex_lines[v] > 0)
    s += fmt::format(" ({}line {})", soup.source.empty() ? "" : soup.source + ", ",
                     soup.vertex_lines[v]);
  return s;
}

void check_soup(const PolygonSoup& soup, const BuildOptions& options) {
  const int nv = static_cast<int>(soup.positions.size());
  for (int v = 0; v < nv; ++v)
    if (!soup.positions[v].allFinite())
      throw MeshError(fmt::format("{} has a non-finite coordinate", where_vertex(soup, v)));
  if (soup.faces.empty()) throw MeshError("the mesh has no faces");
  const size_t min_degree = options.allow_two_gons ? 2 : 3;
  for (int f = 0; f < static_cast<int>(soup.faces.size()); ++f) {
    const auto& loop = soup.faces[f];
    if (loop.size() < min_degree)
      throw MeshError(fmt::format("{} has {} vertices; a face needs at least {}",
                                  where_face(soup, f), loop.size(), min_degree));
    for (size_t i = 0; i < loop.size(); ++i) {
      if (loop[i] < 0 || loop[i] >= nv)
        throw MeshError(fmt::format("{} refers to vertex {}, but there are {} vertices",
                                    where_face(soup, f), loop[i] + 1, nv));
      if (loop[i] == loop[(i + 1) % loop.size()])
        throw MeshError(fmt::format("{} repeats vertex {} at consecutive positions",
                                    where_face(soup, f), loop[i] + 1));
    }
  }
}

struct DirectedEdge {
  int face;
  int slot;  // position in the face loop; the edge runs from slot to slot+1
};

}  // namespace

HalfedgeMesh build_mesh(const PolygonSoup& soup, const BuildOptions& options, BuildReport* report) {
  check_soup(soup, options);
  BuildReport local;
  BuildReport& rep = report ? *report : local;

  // Unused vertices are dropped: they have no place on a surface.
  const int nv_in = static_cast<int>(soup.positions.size());
  std::vector<int> used(nv_in, 0);
  for (const auto& loop : soup.faces)
    for (int v : loop) used[v] = 1;
  std::vector<int> remap(nv_in, -1);
  HalfedgeMesh mesh;
  for (int v = 0; v < nv_in; ++v) {
    if (!used[v]) {
      ++rep.dropped_vertices;
      continue;
    }
    remap[v] = mesh.add_vertex(soup.positions[v]).idx;
    rep.vertex_source.push_back(v);
  }
  if (rep.dropped_vertices > 0)
    rep.warnings.push_back(fmt::format("dropped {} unused vertices (not referenced by any face)",
                                       rep.dropped_vertices));

  // Group directed edges by their unordered vertex pair.
  std::map<std::pair<int, int>, std::pair<std::vector<DirectedEdge>, std::vector<DirectedEdge>>>
      groups;  // (lo, hi) -> (lo->hi edges, hi->lo edges)
  for (int f = 0; f < static_cast<int>(soup.faces.size()); ++f) {
    const auto& loop = soup.faces[f];
    for (int i = 0; i < static_cast<int>(loop.size()); ++i) {
      const int a = loop[i], b = loop[(i + 1) % loop.size()];
      auto& g = groups[{std::min(a, b), std::max(a, b)}];
      (a < b ? g.first : g.second).push_back({f, i});
    }
  }

  // Pairing: an edge seen once per direction pairs itself. Where several edges join the same two
  // vertices the file cannot say which directed edge is the twin of which, so the pairings of
  // those groups are searched for one under which every vertex has a single fan.
  struct Group {
    int a, b;                            // mesh vertices, a < b in soup order
    std::vector<DirectedEdge> fwd, bwd;  // a -> b and b -> a
    std::vector<int> perm;               // fwd[i] pairs with bwd[perm[i]]
    std::vector<DirectedEdge> boundary;  // an edge with no partner (fill_holes only)
  };
  std::vector<Group> pairs;
  std::string boundary_error;  // the first boundary edge, when holes are not to be filled
  for (auto& [key, g] : groups) {
    auto& [fwd, bwd] = g;
    Group grp{remap[key.first], remap[key.second], fwd, bwd, {}, {}};
    const size_t total = fwd.size() + bwd.size();
    if (fwd.size() != bwd.size()) {
      if (total == 1) {
        const DirectedEdge d = fwd.empty() ? bwd[0] : fwd[0];
        // Without fill_holes the boundary is refused, but only after the non-manifold checks
        // below (which close the holes to look at every fan): a non-manifold mesh must be
        // reported as such, not sent to --fill-holes first.
        if (!options.fill_holes && boundary_error.empty())
          boundary_error = fmt::format(
              "the mesh has a boundary: edge ({}, {}) of {} has no face on its other side "
              "(use --fill-holes to close every hole with one face)",
              key.first + 1, key.second + 1, where_face(soup, d.face));
        grp.boundary.push_back(d);
        grp.fwd.clear();  // the unpaired edge lives in `boundary` only (perm stays empty)
        grp.bwd.clear();
        pairs.push_back(std::move(grp));
        continue;
      }
      if (total == 2) {
        const auto& same = fwd.empty() ? bwd : fwd;
        throw MeshError(fmt::format(
            "inconsistent orientation: {} and {} both run along edge ({}, {}) in the same "
            "direction (one of them must be flipped)",
            where_face(soup, same[0].face), where_face(soup, same[1].face), key.first + 1,
            key.second + 1));
      }
      throw MeshError(fmt::format("non-manifold edge ({}, {}): it is shared by {} faces, e.g. {}",
                                  key.first + 1, key.second + 1, total,
                                  where_face(soup, fwd.empty() ? bwd[0].face : fwd[0].face)));
    }
    grp.perm.resize(fwd.size());
    for (size_t i = 0; i < fwd.size(); ++i) grp.perm[i] = static_cast<int>(i);
    pairs.push_back(std::move(grp));
  }

  const HalfedgeMesh vertices_only = mesh;
  // Builds the connectivity for the current pairings; returns the vertices with several fans.
  auto assemble = [&](HalfedgeMesh& out) {
    out = vertices_only;
    std::vector<std::vector<Halfedge>> slot_he(soup.faces.size());
    for (size_t f = 0; f < soup.faces.size(); ++f) slot_he[f].resize(soup.faces[f].size());
    std::vector<Halfedge> boundary;  // half-edges with no face: twins of unpaired edges
    for (const Group& g : pairs) {
      for (const DirectedEdge& d : g.boundary) {
        const bool forward = soup.faces[d.face][d.slot] == rep.vertex_source[g.a];
        const Halfedge h = forward ? out.add_edge(Vertex(g.a), Vertex(g.b))
                                   : out.add_edge(Vertex(g.b), Vertex(g.a));
        slot_he[d.face][d.slot] = h;
        boundary.push_back(HalfedgeMesh::twin(h));
      }
      for (size_t i = 0; i < g.fwd.size(); ++i) {
        const Halfedge h = out.add_edge(Vertex(g.a), Vertex(g.b));
        slot_he[g.fwd[i].face][g.fwd[i].slot] = h;
        const DirectedEdge& back = g.bwd[g.perm[i]];
        slot_he[back.face][back.slot] = HalfedgeMesh::twin(h);
      }
    }
    for (int f = 0; f < static_cast<int>(soup.faces.size()); ++f) {
      const Face face = out.add_face();
      const auto& hs = slot_he[f];
      for (size_t i = 0; i < hs.size(); ++i) {
        out.link(hs[i], hs[(i + 1) % hs.size()]);
        out.set_face(hs[i], face);
        out.set_halfedge(out.origin(hs[i]), hs[i]);
      }
      out.set_halfedge(face, hs[0]);
    }
    if (!boundary.empty()) {
      // Boundary half-edge b->a continues with the boundary half-edge leaving a.
      std::map<int, std::vector<Halfedge>> leaving;
      for (Halfedge h : boundary) leaving[out.origin(h).idx].push_back(h);
      for (const auto& [v, hs] : leaving)
        if (hs.size() > 1)
          throw MeshError(fmt::format(
              "{} is non-manifold: {} holes meet there, so --fill-holes cannot close them",
              where_vertex(soup, rep.vertex_source[v]), hs.size()));
      for (Halfedge h : boundary) out.link(h, leaving.at(out.target(h).idx)[0]);
      rep.filled_holes = 0;
      for (Halfedge h : boundary) {
        if (out.face(h).valid()) continue;
        out.assign_loop(h, out.add_face());
        ++rep.filled_holes;
      }
    }
    // A vertex is manifold when its outgoing half-edges form a single fan.
    std::vector<int> outgoing(out.vertex_capacity(), 0);
    for (Halfedge h : out.halfedges()) ++outgoing[out.origin(h).idx];
    std::vector<std::pair<Vertex, int>> bad;  // vertex, size of the fan found
    for (Vertex v : out.vertices()) {
      const int fan = static_cast<int>(out.vertex_fan(v).size());
      if (fan != outgoing[v.idx]) bad.emplace_back(v, fan);
    }
    return bad;
  };

  auto bad = assemble(mesh);
  for (Group& g : pairs) {
    if (bad.empty()) break;
    if (g.perm.size() < 2 || g.perm.size() > 5) continue;  // beyond 5! tries: leave as is
    auto touches = [&](const std::vector<std::pair<Vertex, int>>& b) {
      return std::any_of(b.begin(), b.end(), [&](const auto& vb) {
        return vb.first.idx == g.a || vb.first.idx == g.b;
      });
    };
    if (!touches(bad)) continue;
    std::vector<int> best = g.perm;
    size_t best_bad = bad.size();
    std::sort(g.perm.begin(), g.perm.end());
    do {
      HalfedgeMesh trial;
      const auto b = assemble(trial);
      if (b.size() < best_bad) {
        best_bad = b.size();
        best = g.perm;
      }
    } while (best_bad > 0 && std::next_permutation(g.perm.begin(), g.perm.end()));
    g.perm = best;
    bad = assemble(mesh);
  }
  if (!bad.empty()) {
    const auto [v, fan] = bad.front();
    int outgoing = 0;
    for (Halfedge h : mesh.halfedges()) outgoing += mesh.origin(h) == v;
    throw MeshError(fmt::format(
        "{} is non-manifold: its faces form more than one fan ({} of its {} corners are "
        "connected around it)",
        where_vertex(soup, rep.vertex_source[v.idx]), fan, outgoing));
  }
  if (!boundary_error.empty()) throw MeshError(boundary_error);
  if (rep.filled_holes > 0)
    rep.warnings.push_back(fmt::format("filled {} hole(s), each with one face", rep.filled_holes));
  validate(mesh);
  return mesh;
}

PolygonSoup to_polygon_soup(const HalfedgeMesh& mesh) {
  PolygonSoup soup;
  std::vector<int> index(mesh.vertex_capacity(), -1);
  for (Vertex v : mesh.vertices()) {
    index[v.idx] = static_cast<int>(soup.positions.size());
    soup.positions.push_back(mesh.position(v));
  }
  for (Face f : mesh.faces()) {
    std::vector<int> loop;
    for (Halfedge h : mesh.face_loop(f)) loop.push_back(index[mesh.origin(h).idx]);
    soup.faces.push_back(std::move(loop));
  }
  return soup;
}

}  // namespace stitch
