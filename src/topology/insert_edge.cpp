#include "stitch/topology/insert_edge.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "topology/raw_mesh.hpp"

namespace stitch {

namespace {

/// Does the loop through `from` reach `target` (before coming back to `from`)?
bool loop_contains(const HalfedgeMesh& mesh, Halfedge from, Halfedge target) {
  Halfedge h = from;
  do {
    if (h == target) return true;
    h = mesh.next(h);
  } while (h != from);
  return false;
}

}  // namespace

Verdict can_insert_edge(const HalfedgeMesh& mesh, Corner a, Corner b) {
  for (Corner c : {a, b})
    if (Verdict v = detail::exists(mesh, c, "insert-edge"); !v) return v;
  const Vertex va = mesh.origin(a), vb = mesh.origin(b);
  if (a == b) return Verdict::refused("insert-edge: the two corners are the same corner");
  if (va == vb)
    return Verdict::refused(fmt::format(
        "insert-edge: both corners are at vertex {}; the edge would be a loop", va.idx + 1));
  // Split or merged, a hole would end up on both sides of the new edge, which then bounds no
  // surface; filling the hole first says what the user means.
  for (Face f : {mesh.face(a), mesh.face(b)})
    if (mesh.is_hole(f))
      return Verdict::refused(fmt::format(
          "insert-edge: face {} is a hole (a boundary loop of the surface); an edge into it would "
          "have the hole on both sides (fill-hole {} makes it a face first)",
          f.idx + 1, f.idx + 1));
  for (Edge x : detail::edges_between(mesh, va, vb))
    if (mesh.is_boundary(x))
      return Verdict::refused(fmt::format(
          "insert-edge: vertices {} and {} are joined by boundary edge {}; a second edge beside "
          "it would not read back ({})",
          va.idx + 1, vb.idx + 1, x.idx + 1, detail::kBesideBoundary));
  return {};
}

InsertEdgeResult insert_edge(HalfedgeMesh& mesh, Corner a, Corner b) {
  can_insert_edge(mesh, a, b).throw_if_refused();
  const Vertex va = mesh.origin(a), vb = mesh.origin(b);
  const Face fa = mesh.face(a), fb = mesh.face(b);
  const Halfedge pa = mesh.prev(a), pb = mesh.prev(b);
  const Halfedge h = mesh.add_edge(va, vb), t = HalfedgeMesh::twin(h);
  // Splice: ... pa -> h -> b ...   and   ... pb -> t -> a ...
  mesh.link(pa, h);
  mesh.link(h, b);
  mesh.link(pb, t);
  mesh.link(t, a);

  InsertEdgeResult result;
  result.edge = HalfedgeMesh::edge(h);
  if (fa == fb) {
    result.split = true;
    const Halfedge start = mesh.halfedge(fa);
    const Face fresh = mesh.add_face();
    // The loop through t holds a; the loop through h holds b. Keep fa on the part with its start.
    const Halfedge keep = loop_contains(mesh, t, start) ? t : h;
    const Halfedge give = keep == t ? h : t;
    mesh.set_face(keep, fa);
    mesh.assign_loop(give, fresh);
    mesh.set_halfedge(fa, start);
    result.face = fa;
    result.other = fresh;
  } else {
    result.split = false;
    const Face keep = std::min(fa, fb), gone = std::max(fa, fb);
    const Halfedge start = mesh.halfedge(keep);
    mesh.assign_loop(h, keep);
    mesh.set_halfedge(keep, start);
    mesh.delete_face(gone);
    result.face = keep;
    result.other = gone;
  }
  return result;
}

Verdict can_delete_edge(const HalfedgeMesh& mesh, Edge e) {
  if (Verdict v = detail::exists(mesh, e, "delete-edge"); !v) return v;
  const Halfedge h = HalfedgeMesh::halfedge(e, 0), t = HalfedgeMesh::twin(h);
  // The merged face would hold both a hole and a surface face: neither reading (the face
  // swallowed by the hole, or the hole filled) is what deleting one edge says.
  if (mesh.is_boundary(e)) {
    const bool hole_h = mesh.is_hole(h);
    const Face hole = mesh.face(hole_h ? h : t), face = mesh.face(hole_h ? t : h);
    return Verdict::refused(fmt::format(
        "delete-edge: edge {} lies on the boundary (face {} is a hole); deleting it would merge "
        "face {} into the hole (open-face {} does that)",
        e.idx + 1, hole.idx + 1, face.idx + 1, face.idx + 1));
  }
  for (Vertex v : {mesh.origin(h), mesh.origin(t)})
    if (mesh.valence(v) <= 2)
      return Verdict::refused(fmt::format(
          "delete-edge: vertex {} has valence 2 and would be left with one edge (collapse-edge "
          "removes such a vertex)",
          v.idx + 1));
  return {};
}

DeleteEdgeResult delete_edge(HalfedgeMesh& mesh, Edge e) {
  can_delete_edge(mesh, e).throw_if_refused();
  const Halfedge h = HalfedgeMesh::halfedge(e, 0), t = HalfedgeMesh::twin(h);
  const Vertex va = mesh.origin(h), vb = mesh.origin(t);
  const Face fh = mesh.face(h), ft = mesh.face(t);
  const Halfedge ph = mesh.prev(h), nh = mesh.next(h), pt = mesh.prev(t), nt = mesh.next(t);
  // Keep the end vertices' start half-edges off the deleted edge.
  if (mesh.halfedge(va) == h) mesh.set_halfedge(va, mesh.rotate_ccw(h));
  if (mesh.halfedge(vb) == t) mesh.set_halfedge(vb, mesh.rotate_ccw(t));
  mesh.link(ph, nt);
  mesh.link(pt, nh);
  mesh.delete_edge(e);

  DeleteEdgeResult result;
  if (fh != ft) {
    const Face keep = std::min(fh, ft), gone = std::max(fh, ft);
    Halfedge start = mesh.halfedge(keep);
    if (start == h || start == t) start = keep == fh ? nh : nt;
    mesh.assign_loop(start, keep);
    mesh.delete_face(gone);
    result.face = keep;
    result.other = gone;
  } else {
    result.split = true;
    // The face's loop was h, A, t, B: now A (through nh) and B (through nt) are loops of their own.
    Halfedge start = mesh.halfedge(fh);
    if (start == h) start = nh;
    if (start == t) start = nt;
    const Halfedge other_start = loop_contains(mesh, nh, start) ? nt : nh;
    mesh.assign_loop(start, fh);
    const Face fresh = mesh.add_face();
    mesh.assign_loop(other_start, fresh);
    result.face = fh;
    result.other = fresh;
  }
  return result;
}

}  // namespace stitch
