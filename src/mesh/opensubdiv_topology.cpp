#include "mesh/opensubdiv_topology.hpp"

#include <fmt/format.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/sdc/crease.h>

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace stitch {

namespace Sdc = OpenSubdiv::Sdc;

Sdc::Options catmark_options() {
  Sdc::Options options;
  options.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);
  return options;
}

Sdc::Options catmark_options(BoundaryInterpolation boundary, CreaseMethod creasing) {
  Sdc::Options options;
  options.SetCreasingMethod(creasing == CreaseMethod::chaikin ? Sdc::Options::CREASE_CHAIKIN
                                                              : Sdc::Options::CREASE_UNIFORM);
  options.SetVtxBoundaryInterpolation(boundary == BoundaryInterpolation::edge_only
                                          ? Sdc::Options::VTX_BOUNDARY_EDGE_ONLY
                                          : Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
  return options;
}

SurfaceRing surface_ring(const HalfedgeMesh& mesh, Vertex v) {
  const std::vector<Halfedge> fan = mesh.vertex_fan(v);
  const size_t n = fan.size();
  SurfaceRing ring;
  // fan[k - 1] is the face across edge(fan[k]) from fan[k]: a run of surface corners that
  // starts after a hole starts at a boundary edge.
  size_t runs = 0, start = 0;
  bool any_hole = false;
  for (size_t k = 0; k < n; ++k) {
    const bool hole = mesh.is_hole(fan[k]);
    any_hole = any_hole || hole;
    if (!hole && mesh.is_hole(fan[(k + n - 1) % n])) {
      ++runs;
      start = k;
    }
  }
  if (!any_hole) {
    ring.faces = fan;
    ring.edges = fan;
    return ring;
  }
  if (runs == 0) return ring;
  if (runs > 1) {
    throw InputError(fmt::format(
        "vertex {} lies on the surface's boundary {} times (boundary loops meet there); "
        "OpenSubdiv would take it as non-manifold",
        v.idx + 1, runs));
  }
  for (size_t k = start; !mesh.is_hole(fan[k % n]); ++k) ring.faces.push_back(fan[k % n]);
  ring.edges = ring.faces;
  ring.edges.push_back(mesh.rotate_ccw(ring.faces.back()));
  return ring;
}

float clamped_sharpness(double s) {
  // OpenSubdiv reads anything at or above its infinite value as infinite and anything not
  // positive (NaN included, by this comparison) as smooth.
  if (!(s > 0.0)) return Sdc::Crease::SHARPNESS_SMOOTH;
  return static_cast<float>(std::min(s, static_cast<double>(Sdc::Crease::SHARPNESS_INFINITE)));
}

float osd_edge_sharpness(const HalfedgeMesh& mesh, Edge e) {
  return mesh.is_boundary(e) ? Sdc::Crease::SHARPNESS_INFINITE
                             : clamped_sharpness(mesh.sharpness(e));
}

float osd_vertex_sharpness(const HalfedgeMesh& mesh, Vertex v, const SurfaceRing& ring,
                           BoundaryInterpolation boundary) {
  // Vtr's "topological corner": one face and two edges (TopologyRefinerFactoryBase::
  // prepareComponentTagsAndSharpness).
  if (boundary == BoundaryInterpolation::edge_and_corner && ring.faces.size() == 1 &&
      ring.edges.size() == 2)
    return Sdc::Crease::SHARPNESS_INFINITE;
  return clamped_sharpness(mesh.sharpness(v));
}

std::unique_ptr<OpenSubdiv::Far::TopologyRefiner> catmark_refiner(const HalfedgeMesh& mesh,
                                                                  BoundaryInterpolation boundary) {
  using namespace OpenSubdiv;
  if (mesh.has_garbage())
    throw Error("internal error: OpenSubdiv needs a mesh without deleted elements");
  std::vector<int> sizes, indices;
  for (Face f : mesh.surface_faces()) {
    sizes.push_back(mesh.degree(f));
    for (Halfedge h : mesh.face_loop(f)) indices.push_back(mesh.origin(h).idx);
  }
  // Boundary edges are infinitely sharp whatever their tag, and edges between two holes are not
  // part of OpenSubdiv's mesh: only the other tags are given.
  std::vector<int> crease_ends;
  std::vector<float> crease_sharpness, corner_sharpness;
  std::vector<int> corners;
  for (Edge e : mesh.edges()) {
    if (mesh.is_boundary(e) || mesh.sharpness(e) <= 0.0) continue;
    const Halfedge h = HalfedgeMesh::halfedge(e, 0);
    crease_ends.push_back(mesh.origin(h).idx);
    crease_ends.push_back(mesh.target(h).idx);
    crease_sharpness.push_back(clamped_sharpness(mesh.sharpness(e)));
  }
  for (Vertex v : mesh.vertices()) {
    if (mesh.sharpness(v) <= 0.0) continue;
    corners.push_back(v.idx);
    corner_sharpness.push_back(clamped_sharpness(mesh.sharpness(v)));
  }
  Far::TopologyDescriptor desc;
  desc.numVertices = mesh.num_vertices();
  desc.numFaces = static_cast<int>(sizes.size());
  desc.numVertsPerFace = sizes.data();
  desc.vertIndicesPerFace = indices.data();
  desc.numCreases = static_cast<int>(crease_sharpness.size());
  desc.creaseVertexIndexPairs = crease_ends.data();
  desc.creaseWeights = crease_sharpness.data();
  desc.numCorners = static_cast<int>(corners.size());
  desc.cornerVertexIndices = corners.data();
  desc.cornerWeights = corner_sharpness.data();
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  std::unique_ptr<Far::TopologyRefiner> refiner(Factory::Create(
      desc,
      Factory::Options(Sdc::SCHEME_CATMARK, catmark_options(boundary, mesh.crease_method()))));
  if (!refiner) throw InputError("OpenSubdiv refused the mesh's topology");
  return refiner;
}

}  // namespace stitch
