// The Catmull-Clark step with the mesh's features (holes, creases, corners), as OpenSubdiv
// refines them: catmull_clark_refinement's connectivity with OpenSubdiv's crease and corner rules.
// A remeshing, so it lives with the others above the mesh stage (which holds only what OpenSubdiv
// reads of a mesh). Internal.
#pragma once

#include "stitch/mesh/halfedge_mesh.hpp"
#include "stitch/topology/remesh.hpp"

namespace stitch {

/// One Catmull-Clark step honouring the mesh's features as OpenSubdiv refines them: the
/// connectivity of catmull_clark_refinement, hole faces refined into hole quads, new vertices
/// on creases, corners and the boundary placed by Sdc's crease and corner rules (fractional
/// sharpness blended), and the tags of the refined mesh subdivided (semi-sharp values drop by
/// one). The limit surface outside holes is unchanged, as for the step without features.
/// Throws stitch::Error as surface_ring (mesh/opensubdiv_topology.hpp) does.
CatmullClarkRefinement catmark_refinement_with_features(const HalfedgeMesh& mesh,
                                                        BoundaryInterpolation boundary);

}  // namespace stitch
