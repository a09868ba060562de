#include "topology/catmark_refinement.hpp"

#include <opensubdiv/sdc/catmarkScheme.h>
#include <opensubdiv/sdc/crease.h>

#include <algorithm>
#include <vector>

#include "mesh/opensubdiv_topology.hpp"

namespace stitch {

namespace Sdc = OpenSubdiv::Sdc;

namespace {

// The neighbourhoods OpenSubdiv's Sdc::Scheme asks about to compute its refinement masks (the
// interfaces of Vtr's componentInterfaces.h), with the sharpness Vtr would hold.
struct EdgeNeighbourhood {
  int num_faces = 2;
  int degrees[2] = {0, 0};  // of the surface faces on either side
  float sharpness = 0.0F;
  float child_sharpness[2] = {0.0F, 0.0F};  // of its halves at origin(h0) and origin(h1)
  [[nodiscard]] int GetNumFaces() const { return num_faces; }
  [[nodiscard]] float GetSharpness() const { return sharpness; }
  void GetChildSharpnesses(const Sdc::Crease& /*crease*/, float s[2]) const {
    s[0] = child_sharpness[0];
    s[1] = child_sharpness[1];
  }
  void GetNumVerticesPerFace(int out[]) const {
    for (int i = 0; i < num_faces; ++i) out[i] = degrees[i];
  }
};

struct VertexNeighbourhood {
  int num_edges = 0, num_faces = 0;
  float sharpness = 0.0F, child_sharpness = 0.0F;
  const float* edge_sharpness = nullptr;        // per ring edge
  const float* child_edge_sharpness = nullptr;  // per ring edge, of its half at this vertex
  [[nodiscard]] int GetNumEdges() const { return num_edges; }
  [[nodiscard]] int GetNumFaces() const { return num_faces; }
  [[nodiscard]] float GetSharpness() const { return sharpness; }
  [[nodiscard]] float GetChildSharpness(const Sdc::Crease& /*crease*/) const {
    return child_sharpness;
  }
  float* GetSharpnessPerEdge(float out[]) const {
    std::copy(edge_sharpness, edge_sharpness + num_edges, out);
    return out;
  }
  float* GetChildSharpnessPerEdge(const Sdc::Crease& /*crease*/, float out[]) const {
    std::copy(child_edge_sharpness, child_edge_sharpness + num_edges, out);
    return out;
  }
};

}  // namespace

// catmull_clark_refinement gives the connectivity and, for every face, its face point (no tag
// changes a face point); edge and vertex points are placed again here with the masks Sdc gives
// for their sharpness, exactly as Far's refiner would (it is compared with Far's level 1 in the
// tests). Holes take no part: their faces are not in any neighbourhood, and their refined quads
// stay holes, so the points inside them are left where the smooth step put them.
CatmullClarkRefinement catmark_refinement_with_features(const HalfedgeMesh& mesh,
                                                        BoundaryInterpolation boundary) {
  CatmullClarkRefinement step = catmull_clark_refinement(mesh);
  HalfedgeMesh& fine = step.mesh;
  fine.set_crease_method(mesh.crease_method());
  const Sdc::Options options = catmark_options(boundary, mesh.crease_method());
  const Sdc::Scheme<Sdc::SCHEME_CATMARK> scheme(options);
  const Sdc::Crease crease(options);

  // The quad of corner c runs from the vertex point of origin(c) to the edge point of edge(c),
  // the face point, and the edge point of edge(prev(c)); it exists for hole corners too.
  auto quad_start = [&](Halfedge c) { return fine.halfedge(step.corner_quad[c.idx]); };
  auto vertex_point = [&](Halfedge c) { return fine.origin(quad_start(c)); };
  auto edge_point = [&](Halfedge c) { return fine.origin(fine.next(quad_start(c))); };
  auto face_point = [&](Halfedge c) {
    return fine.position(fine.origin(fine.next(fine.next(quad_start(c)))));
  };
  // The half of edge(c) at origin(c).
  auto child_edge = [&](Halfedge c) { return HalfedgeMesh::edge(quad_start(c)); };

  for (Halfedge c : mesh.halfedges())
    if (mesh.is_hole(c)) fine.set_hole(step.corner_quad[c.idx], true);

  std::vector<SurfaceRing> rings(static_cast<size_t>(mesh.vertex_capacity()));
  size_t max_size = 2;
  for (Vertex v : mesh.vertices()) {
    rings[v.idx] = surface_ring(mesh, v);
    max_size = std::max(max_size, rings[v.idx].edges.size());
  }
  for (Face f : mesh.faces()) max_size = std::max(max_size, static_cast<size_t>(mesh.degree(f)));
  SdcMask mask(max_size);

  // Vertex points, and the sharpness of every half edge at its vertex (needed by the edge points
  // of both ends before they are placed).
  std::vector<float> child_sharpness(static_cast<size_t>(mesh.halfedge_capacity()), 0.0F);
  std::vector<float> sharp, child_sharp;
  for (Vertex v : mesh.vertices()) {
    const SurfaceRing& ring = rings[v.idx];
    if (ring.faces.empty()) continue;
    const int n = static_cast<int>(ring.edges.size());
    sharp.resize(ring.edges.size());
    child_sharp.resize(ring.edges.size());
    for (int k = 0; k < n; ++k)
      sharp[k] = osd_edge_sharpness(mesh, HalfedgeMesh::edge(ring.edges[k]));
    for (int k = 0; k < n; ++k) {
      child_sharp[k] = crease.SubdivideEdgeSharpnessAtVertex(sharp[k], n, sharp.data());
      child_sharpness[ring.edges[k].idx] = child_sharp[k];
    }
    VertexNeighbourhood hood;
    hood.num_edges = n;
    hood.num_faces = static_cast<int>(ring.faces.size());
    hood.sharpness = osd_vertex_sharpness(mesh, v, ring, boundary);
    hood.child_sharpness = crease.SubdivideVertexSharpness(hood.sharpness);
    hood.edge_sharpness = sharp.data();
    hood.child_edge_sharpness = child_sharp.data();
    scheme.ComputeVertexVertexMask(hood, mask);
    require_face_centre_weights(mask);
    // Smaller weights first, as OpenSubdiv's PrimvarRefiner adds them, for the same round-off.
    Vec3 p = Vec3::Zero();
    for (int i = 0; i < mask.num_face; ++i) p += mask.face[i] * face_point(ring.faces[i]);
    for (int i = 0; i < mask.num_edge; ++i)
      p += mask.edge[i] * mesh.position(mesh.target(ring.edges[i]));
    const Vertex child = vertex_point(ring.edges[0]);
    fine.position(child) = p + mask.vertex[0] * mesh.position(v);
    // The boundary and its corners are found again in the refined mesh; only the tags go down.
    fine.set_sharpness(child,
                       crease.SubdivideVertexSharpness(clamped_sharpness(mesh.sharpness(v))));
  }

  for (Edge e : mesh.edges()) {
    const Halfedge h[2] = {HalfedgeMesh::halfedge(e, 0), HalfedgeMesh::halfedge(e, 1)};
    EdgeNeighbourhood hood;
    Halfedge sides[2];
    hood.num_faces = 0;
    for (Halfedge s : h)
      if (!mesh.is_hole(s)) {
        sides[hood.num_faces] = s;
        hood.degrees[hood.num_faces++] = mesh.degree(mesh.face(s));
      }
    if (hood.num_faces == 0) continue;
    hood.sharpness = osd_edge_sharpness(mesh, e);
    hood.child_sharpness[0] = child_sharpness[h[0].idx];
    hood.child_sharpness[1] = child_sharpness[h[1].idx];
    scheme.ComputeEdgeVertexMask(hood, mask);
    require_face_centre_weights(mask);
    Vec3 p = mask.vertex[0] * mesh.position(mesh.origin(h[0])) +
             mask.vertex[1] * mesh.position(mesh.origin(h[1]));
    for (int i = 0; i < mask.num_face; ++i) p += mask.face[i] * face_point(sides[i]);
    fine.position(edge_point(h[0])) = p;
    const float tag = clamped_sharpness(mesh.sharpness(e));
    for (Halfedge s : h) {
      // A boundary stays a boundary by the hole quads beside it; a crease keeps its
      // subdivided sharpness (Vtr's value for the half at each end).
      fine.set_sharpness(child_edge(s), mesh.is_boundary(e) ? crease.SubdivideUniformSharpness(tag)
                                                            : child_sharpness[s.idx]);
    }
  }
  return step;
}

}  // namespace stitch
