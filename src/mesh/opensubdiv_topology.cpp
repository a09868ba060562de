#include "mesh/opensubdiv_topology.hpp"

#include <opensubdiv/far/topologyDescriptor.h>

#include <vector>

namespace stitch {

OpenSubdiv::Sdc::Options catmark_options() {
  OpenSubdiv::Sdc::Options options;
  options.SetVtxBoundaryInterpolation(OpenSubdiv::Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);
  return options;
}

std::unique_ptr<OpenSubdiv::Far::TopologyRefiner> catmark_refiner(const HalfedgeMesh& mesh) {
  using namespace OpenSubdiv;
  if (mesh.has_garbage())
    throw MeshError("internal error: OpenSubdiv needs a mesh without deleted elements");
  std::vector<int> sizes, indices;
  for (Face f : mesh.faces()) {
    sizes.push_back(mesh.degree(f));
    for (Halfedge h : mesh.face_loop(f)) indices.push_back(mesh.origin(h).idx);
  }
  Far::TopologyDescriptor desc;
  desc.numVertices = mesh.num_vertices();
  desc.numFaces = mesh.num_faces();
  desc.numVertsPerFace = sizes.data();
  desc.vertIndicesPerFace = indices.data();
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  std::unique_ptr<Far::TopologyRefiner> refiner(
      Factory::Create(desc, Factory::Options(Sdc::SCHEME_CATMARK, catmark_options())));
  if (!refiner) throw MeshError("OpenSubdiv refused the mesh's topology");
  return refiner;
}

}  // namespace stitch
