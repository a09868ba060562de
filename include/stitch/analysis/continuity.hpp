// Continuity measured, not claimed: normal jumps across every patch boundary and the tangent
// plane agreement at extraordinary points. Along boundaries and creases the surface is only C0
// by design, so those sides are measured apart: watertightness of creases, and tangent-plane
// agreement within each sector at the vertices on them.
#pragma once

#include <vector>

#include "stitch/eval/surface.hpp"

namespace stitch {

struct JumpStats {
  double max_deg = 0;   ///< largest angle between the two patches' normals at one sample
  double mean_deg = 0;  ///< mean over all samples
  long samples = 0;
};

struct ContinuityOptions {
  /// Evenly spaced samples per side at t = (k + 1/2) / n; more samples are added at
  /// t = 2^-k and 1 - 2^-k (k = 2..max_halvings) to probe the neighbourhood of the patch corners.
  int samples_per_side = 8;
  int max_halvings = 12;
};

/// What the sharp features do to the surface: boundaries, and creases, i.e. the edges that are
/// sharp for the surface's method (sharp_edges in sectors.hpp).
struct FeatureReport {
  /// Patch sides along the boundary: two per boundary edge (one per half).
  int boundary_sides = 0;
  /// Patch sides along creases, each counted once though two patches share it: two per edge.
  int crease_sides = 0;
  /// Largest distance between the two patches' positions on a crease, relative to the
  /// bounding-box diagonal (watertight: round-off). Their normals differ by design.
  double crease_gap = 0;
  /// Vertices with a sharp spoke or an infinitely sharp corner tag (boundary, crease, corner and
  /// dart vertices), whose sectors (vertex_sectors) are checked here instead of in
  /// ContinuityReport::ev_normal_spread_deg. A dart's one sector is its whole fan.
  int sector_vertices = 0;
  /// Sectors of two or more patches: the ones where there is something to compare.
  int sectors_compared = 0;
  /// Sectors left out of the comparison because the surface has a cone point there by design
  /// (method.md: sectors that cannot be flattened; for cc, OpenSubdiv's corners).
  int cone_points = 0;
  /// In each such sector: the largest angle between the normal of one of its patches at the
  /// vertex and the mean of those normals (0: one tangent plane per sector, G1).
  double sector_normal_spread_deg = 0;
};

struct ContinuityReport {
  Method method = Method::mdc;
  /// Boundaries with an extraordinary point at one end, and all others. Samples never sit on
  /// the patch corners themselves. Sides on boundaries and creases are not among them.
  JumpStats touching_ev, away_from_ev;
  /// Largest distance between the two sides' positions, relative to the bounding-box diagonal.
  double max_gap = 0;
  /// At each extraordinary point (vertex of valence != 4, face of degree != 4): the largest
  /// angle between the normal of any patch meeting there (evaluated at the point) and the
  /// mean of those normals: 0 means one tangent plane (G1). Vertices on sharp features are
  /// checked per sector instead (FeatureReport).
  double ev_normal_spread_deg = 0;
  int extraordinary_points = 0;
  /// Largest jump at each distance t from an extraordinary point (parametric, along the side),
  /// over all boundaries touching one; sorted by t.
  std::vector<std::pair<double, double>> jump_by_distance;
  /// Whether the surface has a boundary, a crease or an infinitely sharp corner tag; `features`
  /// is all zero otherwise.
  bool has_sharp_features = false;
  FeatureReport features;
};

ContinuityReport analyze_continuity(const HalfedgeMesh& mesh, const Surface& surface,
                                    const ContinuityOptions& options = {});

/// Angle in degrees between two unit vectors, accurate for tiny angles (atan2 of |a x b|, a.b).
double angle_deg(const Vec3& a, const Vec3& b);

}  // namespace stitch
