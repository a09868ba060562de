// A mesh handed to OpenSubdiv as its face-vertex description.
#pragma once

#include <opensubdiv/far/topologyRefiner.h>
#include <opensubdiv/sdc/options.h>

#include <memory>

#include "stitch/mesh/halfedge_mesh.hpp"

namespace stitch {

/// The subdivision options every use of OpenSubdiv here shares: Catmull-Clark's own rules
/// (closed meshes, so the boundary rule never applies but must be named).
OpenSubdiv::Sdc::Options catmark_options();

/// OpenSubdiv's Catmull-Clark topology of a mesh without deleted elements: vertex i and face f
/// are the mesh's, each face's vertices in loop order from halfedge(f). Throws MeshError when
/// the mesh has deleted elements or OpenSubdiv refuses the topology. A face-vertex description
/// cannot tell several edges between the same two vertices apart: check before calling.
std::unique_ptr<OpenSubdiv::Far::TopologyRefiner> catmark_refiner(const HalfedgeMesh& mesh);

}  // namespace stitch
