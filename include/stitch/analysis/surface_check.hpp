// Checks of a triangulated surface: self-intersecting triangles, folds (adjacent triangles whose
// normals point opposite ways) and degenerate triangles; and segments against the surface
// (e.g. "the hole is really open": the axis of a handle meets no triangle).
#pragma once

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "stitch/eval/surface.hpp"
#include "stitch/mesh/build.hpp"
#include "stitch/tess/adaptive.hpp"
#include "stitch/tess/tessellated_mesh.hpp"

namespace stitch {

/// Triangles over shared vertices. source[t] says where triangle t came from (the quad or
/// polygon index), for messages.
struct TriangleSoup {
  std::vector<Vec3> positions;
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> source;
};

/// Each quad split along its shorter diagonal (quad_triangles in stitch/mesh/polygon.hpp: two
/// triangles with source = the quad's index).
TriangleSoup triangulate(const TessellatedMesh& surface);
/// Its triangles as they are (source = the triangle's index).
TriangleSoup triangulate(const AdaptiveMesh& surface);
/// Each polygon fanned from its first corner, a quad split as above; vertices at exactly equal
/// positions are merged first, so a file written without shared vertices still has its
/// adjacency.
TriangleSoup triangulate(const PolygonSoup& soup);

struct SurfaceCheckOptions {
  /// Adjacent triangles fold when the angle between their normals exceeds this (degrees).
  /// 90: "pointing opposite ways" (negative dot product), so that faces meeting at a right angle
  /// (the creases and corners of a box, which a file does not mark) are not a fold. Pairs that
  /// meet along a crease or at a cone point the check knows of are not tested
  /// (check_surface(mesh, surface, ...)).
  double fold_angle_deg = 90;
  /// A triangle is degenerate when twice its area is below this times the squared bounding-box
  /// diagonal (1e-14: well above round-off for coordinates of order 1, far below any real
  /// triangle of a resolution-16 tessellation).
  double degenerate_relative_area = 1e-14;
  /// At most this many of each kind are listed (all are counted).
  int max_listed = 20;
  /// Crossings are not looked for when a fold was found (self_intersections stays 0): for a
  /// caller that only needs to know whether the surface is clean (unfold_tubes' search), since
  /// the crossing test is most of the time of a check.
  bool crossings_only_when_unfolded = false;
  /// If set, told the fraction of the regions of space checked so far, from one thread at a
  /// time, never less than it was told before, 1 at the end (a progress bar's percentage).
  std::function<void(double)> progress;
};

struct SurfaceCheckReport {
  int triangles = 0;
  int self_intersections = 0;  ///< pairs of triangles that cross
  int folds = 0;               ///< pairs of edge-adjacent triangles that fold
  int degenerate = 0;          ///< triangles of (almost) zero area
  int inconsistent_edges = 0;  ///< edges both adjacent triangles run along in the same direction
  std::vector<std::array<int, 2>> intersecting_pairs, folded_pairs;  ///< triangle indices
  std::vector<int> degenerate_triangles;
  [[nodiscard]] bool clean() const {
    return self_intersections == 0 && folds == 0 && degenerate == 0 && inconsistent_edges == 0;
  }
  /// A few lines for people: the counts and the first listed problems (with their sources).
  [[nodiscard]] std::string describe(const TriangleSoup& soup) const;
  /// The same for a report of check_surface(mesh, surface, resolution), whose triangle t is half
  /// of quad t / 2 of the welded tessellation.
  [[nodiscard]] std::string describe_quads() const;
};

/// Runs all checks. Pairs of triangles sharing an edge are tested for folds only; pairs sharing
/// one vertex are tested by the opposite edge of each against the other (coplanar overlap of such
/// pairs is not detected); all other pairs near each other (a uniform grid of cells about a
/// triangle across) by Moller's triangle-triangle test, touching at a point not counting as
/// crossing. Near-linear in the triangles, on every core; besides the soup it holds about 10
/// bytes per triangle and a tile of the grid per thread. The pairs listed are the first by
/// triangle number.
SurfaceCheckReport check_surface(const TriangleSoup& soup, const SurfaceCheckOptions& options = {});
/// The same checks of the welded tessellation at `resolution` (what stitch smooth writes, its
/// quads split as triangulate splits them; triangle 2q + s is half s of quad q), without holding
/// it: the patches are evaluated a region of space at a time, so memory grows with the mesh, not
/// with the resolution. Crease-aware: two triangles that meet along an infinitely sharp edge of
/// the surface (KgonSet::sharp) or at a cone point (a corner: three or more sharp edges or a
/// corner tag, or a sector the K-gons could not flatten, KgonSet::cone) are no fold, whatever
/// their angle. Throws InputError when the surface is not finite.
SurfaceCheckReport check_surface(const HalfedgeMesh& mesh, const Surface& surface, int resolution,
                                 const SurfaceCheckOptions& options = {});
/// The same for Bézier patches kept apart from a Surface (an IncrementalSurface's K-gons and nets,
/// nets indexed by corner) under `method`, mdc or asc; the patches are mesh.patch_corners()'s.
SurfaceCheckReport check_surface(const HalfedgeMesh& mesh, Method method, const KgonSet& kgons,
                                 const std::vector<ControlNet>& nets, int resolution,
                                 const SurfaceCheckOptions& options = {});
/// The same checks for the part of a surface near an edit (local_check.hpp): only triangles
/// with focus[t] != 0 count as degenerate, and only pairs with at least one such triangle count
/// as folded, crossing or inconsistent. The others are there to be met. Throws
/// std::invalid_argument unless there is one flag per triangle.
SurfaceCheckReport check_surface(const TriangleSoup& soup, const std::vector<char>& focus,
                                 const SurfaceCheckOptions& options = {});

/// Moller's interval test (1997) with a coplanar fallback: do the closed triangles intersect?
/// `eps` is the distance below which a vertex counts as on the other's plane.
bool triangles_intersect(const Vec3& a0, const Vec3& a1, const Vec3& a2, const Vec3& b0,
                         const Vec3& b1, const Vec3& b2, double eps = 0);

struct SegmentHit {
  int triangle = -1;
  double t = 0;  ///< position along the segment, 0 at p, 1 at q
};

/// Where segment p-q crosses triangles of the soup (Moller-Trumbore, a hit on an edge counts),
/// sorted by t.
std::vector<SegmentHit> segment_hits(const TriangleSoup& soup, const Vec3& p, const Vec3& q);

}  // namespace stitch
