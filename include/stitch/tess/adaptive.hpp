// Adaptive tessellation: each patch side gets its own number of segments from a flatness bound,
// chosen once for the two patches that share it, so the triangle mesh stays watertight without
// welding (as OpenSubdiv's adaptive tessellation picks rates per edge).
#pragma once

#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "stitch/eval/surface.hpp"
#include "stitch/tess/export.hpp"

namespace stitch {

struct AdaptiveOptions {
  /// Largest allowed distance of the triangles from the patches' control nets' flattening bound,
  /// relative to the diagonal of the input mesh's bounding box. 1e-3 keeps silhouettes smooth at
  /// screen size while a cube needs a few segments per patch side.
  double tolerance = 1e-3;
  int max_rate = 64;  ///< upper clamp of segments per side
};

/// A welded triangle mesh of surface samples.
struct AdaptiveMesh {
  std::vector<Vec3> positions;
  std::vector<Vec3> normals;        ///< unit; the mean direction of the sharing patches' normals
  std::vector<Eigen::Vector2d> uv;  ///< the (u, v) in `patch` of the sample giving the position
  std::vector<int> patch;           ///< that sample's corner half-edge
  std::vector<std::array<int, 3>> triangles;  ///< counter-clockwise seen from the normal side
  int min_rate = 0, max_rate = 0;             ///< segments per side, over all sides

  [[nodiscard]] int num_vertices() const { return static_cast<int>(positions.size()); }
};

/// Side rate n = ceil(sqrt((3/4) max|second difference| / (tolerance * diagonal))), the cubic
/// Bézier flattening bound, over the rows of both patches that run along the side and the next
/// row inwards, clamped to [1, max_rate]. Each patch's inside is a uniform grid at its largest
/// side rate, zipped to coarser sides by triangle strips: no T-junctions. For the cc method the
/// rates come from the Bézier nets, which only approximate its surface.
AdaptiveMesh tessellate_adaptive(const HalfedgeMesh& mesh, const Surface& surface,
                                 const AdaptiveOptions& options = {});

/// Writes the triangles in `format` (whatever the path's extension): OBJ (with vn), PLY (binary
/// doubles with normals unless options.ascii_ply / single_precision), OFF or STL; glTF is
/// refused. Atomic.
void write_adaptive_mesh(const std::string& path, MeshFileFormat format, const AdaptiveMesh& mesh,
                         const SurfaceFileOptions& options = {});

}  // namespace stitch
