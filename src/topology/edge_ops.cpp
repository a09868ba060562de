#include "stitch/topology/edge_ops.hpp"

#include <fmt/format.h>

#include "raw_mesh.hpp"

namespace stitch {

namespace td = topology_detail;

SubdivideEdgeResult subdivide_edge(HalfedgeMesh& mesh, Edge e) {
  td::check_edge(mesh, e, "subdivide-edge");
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
  return {m, HalfedgeMesh::edge(g)};
}

void collapse_edge(HalfedgeMesh& mesh, Edge e, Vertex keep) {
  td::check_edge(mesh, e, "collapse-edge");
  Halfedge h = HalfedgeMesh::halfedge(e, 0);
  if (mesh.origin(h) != keep) h = HalfedgeMesh::twin(h);
  if (mesh.origin(h) != keep)
    throw MeshError(
        fmt::format("collapse-edge: vertex {} is not an end of edge {}", keep.idx + 1, e.idx + 1));
  const Halfedge t = HalfedgeMesh::twin(h);
  const Vertex a = keep, b = mesh.origin(t);
  if (td::edges_between(mesh, a, b).size() > 1)
    throw MeshError(fmt::format(
        "collapse-edge: vertices {} and {} are joined by more than one edge; collapsing one would "
        "make the others loops",
        a.idx + 1, b.idx + 1));

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
  mesh.delete_vertex(b);
  mesh.delete_edge(e);
}

}  // namespace stitch
