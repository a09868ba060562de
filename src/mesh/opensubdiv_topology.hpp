// A mesh handed to OpenSubdiv: its face-vertex description, and the feature tags (holes, creases,
// corners, boundary interpolation) as OpenSubdiv's Vtr reads them.
#pragma once

#include <opensubdiv/far/topologyRefiner.h>
#include <opensubdiv/sdc/options.h>

#include <memory>
#include <stdexcept>
#include <vector>

#include "stitch/mesh/halfedge_mesh.hpp"

namespace stitch {

/// The subdivision options of meshes without boundary (catmull_clark_refinement): Catmull-Clark's
/// own rules; the boundary rule never applies but must be named.
OpenSubdiv::Sdc::Options catmark_options();
/// Catmull-Clark's rules with the given boundary interpolation and creasing method (the mesh's).
OpenSubdiv::Sdc::Options catmark_options(BoundaryInterpolation boundary, CreaseMethod creasing);

/// The surface around a vertex as OpenSubdiv orders it: faces counter-clockwise, edge k leading
/// out of face k (the edge from the vertex to the next vertex of face k), so face k lies between
/// edges k and k+1. On the boundary, face 0 follows the hole and there is one edge more than
/// faces: the last one (a half-edge of the hole) trails the last face. Hole corners are not
/// faces here; edges between two holes are not edges of the surface.
struct SurfaceRing {
  std::vector<Halfedge> faces;  ///< corners of the vertex outside holes
  std::vector<Halfedge> edges;  ///< half-edges leaving the vertex
  [[nodiscard]] bool boundary() const { return edges.size() > faces.size(); }
};

/// Empty when every face around v is a hole. Throws stitch::Error when the surface's boundary
/// passes v more than once: OpenSubdiv would take v as non-manifold and sharpen it.
SurfaceRing surface_ring(const HalfedgeMesh& mesh, Vertex v);

/// The sharpness OpenSubdiv refines with (Vtr sharpens it so before the first level): boundary
/// edges infinitely sharp, tags clamped to [0, infinitely_sharp].
float osd_edge_sharpness(const HalfedgeMesh& mesh, Edge e);
/// A sharpness tag as OpenSubdiv reads it: not positive (NaN too) is smooth, at or above its
/// infinite value infinitely sharp.
float clamped_sharpness(double s);
/// The same for a vertex with the given surface ring: with edge-and-corner interpolation, a
/// boundary vertex with one face is infinitely sharp.
float osd_vertex_sharpness(const HalfedgeMesh& mesh, Vertex v, const SurfaceRing& ring,
                           BoundaryInterpolation boundary);

/// OpenSubdiv's Catmull-Clark topology of a mesh without deleted elements, with its features:
/// hole faces are left out (their edges become OpenSubdiv's boundary), crease and corner
/// sharpness are tagged. Vertex i is the mesh's; face f is the f-th face outside holes (the
/// numbering of to_polygon_soup), its vertices in loop order from halfedge(f). Throws stitch::Error
/// when the mesh has deleted elements or OpenSubdiv refuses the topology. A face-vertex
/// description cannot tell several edges between the same two vertices apart: check before
/// calling.
std::unique_ptr<OpenSubdiv::Far::TopologyRefiner> catmark_refiner(
    const HalfedgeMesh& mesh,
    BoundaryInterpolation boundary = BoundaryInterpolation::edge_and_corner);

// Sdc's MASK interface over plain arrays.
struct SdcMask {
  using Weight = double;
  std::vector<double> vertex, edge, face;
  int num_vertex = 0, num_edge = 0, num_face = 0;
  bool face_centres = false;

  explicit SdcMask(size_t size) : vertex(size), edge(size), face(size) {}
  [[nodiscard]] int GetNumVertexWeights() const { return num_vertex; }
  [[nodiscard]] int GetNumEdgeWeights() const { return num_edge; }
  [[nodiscard]] int GetNumFaceWeights() const { return num_face; }
  void SetNumVertexWeights(int n) { num_vertex = n; }
  void SetNumEdgeWeights(int n) { num_edge = n; }
  void SetNumFaceWeights(int n) { num_face = n; }
  [[nodiscard]] const double& VertexWeight(int i) const { return vertex[i]; }
  [[nodiscard]] const double& EdgeWeight(int i) const { return edge[i]; }
  [[nodiscard]] const double& FaceWeight(int i) const { return face[i]; }
  double& VertexWeight(int i) { return vertex[i]; }
  double& EdgeWeight(int i) { return edge[i]; }
  double& FaceWeight(int i) { return face[i]; }
  [[nodiscard]] bool AreFaceWeightsForFaceCenters() const { return face_centres; }
  void SetFaceWeightsForFaceCenters(bool on) { face_centres = on; }
};

// Face weights of Catmull-Clark's edge and vertex masks apply to the new face points; the other
// reading (weights on vertices opposite in the face) belongs to other schemes.
inline void require_face_centre_weights(const SdcMask& mask) {
  if (mask.num_face > 0 && !mask.face_centres)
    throw std::logic_error("catmull-clark: Sdc gave face weights not meant for face points");
}

}  // namespace stitch
