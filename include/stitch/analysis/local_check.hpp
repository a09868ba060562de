// Folds and self-intersections near an edit: check_surface (surface_check.hpp) run on the
// patches an edit changed and the patches around them only, so its cost follows the size of the
// edit, not of the mesh. The modeler runs it after every topology edit and `stitch edit --check`
// after its operations.
//
// The patches are tessellated on their own (resolution n: (n + 1)^2 samples per patch) and
// welded by the mesh's topology, as the welded tessellation is (tessellate.hpp), so triangles of
// neighbouring patches share their vertices and the fold test sees across patch sides. Changed
// patches are in focus: a fold or a crossing counts when one of its two triangles lies on a
// changed patch. Their neighbours are the patches that share at least a point with one of them
// (the corners of its face, the corners around its vertex, and the two across its edges).
// Crossings with patches further away are not looked for: `stitch check-surface` checks a whole
// surface.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "stitch/analysis/surface_check.hpp"
#include "stitch/eval/surface.hpp"
#include "stitch/mesh/halfedge_mesh.hpp"

namespace stitch {

/// The local check's segments per patch side: 16, as the tests check whole surfaces; at 8 the
/// triangles beside a tightly bent tube (the hole through a cube) differ by more than 90 degrees
/// (README).
inline constexpr int local_check_resolution = 16;

struct LocalCheckOptions {
  int resolution = local_check_resolution;  ///< segments per patch side
  /// Fold angle and degenerate area (max_listed is ignored: every problem is mapped to its
  /// patches).
  SurfaceCheckOptions surface;
};

struct LocalCheckReport {
  int changed_patches = 0;  ///< patches in focus (the live ones among those given)
  int patches = 0;          ///< patches tessellated: the changed ones and their neighbours
  int triangles = 0;        ///< triangles tessellated, which bounds the work done
  int self_intersections = 0, folds = 0, degenerate = 0;  ///< as in SurfaceCheckReport
  /// The patches (corners) with a folded or crossing triangle, in index order; a pair of a
  /// changed patch with a neighbour names both.
  std::vector<Corner> problem_corners;
  /// Degenerate triangles are counted, not reported: check_surface tests them for neither folds
  /// nor crossings.
  [[nodiscard]] bool clean() const { return self_intersections == 0 && folds == 0; }
};

/// Position of corner c's patch at (u, v) = (i / n, j / n), n the check's resolution.
using PatchGridSampler = std::function<Vec3(Corner c, int i, int j)>;

/// The check on `changed` (corners; deleted ones and holes are skipped) with positions from
/// `sample`, which is called only for the changed patches and their neighbours.
LocalCheckReport check_patches(const HalfedgeMesh& mesh, const std::vector<Corner>& changed,
                               const PatchGridSampler& sample,
                               const LocalCheckOptions& options = {});
/// The same with positions evaluated on `surface` (built for `mesh`).
LocalCheckReport check_patches(const HalfedgeMesh& mesh, const Surface& surface,
                               const std::vector<Corner>& changed,
                               const LocalCheckOptions& options = {});

/// The changed patches and their neighbours, in index order (what check_patches tessellates).
std::vector<Corner> patch_neighbourhood(const HalfedgeMesh& mesh,
                                        const std::vector<Corner>& changed);

/// The corners whose patches can differ after edits that touched these elements (the lists of
/// a MeshDelta; elements deleted since are skipped): the patches reading a K-gon of a
/// face whose loop or vertices changed, as the modeler's LiveSurface updates them. A superset
/// of the patches that really changed, in index order, without holes.
std::vector<Corner> patches_touched(const HalfedgeMesh& mesh, const std::vector<Vertex>& vertices,
                                    const std::vector<Edge>& edges, const std::vector<Face>& faces);

/// The corners as `V@F`, 1-based (`V@F#k` when V appears more than once on F), numbered as the
/// mesh is written to a file (live vertices and surface faces in order, without gaps: a pass
/// over the mesh) when `as_written`, else as operation lines number them in a run.
std::vector<std::string> corner_names(const HalfedgeMesh& mesh, const std::vector<Corner>& corners,
                                      bool as_written = false);

}  // namespace stitch
