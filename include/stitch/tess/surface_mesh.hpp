// Kept for code written against stitch 0.1, which called the tessellation's output SurfaceMesh;
// pmp-library and geometry-central use that name for the input mesh, so stitch now says
// TessellatedMesh. New code includes stitch/tess/tessellated_mesh.hpp.
#pragma once

#include "stitch/tess/tessellated_mesh.hpp"

namespace stitch {

using SurfaceMesh [[deprecated("use stitch::TessellatedMesh")]] = TessellatedMesh;

}  // namespace stitch
