// What reads what between control nets and K-gons; see src/kgon/dependencies.cpp.
#include "mesh/sort_unique.hpp"
#include "stitch/net/control_net.hpp"

namespace stitch {

std::vector<Corner> nets_reading(const HalfedgeMesh& mesh, const KgonElements& kgons) {
  std::vector<Corner> out;
  for (Face f : kgons.faces)
    for (Halfedge h : mesh.face_loop(f)) out.push_back(h);
  for (Vertex v : kgons.vertices)
    for (Halfedge h : mesh.vertex_fan(v)) out.push_back(h);
  for (Edge e : kgons.edges)
    for (int side = 0; side < 2; ++side) {
      const Halfedge h = HalfedgeMesh::halfedge(e, side);
      out.push_back(h);             // its edge
      out.push_back(mesh.next(h));  // its previous edge
    }
  std::erase_if(out, [&](Corner c) { return mesh.is_hole(c); });
  detail::sort_unique(out);
  return out;
}

}  // namespace stitch
