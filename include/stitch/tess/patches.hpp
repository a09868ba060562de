// The surface as plain bicubic Bézier patches, for CAD and other tools that know only
// polynomials: regular patches as they are, patches at extraordinary points as their hierarchy
// of modified de Casteljau children (docs/formats.md, "The patch set").
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "stitch/eval/surface.hpp"

namespace stitch {

/// One bicubic polynomial patch: a cell of the hierarchy under the patch of one mesh corner.
struct BezierPatch {
  /// The control points, P[a][b] = net.p[4 * a + b] (a is the u index); `extraordinary` is 0,
  /// since the patch is meant as the plain polynomial of its net.
  ControlNet net;
  Corner corner;   ///< the root patch: the mesh corner (half-edge) it lies in
  int face = 0;    ///< face of that corner (0-based index)
  int vertex = 0;  ///< vertex of that corner (0-based index)
  /// The k of the corner's name `V@F#k` (corner_name), 0 when the vertex appears on the face once.
  int occurrence = 0;
  int level = 0;   ///< modified de Casteljau splits from the root (0: the root itself)
  int cell_u = 0;  ///< the cell covers u in [cell_u, cell_u + 1] / 2^level of the root
  int cell_v = 0;  ///< and v in [cell_v, cell_v + 1] / 2^level
  /// True when the polynomial is the surface (regular root or regular child). False for the
  /// innermost cell at an extraordinary point, whose polynomial only approximates the surface.
  bool exact = true;
};

/// A point where the surface has no tangent plane (a cone point of creases or corners, a
/// valence-2 vertex, a fold): an extraordinary corner of root patches at which the innermost
/// cell's normal and the surface's differ by more than the angle tolerance at every depth. The
/// normal tolerance is not applied at the point itself (it still is around it, and the position
/// tolerance everywhere).
struct PointWithoutNormal {
  enum class Kind { vertex, face_centre, edge_middle } kind = Kind::vertex;
  int index = 0;         ///< the vertex, face or edge (0-based)
  double angle_deg = 0;  ///< the largest angle measured at the point
};

/// "vertex 5", "the centre of face 3", "the middle of edge (2, 7)" (numbered from 1).
std::string describe(const HalfedgeMesh& mesh, const PointWithoutNormal& point);

struct PatchSetOptions {
  /// Largest distance of an inexact cell from the surface, relative to the model size (the
  /// diagonal of the bounding box of the control points). > 0.
  double tolerance = 1e-6;
  /// Largest angle between the normals of two faces meeting along an edge, in degrees (> 0):
  /// an inexact cell's normal is within half of it of the surface's at the nearest point.
  double angle_tolerance_deg = 0.1;
  /// Depth at which a tolerance that cannot be reached is refused.
  int max_depth = 30;
};

struct PatchSet {
  Method method = Method::mdc;
  std::vector<BezierPatch> patches;  ///< root corner order, each root's cells by level
  int depth = 0;          ///< the most splits any extraordinary point needed (0: none needed)
  double model_size = 0;  ///< bounding box diagonal of the control points
  double tolerance = 0, angle_tolerance_deg = 0;  ///< as asked
  /// Largest deviation of an inexact cell from the surface, measured on a grid of samples in
  /// every innermost cell: the distance to the surface in model units (nearest_on_surface) and
  /// the angle to the surface's normal there in degrees.
  double max_position_deviation = 0, max_normal_deviation_deg = 0;
  /// Where the normal tolerance was not applied, one entry per point, sorted by kind and index.
  std::vector<PointWithoutNormal> points_without_normal;

  [[nodiscard]] int num_exact() const;
  /// The bound on an inexact cell's normal: half the angle tolerance, so that two faces meet
  /// within it along the edges they share.
  [[nodiscard]] double cell_angle_tolerance_deg() const { return angle_tolerance_deg / 2; }
};

/// The patches of the surface: for mdc, every extraordinary root split towards each of its
/// extraordinary corners to the smallest depth at which the innermost cell there is within the
/// tolerances (each point has its own depth); for asc, the roots as they are. Throws
/// UsageError for cc (not a set of Bézier patches), a tolerance <= 0 or not finite,
/// and stitch::Error naming the place when max_depth does not reach the tolerance.
/// `progress` (optional) is told the fraction (0..1) of the extraordinary points whose depth is
/// settled, from one thread at a time.
PatchSet bezier_patches(const HalfedgeMesh& mesh, const Surface& surface,
                        const PatchSetOptions& options = {},
                        const std::function<void(double)>& progress = {});

/// The volume the patches enclose, by the divergence theorem (a third of the integral of
/// p . (du x dv)), exact for their polynomials up to round-off; the volume of the solid they
/// bound when the surface is closed, positive when its normals point out.
double enclosed_volume(const PatchSet& patches);

/// The plain polynomial of one patch at (u, v) of its own cell, in the root's scale of
/// derivatives (du, dv multiplied by 2^level) so it can be compared with Surface::evaluate.
SurfacePoint evaluate_cell(const BezierPatch& patch, double u, double v);

/// (u, v) of the root patch for (s, t) of the cell.
std::array<double, 2> cell_to_root(const BezierPatch& patch, double s, double t);

/// The surface's point nearest to `point`, sought from (u, v) of corner c's patch
/// (nearest_point on Surface::evaluate): the distance to it is the distance a patch set's
/// tolerance bounds, up to the search's accuracy (it never underestimates).
SurfacePoint nearest_on_surface(const Surface& surface, Corner c, const Vec3& point, double u,
                                double v);

}  // namespace stitch
