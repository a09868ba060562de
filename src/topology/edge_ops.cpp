#include "stitch/topology/edge_ops.hpp"

#include <fmt/format.h>

#include "topology/raw_mesh.hpp"

namespace stitch {

Verdict can_subdivide_edge(const HalfedgeMesh& mesh, Edge e) {
  return detail::exists(mesh, e, "subdivide-edge");
}

SubdivideEdgeResult subdivide_edge(HalfedgeMesh& mesh, Edge e) {
  can_subdivide_edge(mesh, e).throw_if_refused();
  const Halfedge h = HalfedgeMesh::halfedge(e, 0), t = HalfedgeMesh::twin(h);
  const Vertex a = mesh.origin(h), b = mesh.origin(t);
  const Vertex m = mesh.add_vertex(0.5 * (mesh.position(a) + mesh.position(b)));
  // h becomes a -> m followed by g: m -> b; on the other side g's twin b -> m precedes t: m -> a.
  const Halfedge g = mesh.add_edge(m, b), gt = HalfedgeMesh::twin(g);
  const Halfedge nh = mesh.next(h), pt = mesh.prev(t);
  mesh.link(h, g);
  mesh.link(g, nh);
  mesh.link(pt, gt);
  mesh.link(gt, t);
  mesh.set_face(g, mesh.face(h));
  mesh.set_face(gt, mesh.face(t));
  mesh.set_origin(t, m);
  mesh.set_halfedge(m, g);
  if (mesh.halfedge(b) == t) mesh.set_halfedge(b, gt);
  // A crease runs on through the new vertex: both halves are the old edge, so both keep its tag.
  mesh.set_sharpness(HalfedgeMesh::edge(g), mesh.sharpness(e));
  return {m, HalfedgeMesh::edge(g)};
}

Verdict can_collapse_edge(const HalfedgeMesh& mesh, Edge e, Vertex keep) {
  if (Verdict v = detail::exists(mesh, e, "collapse-edge"); !v) return v;
  Halfedge h = HalfedgeMesh::halfedge(e, 0);
  if (mesh.origin(h) != keep) h = HalfedgeMesh::twin(h);
  if (mesh.origin(h) != keep)
    return Verdict::refused(
        fmt::format("collapse-edge: vertex {} is not an end of edge {}", keep.idx + 1, e.idx + 1));
  const Halfedge t = HalfedgeMesh::twin(h);
  const Vertex a = keep, b = mesh.origin(t);
  if (detail::edges_between(mesh, a, b).size() > 1)
    return Verdict::refused(fmt::format(
        "collapse-edge: vertices {} and {} are joined by more than one edge; collapsing one would "
        "make the others loops",
        a.idx + 1, b.idx + 1));

  // a takes every corner of b: if both already touch the boundary and e is not a boundary edge
  // (whose hole loses one of its two corners there), two boundary loops, or one loop twice,
  // would meet at a single vertex.
  auto hole_corners = [&](Vertex v) {
    int n = 0;
    for (Halfedge c : mesh.vertex_fan(v)) n += mesh.is_hole(c);
    return n;
  };
  const int holes_after =
      hole_corners(a) + hole_corners(b) - (mesh.is_hole(h) ? 1 : 0) - (mesh.is_hole(t) ? 1 : 0);
  if (holes_after > 1)
    return Verdict::refused(fmt::format(
        "collapse-edge: vertices {} and {} both lie on the boundary but edge {} does not; "
        "merging them would pinch the boundary at one vertex",
        a.idx + 1, b.idx + 1, e.idx + 1));
  for (Halfedge side : {h, t})
    if (mesh.is_hole(side) && mesh.degree(mesh.face(side)) <= 3)
      return Verdict::refused(fmt::format(
          "collapse-edge: hole {} would be left with 2 sides, a slit that a written file cannot "
          "tell from a closed seam",
          mesh.face(side).idx + 1));
  // Edges from a and b to a common neighbour become parallel: fine between faces, but not when
  // one of them is on the boundary.
  for (Halfedge x : mesh.vertex_fan(b)) {
    const Vertex c = mesh.target(x);
    if (c == a) continue;
    for (Edge y : detail::edges_between(mesh, a, c))
      if (mesh.is_boundary(y) || mesh.is_boundary(HalfedgeMesh::edge(x)))
        return Verdict::refused(fmt::format(
            "collapse-edge: vertices {} and {} are both joined to vertex {}, on the boundary; "
            "the two edges would join the same vertices and would not read back ({})",
            a.idx + 1, b.idx + 1, c.idx + 1, detail::kBesideBoundary));
  }
  return {};
}

void collapse_edge(HalfedgeMesh& mesh, Edge e, Vertex keep) {
  can_collapse_edge(mesh, e, keep).throw_if_refused();
  Halfedge h = HalfedgeMesh::halfedge(e, 0);
  if (mesh.origin(h) != keep) h = HalfedgeMesh::twin(h);
  const Halfedge t = HalfedgeMesh::twin(h);
  const Vertex a = keep, b = mesh.origin(t);

  const Halfedge ph = mesh.prev(h), nh = mesh.next(h), pt = mesh.prev(t), nt = mesh.next(t);
  for (Halfedge o : mesh.vertex_fan(b))
    if (o != t) mesh.set_origin(o, a);
  mesh.link(ph, nh);
  mesh.link(pt, nt);
  for (Halfedge side : {h, t}) {
    const Face f = mesh.face(side);
    if (mesh.halfedge(f) == side) mesh.set_halfedge(f, side == h ? nh : nt);
  }
  if (mesh.halfedge(a) == h) mesh.set_halfedge(a, nt);
  mesh.position(a) = 0.5 * (mesh.position(a) + mesh.position(b));
  // The merged vertex stands for both: a corner tag on either survives, as when a file tags one
  // vertex twice.
  if (mesh.sharpness(b) > mesh.sharpness(a)) mesh.set_sharpness(a, mesh.sharpness(b));
  mesh.delete_vertex(b);
  mesh.delete_edge(e);
}

}  // namespace stitch
