#include "stitch/tess/surface_change.hpp"

#include "mesh/sort_unique.hpp"
#include "stitch/kgon/kgon.hpp"
#include "stitch/net/control_net.hpp"

namespace stitch {

using detail::sort_unique;

SurfaceChange topology_change(const MeshDelta& delta) {
  SurfaceChange c;
  c.kind = SurfaceChange::Kind::topology;
  c.vertices = delta.vertices;
  c.edges = delta.edges;
  c.faces = delta.faces;
  return c;
}

SurfaceChange whole_change() {
  SurfaceChange c;
  c.kind = SurfaceChange::Kind::topology;
  c.whole = true;
  return c;
}

SurfaceChange combined(const std::vector<SurfaceChange>& changes) {
  SurfaceChange out;
  if (changes.empty()) return out;
  out.kind = SurfaceChange::Kind::topology;
  for (const SurfaceChange& c : changes) {
    out.whole = out.whole || c.whole;
    out.vertices.insert(out.vertices.end(), c.moved.begin(), c.moved.end());
    if (c.kind != SurfaceChange::Kind::topology) continue;
    out.vertices.insert(out.vertices.end(), c.vertices.begin(), c.vertices.end());
    out.edges.insert(out.edges.end(), c.edges.begin(), c.edges.end());
    out.faces.insert(out.faces.end(), c.faces.begin(), c.faces.end());
  }
  sort_unique(out.vertices);
  sort_unique(out.edges);
  sort_unique(out.faces);
  return out;
}

AffectedSet affected_by(const HalfedgeMesh& m, std::vector<Face> moved_faces, AffectedSet seeds) {
  KgonElements kgons = kgons_reading(m, std::move(moved_faces));
  kgons.merge({std::move(seeds.faces), std::move(seeds.vertices), std::move(seeds.edges)});
  seeds.corners = nets_reading(m, kgons);
  seeds.faces = std::move(kgons.faces);
  seeds.vertices = std::move(kgons.vertices);
  seeds.edges = std::move(kgons.edges);
  return seeds;
}

AffectedSet affected_by(const HalfedgeMesh& m, const SurfaceChange& change) {
  AffectedSet a;
  std::vector<Face> moved_faces;
  if (change.kind == SurfaceChange::Kind::geometry) {
    for (Vertex v : change.moved)
      for (Halfedge h : m.vertex_fan(v)) moved_faces.push_back(m.face(h));
  } else if (change.kind == SurfaceChange::Kind::kgons) {
    a.faces = change.faces;
    a.vertices = change.vertices;
    a.edges = change.edges;
  }
  return affected_by(m, std::move(moved_faces), std::move(a));
}

}  // namespace stitch
