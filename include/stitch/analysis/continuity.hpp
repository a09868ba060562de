// Continuity measured, not claimed: normal jumps across every patch boundary and the tangent
// plane agreement at extraordinary points.
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

struct ContinuityReport {
  Method method = Method::mdc;
  /// Boundaries with an extraordinary point at one end, and all others. Samples never sit on
  /// the patch corners themselves.
  JumpStats touching_ev, away_from_ev;
  /// Largest distance between the two sides' positions, relative to the bounding-box diagonal.
  double max_gap = 0;
  /// At each extraordinary point (vertex of valence != 4, face of degree != 4): the largest
  /// angle between the normal of any patch meeting there (evaluated at the point) and the
  /// mean of those normals: 0 means one tangent plane (G1).
  double ev_normal_spread_deg = 0;
  int extraordinary_points = 0;
  /// Largest jump at each distance t from an extraordinary point (parametric, along the side),
  /// over all boundaries touching one; sorted by t.
  std::vector<std::pair<double, double>> jump_by_distance;
};

ContinuityReport analyze_continuity(const HalfedgeMesh& mesh, const Surface& surface,
                                    const ContinuityOptions& options = {});

/// Angle in degrees between two unit vectors, accurate for tiny angles (atan2 of |a x b|, a.b).
double angle_deg(const Vec3& a, const Vec3& b);

}  // namespace stitch
