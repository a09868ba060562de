#include "stitch/net/control_net.hpp"

#include <tbb/parallel_for.h>

#include "support/fresh_storage.hpp"

namespace stitch {

ControlNet build_control_net(const HalfedgeMesh& m, const KgonSet& kg, Corner c) {
  const Corner n0 = m.rotate_cw(c);   // across side 0 (the half of edge(c) at the vertex)
  const Corner n1 = m.next(c);        // across side 1 (inside the face)
  const Corner n2 = m.prev(c);        // across side 2 (inside the face)
  const Corner n3 = m.rotate_ccw(c);  // across side 3 (the half of edge(prev(c)) at the vertex)
  const Kgon& vk = kg.vertex[m.origin(c).idx];
  const Kgon& fk = kg.face[m.face(c).idx];
  const Kgon& ek_next = kg.edge[HalfedgeMesh::edge(c).idx];
  const Kgon& ek_prev = kg.edge[HalfedgeMesh::edge(m.prev(c)).idx];

  ControlNet net;
  // Patch corners: the centroids of the four K-gons around the corner point.
  net.at(0, 0) = vk.centroid;
  net.at(3, 0) = ek_next.centroid;
  net.at(3, 3) = fk.centroid;
  net.at(0, 3) = ek_prev.centroid;
  // Inner points: this corner's point in each of those K-gons.
  net.at(1, 1) = kg.vertex_point(m, c);
  net.at(2, 1) = kg.next_edge_point(c);
  net.at(2, 2) = kg.face_point(m, c);
  net.at(1, 2) = kg.prev_edge_point(m, c);
  // Boundary points: midpoints of the two K-gon points on either side of the boundary, so the
  // neighbour computes the same curve and every boundary point is the midpoint of the two inner
  // points beside it (C1 across the boundary).
  net.at(1, 0) = 0.5 * (net.at(1, 1) + kg.vertex_point(m, n0));
  net.at(2, 0) = 0.5 * (net.at(2, 1) + kg.prev_edge_point(m, n0));
  net.at(3, 1) = 0.5 * (net.at(2, 1) + kg.prev_edge_point(m, n1));
  net.at(3, 2) = 0.5 * (net.at(2, 2) + kg.face_point(m, n1));
  net.at(1, 3) = 0.5 * (net.at(1, 2) + kg.next_edge_point(n2));
  net.at(2, 3) = 0.5 * (net.at(2, 2) + kg.face_point(m, n2));
  net.at(0, 1) = 0.5 * (net.at(1, 1) + kg.vertex_point(m, n3));
  net.at(0, 2) = 0.5 * (net.at(1, 2) + kg.next_edge_point(n3));
  // Along a sharp edge the side is the sharp curve, which only the vertices along the edge
  // shape; the patch across (if any) has the same curve, so the surface stays watertight there.
  if (kg.sharp(HalfedgeMesh::edge(c))) {
    const auto& curve = kg.sharp_curve[c.idx];
    net.at(1, 0) = curve[0];
    net.at(2, 0) = curve[1];
  }
  if (kg.sharp(HalfedgeMesh::edge(n2))) {
    const auto& curve = kg.sharp_curve[n3.idx];  // the half-edge leaving the vertex along it
    net.at(0, 1) = curve[0];
    net.at(0, 2) = curve[1];
  }

  net.corner_k = {kg.vertex_k[c.idx], ek_next.size(), fk.size(), ek_prev.size()};
  const std::uint8_t bits[4] = {corner00, corner30, corner33, corner03};
  for (int i = 0; i < 4; ++i)
    if (net.corner_k[i] != 4) net.extraordinary |= bits[i];
  return net;
}

ControlNet unused_net() {
  ControlNet net;
  net.p.fill(Vec3::Zero());
  return net;
}

std::vector<ControlNet> build_control_nets(const HalfedgeMesh& m, const KgonSet& kgons) {
  std::vector<ControlNet> nets;
  build_control_nets(m, kgons, nets);
  return nets;
}

void build_control_nets(const HalfedgeMesh& m, const KgonSet& kgons,
                        std::vector<ControlNet>& nets) {
  detail::size_for_overwrite(nets, static_cast<size_t>(m.halfedge_capacity()));
  const std::vector<Corner> corners = m.patch_corners();
  // Each step also empties the indices before its corner that make no patch (deleted half-edges,
  // holes' corners): storage reused from another mesh still holds that mesh's nets there.
  const ControlNet unused = unused_net();
  tbb::parallel_for(size_t{0}, corners.size() + 1, [&](size_t i) {
    const size_t from = i == 0 ? 0 : static_cast<size_t>(corners[i - 1].idx) + 1;
    const size_t to = i == corners.size() ? nets.size() : static_cast<size_t>(corners[i].idx);
    for (size_t k = from; k < to; ++k) nets[k] = unused;
    if (i < corners.size()) nets[corners[i].idx] = build_control_net(m, kgons, corners[i]);
  });
}

PatchNeighbour neighbour_across(const HalfedgeMesh& m, Corner c, int side) {
  switch (side) {
    case 0:
      return {m.rotate_cw(c), 3};
    case 1:
      return {m.next(c), 2};
    case 2:
      return {m.prev(c), 1};
    default:
      return {m.rotate_ccw(c), 0};
  }
}

std::array<double, 2> side_point(int side, double t) {
  switch (side) {
    case 0:
      return {t, 0.0};
    case 1:
      return {1.0, t};
    case 2:
      return {t, 1.0};
    default:
      return {0.0, t};
  }
}

}  // namespace stitch
