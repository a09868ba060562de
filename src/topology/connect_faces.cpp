#include "stitch/topology/connect_faces.hpp"

#include <fmt/format.h>

#include "raw_mesh.hpp"
#include "stitch/topology/insert_edge.hpp"

namespace stitch {

namespace td = topology_detail;

ConnectFacesResult connect_faces(HalfedgeMesh& mesh, Face f, Face g, int twist) {
  td::check_face(mesh, f, "connect-faces");
  td::check_face(mesh, g, "connect-faces");
  if (f == g) throw MeshError(fmt::format("connect-faces: face {} given twice", f.idx + 1));
  const std::vector<Halfedge> lf = mesh.face_loop(f), lg = mesh.face_loop(g);
  const int k = static_cast<int>(lf.size());
  if (static_cast<int>(lg.size()) != k)
    throw MeshError(fmt::format(
        "connect-faces: face {} has {} sides but face {} has {}; they must match (subdivide-edge "
        "or insert-edge first)",
        f.idx + 1, k, g.idx + 1, lg.size()));
  // Reduced first: twist - i must not overflow for a twist near INT_MIN.
  const int turn = (twist % k + k) % k;
  auto partner_index = [&](int i) { return (turn - i + k) % k; };
  auto partner = [&](int i) { return lg[partner_index(i)]; };
  for (int i = 0; i < k; ++i)
    if (mesh.origin(lf[i]) == mesh.origin(partner(i)))
      throw MeshError(fmt::format(
          "connect-faces: corner {} of face {} and corner {} of face {} are both vertex {}; the "
          "edge joining them would be a loop",
          i + 1, f.idx + 1, partner_index(i) + 1, g.idx + 1, mesh.origin(lf[i]).idx + 1));

  ConnectFacesResult result;
  result.degree = k;
  // Checked above: none of these insertions can be refused, so the mesh is never left half-done.
  for (int i = 0; i < k; ++i) {
    const InsertEdgeResult r = insert_edge(mesh, lf[i], partner(i));
    if (i == 0) result.first_edge = r.edge.idx;
  }
  return result;
}

}  // namespace stitch
