#include "stitch/topology/connect_faces.hpp"

#include <fmt/format.h>

#include "raw_mesh.hpp"
#include "stitch/topology/insert_edge.hpp"

namespace stitch {

namespace td = topology_detail;

Verdict can_connect_faces(const HalfedgeMesh& mesh, Face f, Face g, int twist) {
  for (Face x : {f, g})
    if (Verdict v = td::exists(mesh, x, "connect-faces"); !v) return v;
  if (f == g) return Verdict::refused(fmt::format("connect-faces: face {} given twice", f.idx + 1));
  const std::vector<Halfedge> lf = mesh.face_loop(f), lg = mesh.face_loop(g);
  const int k = static_cast<int>(lf.size());
  if (static_cast<int>(lg.size()) != k)
    return Verdict::refused(fmt::format(
        "connect-faces: face {} has {} sides but face {} has {}; they must match (subdivide-edge "
        "or insert-edge first)",
        f.idx + 1, k, g.idx + 1, lg.size()));
  // Reduced first: twist - i must not overflow for a twist near INT_MIN.
  const int turn = (twist % k + k) % k;
  auto partner_index = [&](int i) { return (turn - i + k) % k; };
  auto partner = [&](int i) { return lg[partner_index(i)]; };
  for (int i = 0; i < k; ++i)
    if (mesh.origin(lf[i]) == mesh.origin(partner(i)))
      return Verdict::refused(fmt::format(
          "connect-faces: corner {} of face {} and corner {} of face {} are both vertex {}; the "
          "edge joining them would be a loop",
          i + 1, f.idx + 1, partner_index(i) + 1, g.idx + 1, mesh.origin(lf[i]).idx + 1));

  // An edge still on the boundary afterwards (a hole other than f and g on one side) must not get
  // a tube edge beside it.
  auto stays_boundary = [&](Halfedge h) {
    const Face side = mesh.face(h);
    return mesh.is_hole(side) && side != f && side != g;
  };
  for (int i = 0; i < k; ++i) {
    const Vertex u = mesh.origin(lf[i]), v = mesh.origin(partner(i));
    for (Edge y : td::edges_between(mesh, u, v))
      if (stays_boundary(HalfedgeMesh::halfedge(y, 0)) ||
          stays_boundary(HalfedgeMesh::halfedge(y, 1)))
        return Verdict::refused(fmt::format(
            "connect-faces: vertices {} and {} are joined by boundary edge {}; a tube edge beside "
            "it would not read back ({})",
            u.idx + 1, v.idx + 1, y.idx + 1, td::kBesideBoundary));
  }
  return {};
}

ConnectFacesResult connect_faces(HalfedgeMesh& mesh, Face f, Face g, int twist) {
  can_connect_faces(mesh, f, g, twist).throw_if_refused();
  const std::vector<Halfedge> lf = mesh.face_loop(f), lg = mesh.face_loop(g);
  const int k = static_cast<int>(lf.size());
  const int turn = (twist % k + k) % k;
  auto partner = [&](int i) { return lg[(turn - i + k) % k]; };

  ConnectFacesResult result;
  result.degree = k;
  // Both faces are removed, so a hole given is closed by the tube (bridging boundary loops);
  // the quads are surface, which insert_edge only builds between surface faces.
  mesh.set_hole(f, false);
  mesh.set_hole(g, false);
  // Checked above: none of these insertions can be refused, so the mesh is never left half-done.
  for (int i = 0; i < k; ++i) {
    const InsertEdgeResult r = insert_edge(mesh, lf[i], partner(i));
    if (i == 0) result.first_edge = r.edge.idx;
  }
  return result;
}

}  // namespace stitch
