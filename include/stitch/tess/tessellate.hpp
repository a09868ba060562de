// Sampling the surface on a regular grid per patch.
#pragma once

#include <functional>

#include "stitch/eval/surface.hpp"
#include "stitch/tess/tessellated_mesh.hpp"

namespace stitch {

/// Segments per patch side when nobody asks for another number: smooth silhouettes at screen
/// size, 64 samples per patch.
inline constexpr int kDefaultResolution = 8;

struct TessellationOptions {
  int resolution = kDefaultResolution;  ///< segments per patch side, >= 1
  bool welded = true;  ///< share samples on patch boundaries (watertight); else one grid per patch
  // The per-sample attributes, each filled only when asked (the arrays stay empty otherwise):
  // positions, normals and quads are what a mesh is drawn and written from; the attributes cost
  // 24 bytes per vertex more together, and fresh memory is what a first call mostly pays for.
  bool uv = false;     ///< TessellatedMesh::uv, the sample's (u, v) in its patch (16 bytes)
  bool patch = false;  ///< TessellatedMesh::patch, the corner of the patch it lies on (4 bytes)
  bool level = false;  ///< TessellatedMesh::level, its level in the hierarchy (4 bytes)
  /// false, tessellating into a kept TessellatedMesh (the overload below): leave its quads as
  /// they are. They depend on the mesh's connectivity, the resolution and `welded` alone, so a
  /// caller that moved only positions (an animation, K-gon controls) since it last tessellated
  /// into `out` keeps a valid index buffer and skips writing it (16 bytes per quad). Refused
  /// when `out` holds a different number of vertices or quads.
  bool index_buffer = true;
};

/// Welded: one watertight, consistently oriented mesh with the input's genus. A sample shared by
/// several patches on a face spoke or a smooth edge takes the first patch's normal under mdc and
/// cc (the patches meet with C1 there: their normals agree up to round-off); mesh vertices, face
/// centres, edge midpoints, samples on sharp edges and every shared sample under asc take the
/// normalized mean of the patches' normals. Unwelded: every patch's own (resolution+1)^2 grid.
TessellatedMesh tessellate(const HalfedgeMesh& mesh, const Surface& surface,
                           const TessellationOptions& options = {});

/// The same, into `out`, reusing its arrays' storage where it is large enough: tessellating
/// again (an animation, a modeler's vertex moves) then allocates and first-touches no memory.
/// On an exception, `out` holds no usable tessellation.
void tessellate(const HalfedgeMesh& mesh, const Surface& surface,
                const TessellationOptions& options, TessellatedMesh& out);

/// The unwelded tessellation (options.welded false) a block of `patches_per_block` whole patches
/// at a time, for a reader that needs each sample once and in order (a picture, a bound):
/// visit(block, first) gets patches [first, first + count) of surface.corners(), their samples
/// and attributes as tessellate gives them (to the bit), their quads numbered from the block's
/// first vertex. The block's storage is reused for the next one, so memory holds one block
/// whatever the mesh and resolution. Throws std::invalid_argument for welded options or fewer
/// than one patch a block, InputError as tessellate does.
void tessellate_blocks(const HalfedgeMesh& mesh, const Surface& surface,
                       const TessellationOptions& options, int patches_per_block,
                       const std::function<void(const TessellatedMesh& block, int first)>& visit);

}  // namespace stitch
